package org.stagecraft.foxglove.live;

import java.io.IOException;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.SpyRecorder;
import org.stagecraft.spy.proxy.SpyStreams;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;

/**
 * A {@link SpyRecorder} in front of the spy log (or of none) that also publishes {@link ConnectionEnded}
 * on the bus when a connection closes. The observation pipeline records a connection's end after it has
 * published the connection's last message, on the same thread, so the event follows those messages on
 * the bus. It travels under the connection's diagnostics key, as a payload no view takes for a
 * diagnostic.
 */
public final class EndOfConnections implements SpyRecorder {
    private final @Nullable SpyRecorder log;
    private final StreamBus bus;

    /** @param log the spy log, or null when there is none */
    public EndOfConnections(@Nullable SpyRecorder log, StreamBus bus) {
        this.log = log;
        this.bus = bus;
    }

    @Override
    public void opened(ConnectionInfo connection, long timeNanos) throws IOException {
        if (log != null) {
            log.opened(connection, timeNanos);
        }
    }

    @Override
    public void closed(ConnectionInfo connection, long timeNanos, String reason) throws IOException {
        // first the bus: a log that fails here must not hide the end from the viewers
        bus.publish(new StreamMessage(SpyStreams.diagnosticKey(connection, Direction.SERVER_TO_CLIENT), timeNanos,
                new ConnectionEnded(connection)));
        if (log != null) {
            log.closed(connection, timeNanos, reason);
        }
    }

    @Override
    public void wire(ConnectionInfo connection, Direction dir, WireEvent event, long timeNanos) throws IOException {
        if (log != null) {
            log.wire(connection, dir, event, timeNanos);
        }
    }

    @Override
    public void diagnostic(ConnectionInfo connection, Direction dir, long streamOffset, String text, long timeNanos)
            throws IOException {
        if (log != null) {
            log.diagnostic(connection, dir, streamOffset, text, timeNanos);
        }
    }

    @Override
    public void hold(HoldEntry entry) throws IOException {
        if (log != null) {
            log.hold(entry);
        }
    }

    @Override
    public void flush() throws IOException {
        if (log != null) {
            log.flush();
        }
    }

    @Override
    public @Nullable Logged logged() {
        return log != null ? log.logged() : null;
    }

    @Override
    public void close() throws IOException {
        if (log != null) {
            log.close();
        }
    }
}
