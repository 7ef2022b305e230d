package org.stagecraft.spy.proxy;

import java.io.IOException;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.SpyLogWriter;

/** Records what the spy observes into an MCAP spy log. */
public final class LogRecorder implements SpyRecorder {
    private final SpyLogWriter writer;

    public LogRecorder(SpyLogWriter writer) {
        this.writer = writer;
    }

    public SpyLogWriter writer() {
        return writer;
    }

    @Override
    public void opened(ConnectionInfo c, long timeNanos) throws IOException {
        writer.connectionOpened(timeNanos, c.id(), c.client(), c.listen(), c.upstream());
    }

    @Override
    public void closed(ConnectionInfo c, long timeNanos, String reason) throws IOException {
        writer.connectionClosed(timeNanos, c.id(), reason);
    }

    @Override
    public void wire(ConnectionInfo c, Direction dir, WireEvent event, long timeNanos) throws IOException {
        writer.wire(timeNanos, c.id(), c.port(), dir, event);
    }

    @Override
    public void diagnostic(ConnectionInfo c, Direction dir, long streamOffset, String text, long timeNanos)
            throws IOException {
        writer.diagnostic(timeNanos, c.id(), dir, streamOffset, text);
    }

    @Override
    public void hold(HoldEntry entry) throws IOException {
        writer.hold(entry);
    }

    @Override
    public void flush() throws IOException {
        writer.flush();
    }

    @Override
    public void close() throws IOException {
        writer.close();
    }
}
