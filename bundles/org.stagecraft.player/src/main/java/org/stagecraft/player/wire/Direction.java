package org.stagecraft.player.wire;

/** Which way bytes travel on a Player connection. */
public enum Direction {
    /** Robot program to Player server: no preamble, messages only. */
    CLIENT_TO_SERVER("c2s"),
    /** Player server to robot program: a 32-byte ident banner, then messages. */
    SERVER_TO_CLIENT("s2c");

    private final String label;

    Direction(String label) {
        this.label = label;
    }

    /** The short label used in traces, logs and JSON output. */
    public String label() {
        return label;
    }

    public static Direction fromLabel(String label) {
        for (Direction d : values()) {
            if (d.label.equals(label)) {
                return d;
            }
        }
        throw new IllegalArgumentException("unknown direction '" + label + "' (expected c2s or s2c)");
    }
}
