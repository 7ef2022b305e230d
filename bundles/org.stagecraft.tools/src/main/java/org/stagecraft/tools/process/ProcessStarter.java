package org.stagecraft.tools.process;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import com.pty4j.PtyProcessBuilder;
import org.eclipse.jdt.annotation.Nullable;

/**
 * Starts a tool's process on a pseudo-terminal (pty4j), or on plain pipes when no terminal can be
 * made.
 * <p>
 * Why a terminal: C stdio (Player's) buffers a pipe in 4 KiB blocks, so "Listening on ports" would
 * only show once the buffer fills, and the last lines of a crash would be lost; on a terminal it
 * writes each line. Standard error gets a terminal of its own (pty4j's console mode), so the two
 * streams stay apart. A process on a terminal is also the leader of a session and process group of
 * its own, which is what the {@link OrphanReaper} kills when the IDE dies.
 */
public final class ProcessStarter {
    /** Set to false ({@code -Dstagecraft.tools.pty=false}) to run tools on pipes. */
    public static final String PTY_PROPERTY = "stagecraft.tools.pty";

    /** A started process, and a note for the tool's console when it is not on a terminal. */
    public record Started(Process process, boolean onTerminal, @Nullable String note) {
    }

    private final boolean tryTerminal;

    public ProcessStarter(boolean tryTerminal) {
        this.tryTerminal = tryTerminal;
    }

    /** On a terminal unless the system property says otherwise. */
    public static ProcessStarter fromSystemProperties() {
        return new ProcessStarter(!"false".equalsIgnoreCase(System.getProperty(PTY_PROPERTY, "true")));
    }

    /**
     * @param environment added to (and overriding) this JVM's environment
     * @throws IOException if the program cannot be run at all (on pipes either)
     */
    public Started start(List<String> command, @Nullable Path workingDir, Map<String, String> environment) throws IOException {
        String note = null;
        if (tryTerminal) {
            try {
                return new Started(onTerminal(command, workingDir, environment), true, null);
            } catch (IOException | RuntimeException | LinkageError e) {
                if (isMissingProgram(e)) {
                    throw e instanceof IOException io ? io : new IOException(e.getMessage(), e);
                }
                note = "no pseudo-terminal (" + e.getMessage() + "): output through pipes, so a C program's lines may"
                        + " come late, in blocks";
            }
        }
        ProcessBuilder pb = new ProcessBuilder(command);
        if (workingDir != null) {
            pb.directory(workingDir.toFile());
        }
        pb.environment().putAll(environment);
        return new Started(pb.start(), false, note);
    }

    private static Process onTerminal(List<String> command, @Nullable Path workingDir, Map<String, String> environment)
            throws IOException {
        String program = command.get(0);
        // pty4j execs without a PATH search of its own when the name has no slash: resolve it as
        // ProcessBuilder would, so "player" and "python3" work and a missing one is reported the same way.
        String resolved = program.contains("/") ? program : ExecutableLookup.onPath(program, environment)
                .map(Path::toString).orElseThrow(() -> new IOException("Cannot run program \"" + program
                        + "\": error=2, No such file or directory"));
        if (program.contains("/") && !java.nio.file.Files.isExecutable(Path.of(program))) {
            throw new IOException("Cannot run program \"" + program + "\": error=2, No such file or directory");
        }
        String[] cmd = command.toArray(String[]::new);
        cmd[0] = resolved;
        Map<String, String> env = new HashMap<>(System.getenv());
        env.putAll(environment);
        // a terminal that does not draw: no colour codes or cursor movement in the console
        env.putIfAbsent("TERM", "dumb");
        PtyProcessBuilder b = new PtyProcessBuilder(cmd).setEnvironment(env).setConsole(true)
                .setRedirectErrorStream(false).setInitialColumns(250).setInitialRows(50);
        if (workingDir != null) {
            b.setDirectory(workingDir.toString());
        }
        return b.start();
    }

    private static boolean isMissingProgram(Throwable e) {
        String m = String.valueOf(e.getMessage());
        return m.contains("error=2,") || m.contains("No such file or directory");
    }
}
