package org.stagecraft.replay.ui.internal;

import java.net.URI;
import java.nio.file.Path;

import org.eclipse.core.resources.IFile;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.ui.IEditorInput;
import org.eclipse.ui.IPathEditorInput;
import org.eclipse.ui.IURIEditorInput;

/** The local file behind an editor input: a workspace file, a file opened from outside, or a path. */
public final class EditorInputs {
    private EditorInputs() {
    }

    /** @return the file, or null when the input is not a local file */
    public static @Nullable Path path(IEditorInput input) {
        @Nullable IFile file = input.getAdapter(IFile.class);
        if (file != null && file.getLocation() != null) {
            return file.getLocation().toPath();
        }
        if (input instanceof IPathEditorInput p && p.getPath() != null) {
            return p.getPath().toPath();
        }
        if (input instanceof IURIEditorInput u) {
            URI uri = u.getURI();
            if (uri != null && "file".equals(uri.getScheme())) {
                return Path.of(uri);
            }
        }
        return null;
    }
}
