package org.stagecraft.replay.writelog;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;

/**
 * The payload text of one interface in a writelog file (after the seven header values), in both
 * directions: what Player's writelog writes and readlog reads, built into the codec's message classes.
 */
interface PayloadText {
    int DATA = 1;
    int RESP_ACK = 4;

    /** Why a writelog file cannot hold this message (it is then skipped), or null when it can. */
    @Nullable String cannotWrite(int type, int subtype, MessageBody body);

    /** A note to write on a comment line before the message, for what the text cannot say itself. */
    default LineNote noteFor(MessageBody body) {
        return LineNote.NONE;
    }

    /** Writes the payload; only called when {@link #cannotWrite} said null. */
    void write(int type, int subtype, MessageBody body, TextOut out);

    /** Reads the payload of a line whose header names this interface. */
    MessageBody read(int type, int subtype, Tokens in, LineNote note) throws WritelogSyntaxException;

    static WritelogSyntaxException unknown(String iface, int type, int subtype) {
        return new WritelogSyntaxException(iface + " message type " + type + " subtype " + subtype
                + " has no writelog text");
    }
}
