package org.stagecraft.recording.peers;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;

@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ReplayPeerTest {

    @Test
    void connectionsHoldEveryRecordedByteOfTheirStreams() throws Exception {
        Path trace = TraceCorpus.file("pioneer-laser-sonar.sonar.trace.jsonl");
        List<RecordedConnection> conns = RecordedConnection.read(trace);
        assertEquals(2, conns.size(), "the sonar scenario has two clients");
        for (RecordedConnection c : conns) {
            ByteArrayOutputStream c2s = new ByteArrayOutputStream();
            ByteArrayOutputStream s2c = new ByteArrayOutputStream();
            try (TraceReader r = new TraceReader(trace)) {
                for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                    if (rec instanceof TraceRecord.Chunk ch && ch.stream().conn() == c.conn()) {
                        (ch.stream().dir() == Direction.CLIENT_TO_SERVER ? c2s : s2c).writeBytes(ch.data());
                    }
                }
            }
            assertArrayEquals(c2s.toByteArray(), c.clientBytes());
            assertArrayEquals(s2c.toByteArray(), c.serverBytes());
            assertEquals(6665, c.port());
        }
    }

    @Test
    void twoPeersReplayEveryTraceToEachOtherExactly() throws Exception {
        try (ExecutorService pool = Executors.newVirtualThreadPerTaskExecutor()) {
            for (Path trace : TraceCorpus.all()) {
                for (RecordedConnection c : RecordedConnection.read(trace)) {
                    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
                        Future<ReplayPeer.Result> player = pool.submit(() -> ReplayPeer.serve(server.accept(), c));
                        Socket s = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort());
                        ReplayPeer.Result client = ReplayPeer.client(s, c);
                        assertTrue(client.matches(), trace + " conn " + c.conn() + " differs at " + client.firstDifference());
                        assertTrue(player.get(60, TimeUnit.SECONDS).matches(), trace + " conn " + c.conn());
                    }
                }
            }
        }
    }

    @Test
    void aDifferenceIsLocated() {
        ReplayPeer.Result r = new ReplayPeer.Result(new byte[] {1, 2, 9}, new byte[] {1, 2, 3});
        assertFalse(r.matches());
        assertEquals(2, r.firstDifference());
    }
}
