package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.SpyLogReader;

/** {@code stagecraft spy --break}: held at the first message that satisfies the condition, said, logged, released by a key. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SpyBreakTest {
    @TempDir
    Path tmp;

    /** The offset of the first laser scan nearer than {@code metres} in Player's stream, by the framer and the typed scan. */
    private static long firstScanNearerThan(byte[] s2c, float metres) {
        PlayerDecoder d = new PlayerDecoder(CodecRegistry.standard());
        List<Long> found = new ArrayList<>();
        new PlayerFramer(Direction.SERVER_TO_CLIENT, e -> {
            if (e instanceof WireEvent.Frame f && f.header().type() == 1
                    && d.decode(f.header(), f.payload()).body() instanceof Laser.Scan s) {
                for (float r : s.ranges().toArray()) {
                    if (r < metres) {
                        found.add(f.offset());
                        return;
                    }
                }
            }
        }).accept(s2c);
        assertTrue(!found.isEmpty(), "no scan nearer than " + metres);
        return found.get(0);
    }

    @Test
    void holdsAtTheFirstSatisfyingMessageSaysItLogsItAndAKeyReleases() throws Exception {
        RecordedConnection rc = RecordedConnection.read(TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl")).get(0);
        long expected = firstScanNearerThan(rc.serverBytes(), 1.0f);
        Path log = tmp.resolve("break.mcap");
        PrintedLines err = new PrintedLines();
        CountDownLatch stop = new CountDownLatch(1);
        PipedOutputStream keys = new PipedOutputStream();
        PipedInputStream keysIn = new PipedInputStream(keys);
        try (ExecutorService threads = Executors.newVirtualThreadPerTaskExecutor();
                ServerSocket player = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            Future<ReplayPeer.Result> served = threads.submit(() -> ReplayPeer.serve(player.accept(), rc));
            SpyCommand.Options o = SpyCommand.parse(new String[] { "--listen", "0", "--to", "127.0.0.1:" + player.getLocalPort(),
                    "--log", log.toString(), "--break", "laser:0 min(ranges) < 1.0" });
            Future<Integer> spy = threads.submit(() -> new SpyCommand().serve(o, new PrintStream(err, true, StandardCharsets.UTF_8),
                    stop, false, keysIn));
            int port = Integer.parseInt(err.await(Pattern.compile("spying 127\\.0\\.0\\.1:(\\d+) -> "), 20_000));

            ReplayPeer.Result program = ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), rc);
            assertTrue(program.matches(), "the program's bytes differ at " + program.firstDifference());
            Matcher hit = err.awaitMatch(Pattern.compile("BREAK robot data breakpoint: laser:0 min\\(ranges\\) < 1\\.0 \\(laser:0 min\\(ranges\\) = "
                    + "([0-9.]+) m < 1\\.0\\), connection 1 at byte (\\d+) "), 20_000);
            assertEquals(expected, Long.parseLong(hit.group(2)), err.text());
            assertTrue(Double.parseDouble(hit.group(1)) < 1.0, hit.group());
            err.await(Pattern.compile("(robots held; press Enter)"), 1_000);
            served.get(20, TimeUnit.SECONDS); // Player got the program's requests; its motion commands were held back

            keys.write('\n');
            keys.flush();
            err.await(Pattern.compile("(released: the robots move again)"), 20_000);
            stop.countDown();
            assertEquals(0, spy.get(20, TimeUnit.SECONDS));
            assertTrue(err.text().contains("robot data breakpoint hits"), err.text());
        }
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertArrayEquals(rc.serverBytes(), r.streamBytes(1, Direction.SERVER_TO_CLIENT), "what Player sent, whole");
            List<HoldEntry> holds = r.holdEntries();
            HoldEntry brk = holds.stream().filter(e -> e.action() == HoldEntry.Action.BREAK).findFirst().orElseThrow();
            assertEquals(expected, brk.programOffset());
            assertTrue(brk.text().startsWith("robot data breakpoint: laser:0 min(ranges) < 1.0"), brk.text());
            assertTrue(holds.stream().anyMatch(e -> e.action() == HoldEntry.Action.HOLD_ON && e.text().contains("robot data breakpoint")),
                    holds.toString());
            assertTrue(holds.stream().anyMatch(e -> e.action() == HoldEntry.Action.PASSED_ON && e.programOffset() == expected));
        }
    }

    @Test
    void aBadConditionIsRefusedWithWhereAndWhy() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SpyCommand.parse(new String[] {
                "--listen", "0", "--to", "127.0.0.1:7000", "--break", "laser:0 min(ranges) < 30 deg" }));
        assertTrue(e.getMessage().startsWith("--break at character 23: '30 deg' is an angle, but 'min(ranges)' is a length"),
                e.getMessage());
        assertTrue(e.getMessage().endsWith("laser:0 min(ranges) < 30 deg\n  " + " ".repeat(22) + "^"), e.getMessage());
    }
}
