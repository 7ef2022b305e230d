package org.stagecraft.mcap;

/**
 * A part of a file that could not be read: a damaged chunk, bytes skipped to find the next record, or
 * the incomplete end of a file that was cut off.
 *
 * @param offset        where the unread bytes start
 * @param length        how many bytes were not read
 * @param reason        why, for people
 * @param messagesLost  messages lost with it, from its message indexes, or -1 if unknown
 * @param cutOff        true for the incomplete last record of a file that was cut off (a crash, a full disk)
 */
public record Damage(long offset, long length, String reason, long messagesLost, boolean cutOff) {

    /** E.g. "bytes 1024..2048 (1024 bytes): chunk CRC mismatch; 312 messages lost". */
    public String describe() {
        String lost = messagesLost >= 0 ? "; " + messagesLost + " message" + (messagesLost == 1 ? "" : "s") + " lost" : "";
        return "bytes " + offset + ".." + (offset + length) + " (" + length + " bytes): " + reason + lost;
    }
}
