package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;

import org.eclipse.core.commands.Command;
import org.eclipse.jface.bindings.Binding;
import org.eclipse.jface.bindings.keys.KeySequence;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.commands.ICommandService;
import org.eclipse.ui.contexts.IContextService;
import org.eclipse.ui.handlers.IHandlerService;
import org.eclipse.ui.keys.IBindingService;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.replay.ui.internal.EditorCommand;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/**
 * The editor's transport, Reload, Plot, Show in Robot View and Export are workbench commands with
 * handlers and key bindings (plugin.xml), so users can rebind them: executed through the handler
 * service they move the editor's replay as its buttons do, and the keys are bound in the editor's
 * contexts.
 */
@Timeout(180)
class EditorCommandsTest {
    private final IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();

    @AfterEach
    void close() {
        page.closeAllEditors(false);
    }

    private static IHandlerService handlers() {
        return PlatformUI.getWorkbench().getService(IHandlerService.class);
    }

    private static void execute(EditorCommand c) throws Exception {
        handlers().executeCommand(c.id(), null);
    }

    @Test
    void transportCommandsExecutedThroughTheHandlerServiceMoveTheEditorsReplay() throws Exception {
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.spyLog("commands.mcap", 64 << 10));
        SessionLogEditorTest.waitForTimeline(e);
        long ten = e.log().startNanos() + 10_000_000_000L;
        e.session().transport().seek(ten);
        LinkedBlockingQueue<StreamMessage> received = new LinkedBlockingQueue<>();
        try (Subscription s = e.bus().subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 16), received::add)) {
            LogMessage stepped = null;
            for (int i = 0; i < 50 && (stepped == null || stepped.toStreamMessage().isEmpty()); i++) {
                execute(EditorCommand.STEP_FORWARD);
                stepped = e.replayer().lastPublished();
            }
            assertNotNull(stepped, "Step Forward published an entry");
            LogMessage published = stepped;
            StreamMessage expected = published.toStreamMessage().orElseThrow();
            assertEquals(published.timeNanos(), e.replayer().position(), "the replay is at the stepped message");
            Ui.spinUntil(() -> received.stream().anyMatch(m -> m.key().equals(expected.key()) && m.timeNanos() == expected.timeNanos()),
                    5_000, "the stepped message on the editor's bus");
            Ui.spinUntil(() -> e.timeline().position() == published.timeNanos(), 5_000, "the timeline cursor to follow the command");

            execute(EditorCommand.TO_START);
            assertEquals(e.log().startNanos(), e.replayer().position(), "To the Start");

            execute(EditorCommand.FASTER);
            assertEquals(2.0, e.replayer().speed(), 1e-9, "Faster: 1x to 2x");
            execute(EditorCommand.SLOWER);
            execute(EditorCommand.SLOWER);
            assertEquals(0.5, e.replayer().speed(), 1e-9, "Slower twice: 2x to 0.5x");
            Ui.spinUntil(() -> "0.5x".equals(e.transport().speedCombo().getText()), 5_000, "the speed box to show 0.5x");

            execute(EditorCommand.PLAY_PAUSE);
            assertTrue(e.replayer().playing(), "Play/Pause plays");
            Ui.spinUntil(() -> playButton(e).getText().contains("Pause"), 5_000, "the play button to offer Pause");
            execute(EditorCommand.PLAY_PAUSE);
            assertFalse(e.replayer().playing(), "Play/Pause pauses");
            Ui.spinUntil(() -> playButton(e).getText().contains("Play"), 5_000, "the play button to offer Play");
        }

        var before = e.log();
        execute(EditorCommand.RELOAD);
        assertTrue(e.reading(), "Reload reads the file again in the background");
        Ui.spinUntil(() -> !e.reading() && e.log() != before, 60_000, "the log read again");
    }

    @Test
    void theCommandsHaveNoHandlerWithoutASessionLogEditor() throws Exception {
        page.closeAllEditors(false);
        Command c = PlatformUI.getWorkbench().getService(ICommandService.class).getCommand(EditorCommand.PLAY_PAUSE.id());
        assertTrue(c.isDefined());
        Ui.spinUntil(() -> !c.isHandled(), 5_000, "the handler to go with the editor");
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.trace());
        Ui.spinUntil(c::isHandled, 5_000, "a handler while a Session Log editor is active");
        assertNotNull(e.replayer());
    }

    @Test
    void everyCommandIsDefinedAndTheKeysAreBoundInTheEditorsContexts() throws Exception {
        ICommandService commands = PlatformUI.getWorkbench().getService(ICommandService.class);
        for (EditorCommand c : EditorCommand.values()) {
            Command command = commands.getCommand(c.id());
            assertTrue(command.isDefined(), c.id());
            assertEquals("Session Log", command.getCategory().getName(), c.id());
        }
        IContextService contexts = PlatformUI.getWorkbench().getService(IContextService.class);
        assertTrue(contexts.getContext(EditorCommand.EDITOR_CONTEXT).isDefined());
        assertTrue(contexts.getContext(EditorCommand.TIMELINE_CONTEXT).isDefined());

        IBindingService bindings = PlatformUI.getWorkbench().getService(IBindingService.class);
        Map<String, String> timeline = new HashMap<>();
        Map<String, String> editor = new HashMap<>();
        for (Binding b : bindings.getBindings()) {
            if (b.getParameterizedCommand() == null || b.getType() != Binding.SYSTEM
                    || !"org.eclipse.ui.defaultAcceleratorConfiguration".equals(b.getSchemeId())) {
                continue;
            }
            String command = b.getParameterizedCommand().getId();
            String keys = ((KeySequence) b.getTriggerSequence()).format();
            if (EditorCommand.TIMELINE_CONTEXT.equals(b.getContextId())) {
                timeline.put(keys, command);
            } else if (EditorCommand.EDITOR_CONTEXT.equals(b.getContextId())) {
                editor.put(keys, command);
            }
        }
        Map<String, EditorCommand> expectedOnTimeline = Map.of(key("SPACE"), EditorCommand.PLAY_PAUSE, key("ARROW_RIGHT"), EditorCommand.STEP_FORWARD,
                key("ARROW_LEFT"), EditorCommand.STEP_BACK, key("HOME"), EditorCommand.TO_START, key("ARROW_UP"), EditorCommand.FASTER,
                key("ARROW_DOWN"), EditorCommand.SLOWER);
        expectedOnTimeline.forEach((k, c) -> assertEquals(c.id(), timeline.get(k), "on the timeline, " + k + ": " + timeline));
        assertEquals(EditorCommand.RELOAD.id(), editor.get(key("F5")), "in the editor, F5: " + editor);
    }

    private static String key(String sequence) {
        try {
            return KeySequence.getInstance(sequence).format();
        } catch (org.eclipse.jface.bindings.keys.ParseException e) {
            throw new AssertionError(sequence, e);
        }
    }

    @Test
    void theKeysOnTheTimelineRunTheCommandsAndATextFieldKeepsThem() throws Exception {
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.trace());
        e.setFocus();
        Ui.spinUntil(() -> e.timeline().canvas().isFocusControl(), 5_000, "the timeline to have the focus");
        Event space = new Event();
        space.keyCode = ' ';
        space.character = ' ';
        e.timeline().canvas().notifyListeners(SWT.KeyDown, space);
        assertTrue(e.replayer().playing(), "Space on the timeline plays");
        e.timeline().canvas().notifyListeners(SWT.KeyDown, space);
        assertFalse(e.replayer().playing(), "and pauses");

        // in the time field Space is a character, not Play
        var time = timeField(e);
        time.setFocus();
        Ui.spinUntil(time::isFocusControl, 5_000, "the time field to have the focus");
        Event typed = new Event();
        typed.keyCode = ' ';
        typed.character = ' ';
        time.notifyListeners(SWT.KeyDown, typed);
        assertFalse(e.replayer().playing(), "Space typed in a text field does not play");
    }

    private static Button playButton(SessionLogEditor e) {
        for (Control c : e.transport().control().getChildren()) {
            if (c instanceof Button b && (b.getText().contains("Play") || b.getText().contains("Pause"))) {
                return b;
            }
        }
        throw new AssertionError("no play button");
    }

    private static org.eclipse.swt.widgets.Text timeField(SessionLogEditor e) {
        for (Control c : e.transport().control().getChildren()) {
            if (c instanceof org.eclipse.swt.widgets.Text t) {
                return t;
            }
        }
        throw new AssertionError("no time field");
    }
}
