package org.stagecraft.tools.process;

/**
 * What to do when a tool ends by itself during a session.
 *
 * @param maxRestarts how many restarts in one session at most (after that the tool stays down)
 */
public record RestartPolicy(Mode mode, int maxRestarts) {
    public enum Mode {
        /** Leave it down. */
        NEVER,
        /** Restart it when it exits with a non-zero code or is killed by a signal. */
        ON_FAILURE,
        /** Restart it whenever it exits. */
        ALWAYS
    }

    public static final RestartPolicy NEVER = new RestartPolicy(Mode.NEVER, 0);

    public RestartPolicy {
        if (maxRestarts < 0) {
            throw new IllegalArgumentException("maxRestarts " + maxRestarts + " < 0");
        }
    }

    public static RestartPolicy onFailure(int maxRestarts) {
        return new RestartPolicy(Mode.ON_FAILURE, maxRestarts);
    }

    public static RestartPolicy always(int maxRestarts) {
        return new RestartPolicy(Mode.ALWAYS, maxRestarts);
    }

    /** Whether to restart after an exit with {@code exitCode}, given {@code restartsSoFar}. */
    public boolean restartAfter(int exitCode, int restartsSoFar) {
        if (restartsSoFar >= maxRestarts) {
            return false;
        }
        return switch (mode) {
            case NEVER -> false;
            case ON_FAILURE -> exitCode != 0;
            case ALWAYS -> true;
        };
    }

    /** As stored in preferences and launch configurations: "never", "on-failure:3", "always:5". */
    public String text() {
        return switch (mode) {
            case NEVER -> "never";
            case ON_FAILURE -> "on-failure:" + maxRestarts;
            case ALWAYS -> "always:" + maxRestarts;
        };
    }

    /** Parses {@link #text()}; a missing count means 3. */
    public static RestartPolicy parse(String text) {
        String t = text == null ? "" : text.trim();
        if (t.isEmpty() || t.equals("never")) {
            return NEVER;
        }
        String[] p = t.split(":", 2);
        int max;
        try {
            max = p.length > 1 ? Integer.parseInt(p[1].trim()) : 3;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("restart policy '" + text + "': '" + p[1] + "' is not a number");
        }
        return switch (p[0].trim()) {
            case "on-failure" -> onFailure(max);
            case "always" -> always(max);
            default -> throw new IllegalArgumentException("restart policy '" + text
                    + "' is not never, on-failure[:N] or always[:N]");
        };
    }
}
