package org.stagecraft.replay.fields;

/**
 * A condition that cannot be read: what is wrong and where. {@link #getMessage()} says both, e.g.
 * {@code "at character 17: 'deg' is an angle, but min(ranges) is a length"}.
 */
public final class ConditionException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    private final String text;
    private final int position;
    private final String reason;

    public ConditionException(String text, int position, String reason) {
        super("at character " + (position + 1) + ": " + reason);
        this.text = text;
        this.position = position;
        this.reason = reason;
    }

    /** The whole text that was read. */
    public String text() {
        return text;
    }

    /** Where the problem is, 0-based in {@link #text()}. */
    public int position() {
        return position;
    }

    /** What the problem is, without the position. */
    public String reason() {
        return reason;
    }

    /** Two lines for a console: the text, and a caret under the problem. */
    public String pointer() {
        return text + "\n" + " ".repeat(Math.max(0, Math.min(position, text.length()))) + "^";
    }
}
