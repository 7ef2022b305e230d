package org.stagecraft.demo.ui;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.eclipse.core.runtime.FileLocator;
import org.eclipse.core.runtime.Platform;
import org.osgi.framework.Bundle;
import org.stagecraft.demo.recorded.RecordedPlayerMain;
import org.stagecraft.demo.recorded.RecordedRobotMain;
import org.stagecraft.tools.types.GenericToolType;
import org.stagecraft.tools.types.ToolDefinition;

/**
 * The recorded Player and the recorded robot program as programs a Robot Session can start: the
 * product's own Java with the few plain-Java bundles they need on the class path. No Python and no
 * test script: what runs is shipped in the product ({@code org.stagecraft.demo}).
 */
final class RecordedPrograms {
    static final String ROBOT_TOOL = "Recorded robot program";
    /** Read by the recorded Player and robot program when no --recording is given. */
    static final String RECORDING_VARIABLE = "STAGECRAFT_RECORDING";
    /** Plain-Java bundles the recorded peers load classes from (the cfg reader is in tools). */
    private static final List<String> CLASS_PATH_BUNDLES = List.of("org.stagecraft.demo", "org.stagecraft.recording",
            "org.stagecraft.player", "org.stagecraft.tools", "com.google.gson");

    private RecordedPrograms() {
    }

    static Path java() {
        return Path.of(System.getProperty("java.home"), "bin", "java");
    }

    static String classPath() throws IOException {
        List<String> entries = new ArrayList<>();
        for (String id : CLASS_PATH_BUNDLES) {
            Bundle b = Platform.getBundle(id);
            Optional<File> f = b == null ? Optional.empty() : FileLocator.getBundleFileLocation(b);
            if (f.isEmpty()) {
                throw new IOException("bundle " + id + " is not installed as a file, so the recorded Player cannot load it");
            }
            File location = f.get();
            // a bundle run from its project (development) keeps its classes in target/classes
            File classes = new File(location, "target/classes");
            entries.add((location.isDirectory() && classes.isDirectory() ? classes : location).getAbsolutePath());
        }
        return String.join(File.pathSeparator, entries);
    }

    /**
     * Writes the recorded Player's launcher: a Robot Session runs "Player" as one program plus
     * {@code -p PORT copy.cfg}, so the Java command line goes into a script.
     */
    static Path writePlayerLauncher(Path directory) throws IOException {
        Files.createDirectories(directory);
        Path script = directory.resolve("recorded-player");
        String text = "#!/bin/sh\n"
                + "# Written by the Stagecraft demo: the recorded Player (org.stagecraft.demo), run as Player is run:\n"
                + "#   recorded-player -p PORT file.cfg      (the recording: $" + RECORDING_VARIABLE + " or --recording FILE)\n"
                + "exec " + quote(java().toString()) + " -cp " + quote(classPath()) + " "
                + RecordedPlayerMain.class.getName() + " \"$@\"\n";
        Path tmp = Files.createTempFile(directory, "recorded-player", ".tmp");
        Files.writeString(tmp, text);
        Files.setPosixFilePermissions(tmp, PosixFilePermissions.fromString("rwxr-xr-x"));
        return Files.move(tmp, script, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    /** The recorded robot program as a helper tool of the session (started first; it waits for the spy). */
    static ToolDefinition robotTool(Path recording, int port) throws IOException {
        String args = String.join(" ", List.of("-cp", quoteForSplit(classPath()), RecordedRobotMain.class.getName(),
                "--connect", "127.0.0.1:" + port, "--recording", quoteForSplit(recording.toString())));
        return new ToolDefinition(ROBOT_TOOL, GenericToolType.ID, java().toString(), args, "", Map.of(), "", "never", 30, true);
    }

    /** Single quotes for sh. */
    private static String quote(String s) {
        return "'" + s.replace("'", "'\\''") + "'";
    }

    /** Double quotes for the tool manager's shell-like argument splitting (a backslash escapes there). */
    private static String quoteForSplit(String s) {
        return "\"" + s.replace("\\", "\\\\").replace("\"", "\\\"") + "\"";
    }
}
