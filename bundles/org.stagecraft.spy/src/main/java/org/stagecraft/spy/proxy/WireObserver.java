package org.stagecraft.spy.proxy;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.hold.HoldAction;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.spy.hold.WorldChange;

/**
 * Sees what the spy forwards, after it has been forwarded. Called on the forwarding threads, so
 * implementations must not block: they may copy and queue, and wait only a bounded time for room
 * (the observation pipeline's complete observation: never for a part that makes no progress).
 */
public interface WireObserver {
    void opened(ConnectionInfo connection, long timeNanos);

    /** A chunk exactly as one read returned it; the array belongs to the observer. */
    void chunk(ConnectionInfo connection, Direction dir, byte[] data, long timeNanos);

    /**
     * A chunk as one read returned it, in the relay's buffer: the observer must not keep the array
     * (it is reused by the next read). By default a copy is handed to {@link #chunk(ConnectionInfo,
     * Direction, byte[], long)}; an observer that takes what it needs at once saves that copy.
     */
    default void chunk(ConnectionInfo connection, Direction dir, byte[] buffer, int offset, int length, long timeNanos) {
        chunk(connection, dir, java.util.Arrays.copyOfRange(buffer, offset, offset + length), timeNanos);
    }

    /** Both directions have ended (closed, reset, or the upstream refused). */
    void closed(ConnectionInfo connection, long timeNanos, String reason);

    /**
     * Something the user must see about the connection (Player refusing it), also given to the
     * spy's {@link SpyListener}s. Between {@link #opened} and {@link #closed}.
     */
    default void notice(SpyNotice notice, long timeNanos) {
    }

    /** A robot hold injected or held back a message (only when the user enabled holds). */
    default void holdAction(HoldAction action, long timeNanos) {
    }

    /** The robot hold changed (enabled, held, reasons). */
    default void holdState(HoldState state, long timeNanos) {
    }

    /** The session froze or thawed its simulated world. */
    default void worldChanged(WorldChange change, long timeNanos) {
    }

    WireObserver NONE = new WireObserver() {
        @Override
        public void opened(ConnectionInfo connection, long timeNanos) {
        }

        @Override
        public void chunk(ConnectionInfo connection, Direction dir, byte[] data, long timeNanos) {
        }

        @Override
        public void chunk(ConnectionInfo connection, Direction dir, byte[] buffer, int offset, int length, long timeNanos) {
        }

        @Override
        public void closed(ConnectionInfo connection, long timeNanos, String reason) {
        }
    };
}
