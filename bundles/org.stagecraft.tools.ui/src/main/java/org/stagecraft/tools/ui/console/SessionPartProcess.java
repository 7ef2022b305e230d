package org.stagecraft.tools.ui.console;

import java.io.IOException;
import java.util.HashMap;
import java.util.Map;

import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.model.IProcess;
import org.eclipse.debug.core.model.IStreamMonitor;
import org.eclipse.debug.core.model.IStreamsProxy;
import org.eclipse.jdt.annotation.NonNullByDefault;

/**
 * One part of a Robot Session (Player, a user tool, the Network Spy) as a process of the session's
 * launch: so it has a line in the Debug view under the session, and the debug UI gives it its own
 * console (one per part) fed from its output. A part outlives restarts of its OS process: it ends
 * when the part is down for good.
 */
public final class SessionPartProcess implements IProcess {
    /** What terminating the part does, and whether it still can be terminated. */
    public interface Control {
        void terminate();

        void write(String input) throws IOException;
    }

    private final String label;
    private final ILaunch launch;
    private final Control control;
    private final TextStreamMonitor out = new TextStreamMonitor();
    private final TextStreamMonitor err = new TextStreamMonitor();
    private final Map<String, String> attributes = new HashMap<>();
    private final IStreamsProxy streams = new IStreamsProxy() {
        @Override
        public IStreamMonitor getOutputStreamMonitor() {
            return out;
        }

        @Override
        public IStreamMonitor getErrorStreamMonitor() {
            return err;
        }

        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void write(String input) throws IOException {
            control.write(input);
        }
    };
    private volatile boolean terminated;
    /** Whether the launch manager was seen to hold the launch (see {@link #consoleMayRead()}). */
    private volatile boolean wasRegistered;
    private volatile int exitValue;
    private volatile String status = "";

    public SessionPartProcess(String label, String type, ILaunch launch, Control control) {
        this.label = label;
        this.launch = launch;
        this.control = control;
        attributes.put(IProcess.ATTR_PROCESS_TYPE, type);
        attributes.put(IProcess.ATTR_PROCESS_LABEL, label);
    }

    /** Adds the part to its launch (a console appears) and tells the debug model. */
    public SessionPartProcess register() {
        launch.addProcess(this);
        fire(DebugEvent.CREATE);
        return this;
    }

    public void stdout(String line) {
        if (consoleMayRead()) {
            out.append(line + "\n");
        }
    }

    public void stderr(String line) {
        if (consoleMayRead()) {
            err.append(line + "\n");
        }
    }

    /**
     * False once the launch has been removed, and its consoles with it: a line written to a closed console puts
     * "Output Stream is closed" in the Error Log. Asked on every line, of the launch manager, which unregisters
     * a launch before it tells the debug UI to dispose the consoles (a launch listener hears of it too late).
     */
    private boolean consoleMayRead() {
        DebugPlugin plugin = DebugPlugin.getDefault();
        if (plugin == null) {
            return true;
        }
        if (plugin.getLaunchManager().isRegistered(launch)) {
            wasRegistered = true;
            return true;
        }
        return !wasRegistered;
    }

    /** The part is down for good. */
    public void ended(int exit) {
        if (terminated) {
            return;
        }
        exitValue = exit;
        terminated = true;
        fire(DebugEvent.TERMINATE);
    }

    private void fire(int kind) {
        DebugPlugin plugin = DebugPlugin.getDefault();
        if (plugin != null) {
            plugin.fireDebugEventSet(new DebugEvent[] {new DebugEvent(this, kind)});
        }
    }

    /**
     * What the part is doing that the Debug view should say on its line, e.g. why the session stopped its
     * program ("" for nothing): the line reads "LABEL — STATUS".
     */
    public void status(String text) {
        String t = text == null ? "" : text;
        if (t.equals(status)) {
            return;
        }
        status = t;
        fire(DebugEvent.CHANGE);
    }

    public String status() {
        return status;
    }

    @Override
    public String getLabel() {
        String s = status;
        return s.isEmpty() ? label : label + " — " + s;
    }

    @Override
    public ILaunch getLaunch() {
        return launch;
    }

    @Override
    public IStreamsProxy getStreamsProxy() {
        return streams;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public synchronized void setAttribute(String key, String value) {
        attributes.put(key, value);
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public synchronized String getAttribute(String key) {
        return attributes.get(key);
    }

    @Override
    public int getExitValue() {
        if (!terminated) {
            throw new IllegalStateException(label + " is still running");
        }
        return exitValue;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public <T> T getAdapter(Class<T> adapter) {
        if (adapter.isInstance(this)) {
            return adapter.cast(this);
        }
        if (adapter == ILaunch.class) {
            return adapter.cast(launch);
        }
        return null;
    }

    @Override
    public boolean canTerminate() {
        return !terminated;
    }

    @Override
    public boolean isTerminated() {
        return terminated;
    }

    @Override
    public void terminate() {
        if (!terminated) {
            control.terminate();
        }
    }
}
