package org.stagecraft.player.session;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;

/**
 * Frames every direction of every connection of a session (a trace, a log), with one
 * {@link PlayerFramer} per connection and direction while it holds bytes. Events come out in the order
 * the chunks that complete them come in.
 *
 * <p>
 * Memory per connection is small: a direction that stands at a message boundary, or holds only the
 * first bytes of the next header (the usual state between chunks), keeps its stream offset and those
 * few bytes, not a framer with its buffers. A trace of a million connections that never close is
 * framed in a small heap this way (issue 17). The next chunk of a parked direction gets a fresh framer,
 * fed the held bytes first, and its events are moved to the direction's offset.
 */
public final class SessionFramer {
    private static final Pattern AT_OFFSET = Pattern.compile("at offset (\\d+)");
    /** A direction holding at most this many unreported bytes (a partial header) keeps them, not a framer. */
    static final int PARK_MAX_BYTES = 64;

    private final Consumer<? super SessionEvent> sink;
    /** Open connections by number; the rare second port of one number goes to {@link Connection#others}. */
    private final Map<Integer, Connection> connections = new HashMap<>();
    private double now;

    public SessionFramer(Consumer<? super SessionEvent> sink) {
        this.sink = sink;
    }

    /** Feeds bytes one recv() returned on a stream at time t. */
    public void chunk(double t, StreamId stream, byte[] data, int off, int len) {
        now = t;
        connection(stream).accept(stream.dir(), data, off, len);
    }

    public void chunk(double t, StreamId stream, byte[] data) {
        chunk(t, stream, data, 0, data.length);
    }

    /** The connection closed: both directions end, and unfinished bytes are reported. */
    public void close(double t, int conn) {
        now = t;
        @Nullable Connection c = connections.remove(conn);
        if (c != null) {
            c.end();
        }
    }

    /** Ends every stream still open (end of a recording). */
    public void endAll(double t) {
        now = t;
        for (Connection c : connections.values()) {
            c.end();
        }
        connections.clear();
    }

    /** Directions holding a framer now (the others are parked, with at most a partial header); for tests. */
    public int activeFramers() {
        int n = 0;
        for (Connection c : connections.values()) {
            n += c.activeFramers();
        }
        return n;
    }

    /** Connections open now; for tests. */
    public int openConnections() {
        return connections.size();
    }

    private Connection connection(StreamId stream) {
        Connection c = connections.get(stream.conn());
        if (c == null) {
            c = new Connection(stream.conn(), stream.port());
            connections.put(stream.conn(), c);
        } else if (c.port != stream.port()) {
            c = c.other(stream.port());
        }
        return c;
    }

    /** Convenience for callers that know the direction by label. */
    public static StreamId stream(int conn, int port, String dirLabel) {
        return new StreamId(conn, port, Direction.fromLabel(dirLabel));
    }

    /**
     * Both directions of one connection (conn, port). A direction is either active (a {@link Lane} with
     * its framer) or parked: then only its stream offset and the bytes it has not reported yet (at most
     * {@link #PARK_MAX_BYTES}) are kept here, in fields, so a parked connection costs one small object.
     */
    private final class Connection {
        final int conn;
        final int port;
        long clientToServerAt;
        long serverToClientAt;
        byte @Nullable [] clientToServerHeld;
        byte @Nullable [] serverToClientHeld;
        @Nullable Lane clientToServer;
        @Nullable Lane serverToClient;
        /** The same connection number with another port (only in malformed recordings). */
        @Nullable List<Connection> others;

        Connection(int conn, int port) {
            this.conn = conn;
            this.port = port;
        }

        void accept(Direction dir, byte[] data, int off, int len) {
            boolean c2s = dir == Direction.CLIENT_TO_SERVER;
            Lane lane = c2s ? clientToServer : serverToClient;
            if (lane == null) {
                lane = c2s ? new Lane(this, dir, clientToServerAt, clientToServerHeld)
                        : new Lane(this, dir, serverToClientAt, serverToClientHeld);
                setActive(dir, lane);
            }
            lane.accept(data, off, len);
        }

        /** The lane stands at an item start holding at most a partial header: keep its place and bytes, drop it. */
        void park(Lane lane, long at, byte @Nullable [] held) {
            if (lane.dir == Direction.CLIENT_TO_SERVER) {
                clientToServerAt = at;
                clientToServerHeld = held;
            } else {
                serverToClientAt = at;
                serverToClientHeld = held;
            }
            setActive(lane.dir, null);
        }

        private void setActive(Direction dir, @Nullable Lane lane) {
            if (dir == Direction.CLIENT_TO_SERVER) {
                clientToServer = lane;
            } else {
                serverToClient = lane;
            }
        }

        Connection other(int otherPort) {
            if (others == null) {
                others = new ArrayList<>(1);
            }
            for (Connection o : others) {
                if (o.port == otherPort) {
                    return o;
                }
            }
            Connection o = new Connection(conn, otherPort);
            others.add(o);
            return o;
        }

