package org.stagecraft.spy.proxy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;

/** Cached message keys are exactly the keys {@link SpyStreams} makes, garbage headers included. */
class MessageKeysTest {
    private static final ConnectionInfo CONN = new ConnectionInfo(3, 6665, "127.0.0.1:40000", "127.0.0.1:6665",
            "127.0.0.1:7665");

    private static MessageHeader header(int interf, int index, int type, int subtype) {
        return new MessageHeader(0, 0, interf, index, type, subtype, 0.0, 0, 0);
    }

    @Test
    void sameKeysAsSpyStreamsAndMadeOncePerStream() {
        MessageKeys keys = new MessageKeys(CONN);
        for (Direction d : Direction.values()) {
            MessageHeader h = header(4, 0, 1, 1);
            assertEquals(SpyStreams.messageKey(CONN, d, h), keys.of(d, h));
            assertSame(keys.of(d, h), keys.of(d, header(4, 0, 1, 1)), "made once");
        }
        // fields that differ only in the bits the packing keeps apart
        MessageHeader a = header(0xffff, 0, 1, 0);
        MessageHeader b = header(0, 0xffff, 1, 0);
        MessageHeader c = header(0, 0, 1, 0xff);
        for (MessageHeader h : new MessageHeader[] { a, b, c }) {
            assertEquals(SpyStreams.messageKey(CONN, Direction.CLIENT_TO_SERVER, h), keys.of(Direction.CLIENT_TO_SERVER, h));
        }
    }

    /** The key, or the exception's class when no key can be made (fields out of a stream key's range). */
    private static Object outcome(java.util.function.Supplier<Object> make) {
        try {
            return make.get();
        } catch (RuntimeException e) {
            return e.getClass();
        }
    }

    @Test
    void garbageHeadersGetExactlyWhatSpyStreamsGives() {
        MessageKeys keys = new MessageKeys(CONN);
        MessageHeader[] odd = { header(-1, 7, 2, 3), header(1, -5, 2, 3), header(1, 2, 300, 3), header(1, 2, 3, 1 << 20), header(1, 2, 3, 300),
                header(1, 2, -1, -1) };
        for (MessageHeader h : odd) {
            for (Direction d : Direction.values()) {
                assertEquals(outcome(() -> SpyStreams.messageKey(CONN, d, h)), outcome(() -> keys.of(d, h)), h.toString());
            }
        }
        MessageHeader wide = header(1, 2, 3, 200);
        assertEquals(SpyStreams.messageKey(CONN, Direction.SERVER_TO_CLIENT, wide), keys.of(Direction.SERVER_TO_CLIENT, wide));
    }
}
