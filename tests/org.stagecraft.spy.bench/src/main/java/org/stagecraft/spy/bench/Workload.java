package org.stagecraft.spy.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.trace.TraceCorpus;

/**
 * The recorded Player sessions the benchmark plays, lengthened so a run lasts long enough to
 * measure: the server's ident banner once, then the rest of each recorded stream {@code repeat}
 * times. The repeated part is whole Player messages, so the result is still a valid session for
 * the spy's framer and decoder (nothing is counted as unframed or undecodable). The warm-up sessions
 * are the recorded ones as they are: enough to compile a relay's code, small enough that a spy has
 * observed all of it before latency is measured.
 */
record Workload(List<RecordedConnection> sessions, List<RecordedConnection> warmUp, byte[] banner, byte[] pingRequest,
        byte[] pingReply) {

    static Workload load(int sessions, int repeat) throws IOException {
        List<RecordedConnection> all = new ArrayList<>();
        for (Path trace : TraceCorpus.all()) {
            all.addAll(RecordedConnection.read(trace));
        }
        List<RecordedConnection> picked = new ArrayList<>();
        List<RecordedConnection> warmUp = new ArrayList<>();
        for (int i = 0; i < sessions; i++) {
            picked.add(lengthen(all.get(i % all.size()), repeat));
            warmUp.add(all.get(i % all.size()));
        }
        RecordedConnection first = all.get(0);
        List<WireEvent> s2c = events(first.serverBytes(), Direction.SERVER_TO_CLIENT);
        List<WireEvent> c2s = events(first.clientBytes(), Direction.CLIENT_TO_SERVER);
        byte[] banner = s2c.get(0).bytes();
        // one real request and the server's first message after the banner: a Player round trip
        return new Workload(picked, warmUp, banner, c2s.get(0).bytes(), s2c.get(1).bytes());
    }

    long bytes() {
        long n = 0;
        for (RecordedConnection c : sessions) {
            n += c.clientBytes().length + c.serverBytes().length;
        }
        return n;
    }

    private static RecordedConnection lengthen(RecordedConnection c, int repeat) {
        byte[] server = c.serverBytes();
        List<byte[]> serverChunks = new ArrayList<>();
        serverChunks.add(java.util.Arrays.copyOf(server, PlayerFramer.IDENT_LENGTH));
        byte[] body = java.util.Arrays.copyOfRange(server, PlayerFramer.IDENT_LENGTH, server.length);
        List<byte[]> clientChunks = new ArrayList<>();
        for (int i = 0; i < repeat; i++) {
            serverChunks.add(body);
            clientChunks.add(c.clientBytes());
        }
        return new RecordedConnection(c.conn(), c.port(), clientChunks, serverChunks);
    }

    private static List<WireEvent> events(byte[] stream, Direction dir) {
        List<WireEvent> out = new ArrayList<>();
        PlayerFramer f = new PlayerFramer(dir, out::add);
        f.accept(stream);
        f.end();
        return out;
    }
}
