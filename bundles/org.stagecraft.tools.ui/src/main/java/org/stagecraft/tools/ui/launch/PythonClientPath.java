package org.stagecraft.tools.ui.launch;

import java.io.File;
import java.io.IOException;
import java.net.URL;
import java.util.Optional;

import org.eclipse.core.runtime.FileLocator;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.osgi.framework.Bundle;

/**
 * Where Stagecraft's Python Player client ({@code stagecraft_player}) lives, so a robot program
 * started by a Robot Session can import it without installing anything: the {@code python/src}
 * folder of the bundle {@code org.stagecraft.python}, found at run time (the bundle is optional;
 * without it the program's environment is left as it is).
 */
public final class PythonClientPath {
    public static final String BUNDLE = "org.stagecraft.python";
    public static final String FOLDER = "python/src/";
    public static final String VARIABLE = "PYTHONPATH";

    private PythonClientPath() {
    }

    /** The folder holding the {@code stagecraft_player} package, or empty (with a warning logged). */
    public static Optional<String> folder() {
        Bundle bundle = Platform.getBundle(BUNDLE);
        if (bundle == null) {
            SessionParts.log(Status.warning(BUNDLE + " is not installed: robot programs do not get the stagecraft_player "
                    + "package on their " + VARIABLE));
            return Optional.empty();
        }
        try {
            URL entry = FileLocator.find(bundle, new org.eclipse.core.runtime.Path(FOLDER));
            if (entry == null) {
                SessionParts.log(Status.warning(BUNDLE + " has no folder " + FOLDER));
                return Optional.empty();
            }
            // a packed bundle gets the folder extracted; a folder-shaped one is used in place
            URL file = FileLocator.toFileURL(entry);
            return Optional.of(new File(file.getPath()).getAbsolutePath());
        } catch (IOException | RuntimeException e) {
            SessionParts.log(Status.warning("cannot locate " + FOLDER + " in " + BUNDLE + ": " + e.getMessage(), e));
            return Optional.empty();
        }
    }

    /**
     * {@code existing} with {@code folder} appended, so the user's own entries keep precedence;
     * unchanged if it already holds the folder.
     */
    public static String append(String existing, String folder) {
        if (existing == null || existing.isEmpty()) {
            return folder;
        }
        for (String part : existing.split(File.pathSeparator)) {
            if (part.equals(folder)) {
                return existing;
            }
        }
        return existing + File.pathSeparator + folder;
    }
}
