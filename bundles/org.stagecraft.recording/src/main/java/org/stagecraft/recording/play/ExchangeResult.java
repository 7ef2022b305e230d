package org.stagecraft.recording.play;

/**
 * What one side of a replayed connection saw.
 *
 * @param sent            bytes this side sent (its recorded side)
 * @param received        bytes the other side sent
 * @param matches         whether those were exactly the other side's recorded bytes
 * @param firstDifference offset of the first byte that differs from the recording, or -1
 */
public record ExchangeResult(long sent, long received, boolean matches, long firstDifference) {

    /** "received N bytes, exactly what ... sent" or where it differs. */
    public String describe(String otherSide) {
        return "sent " + sent + " bytes, received " + received + " bytes, "
                + (matches ? "exactly what the recorded " + otherSide + " sent"
                        : "not what the recorded " + otherSide + " sent"
                                + (firstDifference >= 0 ? " (first difference at byte " + firstDifference + ")" : ""));
    }
}
