package org.stagecraft.tools.ui.launch;

import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugException;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.IDebugEventSetListener;
import org.eclipse.debug.core.model.IProcess;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.ui.view.ToolsModel;

/**
 * The robot program as a part of its Robot Session in the Tools view: a row named after the program
 * that follows its process (PyDev's, or the plain interpreter's), with its PID while it runs, and when
 * it ends how: exited (0), stopped with the session, or failed with its exit value.
 */
final class ProgramPart implements IDebugEventSetListener {
    private final SessionParts session;
    private final String name;
    private final IProcess process;
    private boolean ended;

    private ProgramPart(SessionParts session, String name, IProcess process) {
        this.session = session;
        this.name = name;
        this.process = process;
    }

    /** Shows the program's row and keeps it up to date until the process ends. */
    static void follow(SessionParts session, String name, IProcess process) {
        ProgramPart part = new ProgramPart(session, name, process);
        ToolsModel.get().update(new ToolsModel.Row(session.sessionName(), name, ToolState.READY, pid(process), 0, null,
                "the robot program"));
        DebugPlugin.getDefault().addDebugEventListener(part);
        if (process.isTerminated()) { // it may have ended before the listener was there
            part.ended();
        }
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void handleDebugEvents(DebugEvent[] events) {
        for (DebugEvent e : events) {
            if (e.getSource() == process && e.getKind() == DebugEvent.TERMINATE) {
                ended();
            }
        }
    }

    private void ended() {
        synchronized (this) {
            if (ended) {
                return;
            }
            ended = true;
        }
        DebugPlugin.getDefault().removeDebugEventListener(this);
        @Nullable Integer exit;
        try {
            exit = process.getExitValue();
        } catch (DebugException e) {
            exit = null;
        }
        ToolState state;
        String detail;
        if (exit != null && exit == 0) {
            state = ToolState.EXITED;
            detail = "ended (exit value 0)";
        } else if (session.isStopping()) {
            state = ToolState.STOPPED;
            detail = "stopped with the session";
        } else {
            state = ToolState.FAILED;
            detail = "ended with exit value " + exit;
        }
        ToolsModel.get().update(new ToolsModel.Row(session.sessionName(), name, state, -1, 0, exit, detail));
    }

    /** The process's id as the debug platform records it, or -1. */
    private static long pid(IProcess process) {
        String id = process.getAttribute(IProcess.ATTR_PROCESS_ID);
        try {
            return id == null ? -1 : Long.parseLong(id);
        } catch (NumberFormatException e) {
            return -1;
        }
    }
}
