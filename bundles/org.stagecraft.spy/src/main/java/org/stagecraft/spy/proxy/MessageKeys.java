package org.stagecraft.spy.proxy;

import java.util.HashMap;
import java.util.Map;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.streams.StreamKey;

/**
 * The stream keys of one connection's messages ({@link SpyStreams#messageKey}), made once per
 * stream rather than once per message: a connection uses a handful of (direction, type, device,
 * subtype) combinations, and building a key (two address checks, an object) was a tenth of the
 * observation thread's time. Headers whose fields do not fit the cache's packing (garbage that
 * still framed) get a fresh key. Not thread-safe: owned by the observation thread.
 */
final class MessageKeys {
    /** More distinct keys than a Player connection has: a stream of garbage headers stops caching. */
    private static final int MAX_KEYS = 4096;

    private final ConnectionInfo connection;
    private final Map<Long, StreamKey> keys = new HashMap<>();

    MessageKeys(ConnectionInfo connection) {
        this.connection = connection;
    }

    /** Whether these are the keys of {@code c} (ids identify connections within one spy). */
    boolean isFor(ConnectionInfo c) {
        return connection == c || connection.equals(c);
    }

    StreamKey of(Direction dir, MessageHeader h) {
        int type = h.type();
        int interf = h.interf();
        int index = h.index();
        int subtype = h.subtype();
        if ((type & ~0xff) != 0 || (interf & ~0xffff) != 0 || (index & ~0xffff) != 0 || (subtype & ~0xffff) != 0) {
            return SpyStreams.messageKey(connection, dir, h);
        }
        long packed = (long) dir.ordinal() << 56 | (long) type << 48 | (long) interf << 32 | (long) index << 16 | subtype;
        StreamKey k = keys.get(packed);
        if (k == null) {
            k = SpyStreams.messageKey(connection, dir, h);
            if (keys.size() < MAX_KEYS) {
                keys.put(packed, k);
            }
        }
        return k;
    }
}
