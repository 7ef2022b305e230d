package org.stagecraft.player.it;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogReader;

/**
 * What a spy log says, decoded with the project's own reader and Player decoder: every message of
 * every connection in log order, with typed accessors for what the tests check (poses, velocity
 * commands, sonar and laser data).
 */
final class SpyLog {
    static final int PLAYER = 1;
    static final int POSITION2D = 4;
    static final int LASER = 6;
    static final int RANGER = 62;
    static final int DATA = 1;
    static final int CMD = 2;
    static final int REQ = 3;
    static final int RESP_ACK = 4;
    static final int SYNCH = 5;
    /** The player interface's REQ DATA: one round of data, in PULL mode. */
    static final int REQ_DATA = 4;

    /** One decoded message of the log. */
    record Msg(long timeNanos, int conn, int port, Direction dir, DecodedMessage decoded) {
        MessageHeader header() {
            return decoded.header();
        }

        boolean is(int interf, int index, int type, int subtype) {
            MessageHeader h = header();
            return h.interf() == interf && h.index() == index && h.type() == type && h.subtype() == subtype;
        }
    }

    final boolean recovered;
    final List<LogConnection> connections;
    final List<Msg> messages = new ArrayList<>();
    final long decodeProblems;
    /** The ident each connection's server side began with, by connection. */
    final Map<Integer, String> banners = new LinkedHashMap<>();

    private SpyLog(boolean recovered, List<LogConnection> connections, long problems) {
        this.recovered = recovered;
        this.connections = connections;
        this.decodeProblems = problems;
    }

    static SpyLog read(Path file) throws IOException {
        PlayerDecoder decoder = new PlayerDecoder(CodecRegistry.standard());
        try (SpyLogReader r = SpyLogReader.open(file)) {
            List<Msg> msgs = new ArrayList<>();
            long problems = 0;
            Map<Integer, String> banners = new LinkedHashMap<>();
            for (Iterator<LogEntry> it = r.entries(); it.hasNext();) {
                LogEntry e = it.next();
                if (e instanceof LogEntry.Wire w && w.kind() == LogEntry.Kind.BANNER && w.dir() == Direction.SERVER_TO_CLIENT) {
                    banners.put(w.conn(), new String(w.bytes(), java.nio.charset.StandardCharsets.US_ASCII).replace("\0", ""));
                } else if (e instanceof LogEntry.Wire w && w.kind() == LogEntry.Kind.FRAME) {
                    byte[] b = w.bytes();
                    MessageHeader h = MessageHeader.read(b, 0);
                    DecodedMessage d = decoder.decode(h, Arrays.copyOfRange(b, MessageHeader.SIZE, b.length));
                    if (d.hasProblem()) {
                        problems++;
                    }
                    msgs.add(new Msg(w.timeNanos(), w.conn(), w.port(), w.dir(), d));
                }
            }
            SpyLog log = new SpyLog(r.recovered(), r.connections(), problems);
            log.messages.addAll(msgs);
            log.banners.putAll(banners);
            return log;
        }
    }

    List<Msg> of(int conn) {
        return messages.stream().filter(m -> m.conn() == conn).toList();
    }

    /** The poses Player reported on position2d:0 to connection {@code conn}, in order. */
    List<Position2d.State> states(int conn) {
        return of(conn).stream().filter(m -> m.dir() == Direction.SERVER_TO_CLIENT && m.is(POSITION2D, 0, DATA, 1))
                .map(m -> (Position2d.State) m.decoded().body()).toList();
    }

    /** The velocity commands the program sent on position2d:0 over connection {@code conn}. */
    List<Position2d.CmdVel> commands(int conn) {
        return of(conn).stream().filter(m -> m.dir() == Direction.CLIENT_TO_SERVER && m.is(POSITION2D, 0, CMD, 1))
                .map(m -> (Position2d.CmdVel) m.decoded().body()).toList();
    }

    /** Connections by the port the program connected to. */
    Map<Integer, Integer> connByPort() {
        Map<Integer, Integer> m = new LinkedHashMap<>();
        for (LogConnection c : connections) {
            m.put(c.port(), c.conn());
        }
        return m;
    }

    static double distance(Pose2d a, Pose2d b) {
        return Math.hypot(a.px() - b.px(), a.py() - b.py());
    }

    static double angleDiff(double a, double b) {
        return Math.atan2(Math.sin(a - b), Math.cos(a - b));
    }

    static Laser.Scan scan(Msg m) {
        return (Laser.Scan) m.decoded().body();
    }

    static Ranger.Values ranges(Msg m) {
        return (Ranger.Values) m.decoded().body();
    }

    static Ranger.Geom rangerGeom(Msg m) {
        return (Ranger.Geom) m.decoded().body();
    }
}
