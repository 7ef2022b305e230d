package org.stagecraft.scene;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.StreamMessage;

/** The decoded Player body a bus message carries, whoever published it (the spy, a replay, a test). */
public final class Payloads {
    private Payloads() {
    }

    /** The body, or null when the payload is no Player message (or its decoding failed). */
    public static @Nullable MessageBody body(StreamMessage m) {
        Object p = m.payload();
        if (p instanceof SpyMessage s) {
            p = s.message();
        }
        if (p instanceof DecodedMessage d) {
            return d.hasProblem() ? null : d.body();
        }
        return p instanceof MessageBody b ? b : null;
    }
}
