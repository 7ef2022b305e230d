package org.stagecraft.replay.ui.internal;

import java.util.Arrays;
import java.util.Optional;

import org.eclipse.ui.PartInitException;
import org.stagecraft.replay.ui.SessionLogEditor;

/**
 * The Session Log editor's commands, as contributed in plugin.xml ({@code org.eclipse.ui.commands},
 * bound to keys in the editor's contexts): what each does to an editor. The transport bar's buttons
 * and the key bindings' handler ({@link EditorCommandHandler}) both run them, so a button and its key
 * do the same.
 */
public enum EditorCommand {
    TO_START("toStart", e -> e.session().transport().toStart()),
    STEP_BACK("stepBack", e -> e.session().transport().stepBack()),
    PLAY_PAUSE("playPause", e -> e.session().transport().playPause()),
    STEP_FORWARD("stepForward", e -> e.session().transport().stepForward()),
    FASTER("faster", e -> e.session().transport().faster()),
    SLOWER("slower", e -> e.session().transport().slower()),
    RELOAD("reload", SessionLogEditor::reload),
    SHOW_IN_ROBOT_VIEW("showInRobotView", SessionLogEditor::showInRobotView),
    PLOT("plot", SessionLogEditor::showPlot),
    EXPORT("export", e -> ExportMenu.show(e.transport().control(), e));

    /** The prefix of every command id: {@code org.stagecraft.replay.ui.playPause}. */
    public static final String PREFIX = "org.stagecraft.replay.ui.";
    /** Active while a Session Log editor is: its commands' bindings that work anywhere in it. */
    public static final String EDITOR_CONTEXT = "org.stagecraft.replay.ui.sessionLogContext";
    /** Active while the editor's timeline has the focus: plain keys (Space, arrows) that a text field needs for itself. */
    public static final String TIMELINE_CONTEXT = "org.stagecraft.replay.ui.timelineContext";

    private interface Action {
        void run(SessionLogEditor editor) throws PartInitException;
    }

    private final String id;
    private final Action action;

    EditorCommand(String name, Action action) {
        this.id = PREFIX + name;
        this.action = action;
    }

    public String id() {
        return id;
    }

    public void run(SessionLogEditor editor) throws PartInitException {
        action.run(editor);
    }

    public static Optional<EditorCommand> of(String commandId) {
        return Arrays.stream(values()).filter(c -> c.id.equals(commandId)).findFirst();
    }
}