        /** Ends both directions: whatever they hold is reported as unframed. */
        void end() {
            end(Direction.CLIENT_TO_SERVER, clientToServer, clientToServerAt, clientToServerHeld);
            end(Direction.SERVER_TO_CLIENT, serverToClient, serverToClientAt, serverToClientHeld);
            clientToServer = serverToClient = null;
            clientToServerHeld = serverToClientHeld = null;
            if (others != null) {
                others.forEach(Connection::end);
            }
        }

        private void end(Direction dir, @Nullable Lane active, long at, byte @Nullable [] held) {
            if (active == null && held != null) {
                active = new Lane(this, dir, at, held);
            }
            if (active != null) {
                active.end();
            }
        }

        int activeFramers() {
            int n = (clientToServer != null ? 1 : 0) + (serverToClient != null ? 1 : 0);
            if (others != null) {
                for (Connection o : others) {
                    n += o.activeFramers();
                }
            }
            return n;
        }
    }

    /**
     * One direction while it has a framer: from a chunk that finds it parked until it stands at an item
     * start again holding at most {@link #PARK_MAX_BYTES} unreported bytes. Every byte fed is reported by
     * exactly one event, in order; after a banner or a message the framer stands at the start of the
     * next header, so it is fully described by the bytes it received since (a header is judged only once
     * whole): a fresh framer fed those bytes again is in the same state. After unframed bytes the framer
     * may be in the middle of skipping garbage, so it is kept until the next message.
     */
    private final class Lane implements Consumer<WireEvent> {
        final Connection owner;
        final Direction dir;
        final PlayerFramer framer;
        /** Stream offset at which this framer started (its offsets are relative to it). */
        final long base;
        long fed;
        long reported;
        /** The last event was a banner or a message (or there was none): the framer stands at an item start. */
        boolean atItem = true;
        /** The bytes fed again at the start (the parked direction's held bytes), or null. */
        byte @Nullable [] refed;

        /** A framer for a direction parked at stream offset {@code at} with {@code held} bytes not yet reported. */
        Lane(Connection owner, Direction dir, long at, byte @Nullable [] held) {
            this.owner = owner;
            this.dir = dir;
            this.base = at;
            this.fed = at;
            this.reported = at;
            // a new server stream starts with the ident; anything else stands at a message header, where a
            // framer for the client's direction starts
            this.framer = new PlayerFramer(at == 0 ? dir : Direction.CLIENT_TO_SERVER, this);
            if (held != null) {
                refed = held;
                fed += held.length;
                framer.accept(held, 0, held.length);
            }
        }

        void accept(byte[] data, int off, int len) {
            fed += len;
            framer.accept(data, off, len);
            long unreported = fed - reported;
            if (!atItem || unreported > PARK_MAX_BYTES) {
                refed = null; // kept: the bytes held may now begin before this chunk
                return;
            }
            int u = (int) unreported;
            int fromRefed = Math.max(0, u - len);
            if (fromRefed > (refed == null ? 0 : refed.length)) {
                refed = null;
                return; // the held bytes began in chunks fed since the framer was revived
            }
            byte[] held = null;
            if (u > 0) {
                held = new byte[u];
                if (fromRefed > 0) {
                    System.arraycopy(refed, refed.length - fromRefed, held, 0, fromRefed);
                }
                System.arraycopy(data, off + len - (u - fromRefed), held, fromRefed, u - fromRefed);
            }
            owner.park(this, reported, held);
        }

        void end() {
            framer.end();
        }

        @Override
        public void accept(WireEvent e) {
            WireEvent moved = base == 0 ? e : moved(e);
            atItem = !(e instanceof WireEvent.Unframed);
            reported += switch (e) {
                case WireEvent.Banner b -> b.raw().length;
                case WireEvent.Frame f -> f.wireSize();
                case WireEvent.Unframed u -> u.length();
            };
            sink.accept(new SessionEvent(now, new StreamId(owner.conn, owner.port, dir), moved));
        }

        /** The event of a framer that started at {@code base}, at its place in the whole stream. */
        private WireEvent moved(WireEvent e) {
            return switch (e) {
                case WireEvent.Banner b -> new WireEvent.Banner(base + b.offset(), b.raw());
                case WireEvent.Frame f -> new WireEvent.Frame(base + f.offset(), f.header(), f.payloadUnsafe());
                // a framer's reasons may name an offset of its own ("corrupt message header at offset 12")
                case WireEvent.Unframed u -> new WireEvent.Unframed(base + u.offset(), u.raw(), movedText(u.reason()));
            };
        }

        private String movedText(String reason) {
            Matcher m = AT_OFFSET.matcher(reason);
            if (!m.find()) {
                return reason;
            }
            StringBuilder out = new StringBuilder();
            do {
                m.appendReplacement(out, "at offset " + (base + Long.parseLong(m.group(1))));
            } while (m.find());
            m.appendTail(out);
            return out.toString();
        }
    }
}
