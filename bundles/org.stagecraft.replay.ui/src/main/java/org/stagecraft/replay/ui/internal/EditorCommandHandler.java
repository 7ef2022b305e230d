package org.stagecraft.replay.ui.internal;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.handlers.HandlerUtil;
import org.stagecraft.replay.ui.SessionLogEditor;

/**
 * The handler of every {@link EditorCommand}: runs the command that was executed on the active
 * Session Log editor (plugin.xml activates it only while one is the active editor).
 */
public final class EditorCommandHandler extends AbstractHandler {
    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) throws ExecutionException {
        String id = event.getCommand().getId();
        EditorCommand command = EditorCommand.of(id).orElseThrow(() -> new ExecutionException("not a Session Log command: " + id));
        if (!(HandlerUtil.getActiveEditor(event) instanceof SessionLogEditor editor)) {
            throw new ExecutionException(id + ": no Session Log editor is active");
        }
        try {
            command.run(editor);
        } catch (PartInitException e) {
            throw new ExecutionException(id + ": " + e.getMessage(), e);
        }
        return null;
    }
}
