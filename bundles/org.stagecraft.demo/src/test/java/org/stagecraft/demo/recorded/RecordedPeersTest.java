package org.stagecraft.demo.recorded;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.recording.play.RecordedPlayer;
import org.stagecraft.recording.play.RecordedRobot;
import org.stagecraft.recording.play.TimedChunk;
import org.stagecraft.recording.play.TimedConnection;
import org.stagecraft.recording.play.TimedRecording;
import org.stagecraft.tools.session.Ports;

/** The recorded Player and robot program against each other and against a plain socket, on loopback. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RecordedPeersTest {
    private final TimedRecording recording;
    private final TimedConnection conn;
    private final BlockingQueue<RecordedPlayer.Served> served = new LinkedBlockingQueue<>();

    RecordedPeersTest() throws Exception {
        recording = TimedRecording.read(DemoFiles.recording());
        conn = recording.connections().get(0);
    }

    private RecordedPlayer player(double speed) throws IOException {
        RecordedPlayer p = new RecordedPlayer(recording, speed, served::add);
        p.start(List.of(0));
        return p;
    }

    private RecordedPlayer.Served nextServed() throws InterruptedException {
        RecordedPlayer.Served s = served.poll(30, TimeUnit.SECONDS);
        assertNotNull(s, "the recorded Player reported the connection it served");
        return s;
    }

    @Test
    void robotAndPlayerExchangeTheRecordedBytesAtTheRecordedPace() throws Exception {
        double speed = 8;
        try (RecordedPlayer player = player(speed)) {
            List<RecordedRobot.Pass> passes = new ArrayList<>();
            long start = System.nanoTime();
            new RecordedRobot(recording, new InetSocketAddress(InetAddress.getLoopbackAddress(), player.ports().get(0)), speed,
                    passes::add).run(1, Duration.ofSeconds(5));
            double took = (System.nanoTime() - start) / 1e9;
            assertEquals(1, passes.size());
            RecordedRobot.Pass pass = passes.get(0);
            assertNull(pass.error());
            assertTrue(pass.result().matches(), pass.describe());
            assertEquals(conn.serverBytes().length, pass.result().received());
            assertEquals(conn.clientBytes().length, pass.result().sent());
            double paced = conn.length() / speed;
            assertTrue(took >= paced - 0.01 && took < paced + 3, "a pass takes the recorded " + paced + " s at " + speed
                    + "x, took " + took);
            RecordedPlayer.Served s = nextServed();
            assertNull(s.error());
            assertTrue(s.result().matches(), s.describe());
            assertEquals(conn.serverBytes().length, s.result().sent());
        }
    }

    @Test
    void playerDataArrivesNoEarlierThanRecorded() throws Exception {
        double speed = 4;
        try (RecordedPlayer player = player(speed)) {
            // before connecting: the recorded Player's clock starts when it accepts, which may be before connect returns
            long start = System.nanoTime();
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), player.ports().get(0))) {
                // the first chunks recorded at or after 2, 8 and 20 s, and how many bytes come before each
                double[] marks = {2, 8, 20};
                long[] before = new long[marks.length];
                double[] due = new double[marks.length];
                for (int m = 0; m < marks.length; m++) {
                    long bytes = 0;
                    for (TimedChunk c : conn.server()) {
                        if (c.offset() >= marks[m]) {
                            due[m] = c.offset() / speed;
                            break;
                        }
                        bytes += c.data().length;
                    }
                    before[m] = bytes;
                }
                InputStream in = s.getInputStream();
                byte[] buffer = new byte[65536];
                long received = 0;
                int m = 0;
                while (m < marks.length) {
                    int n = in.read(buffer);
                    assertTrue(n > 0, "the recorded Player is still sending");
                    received += n;
                    double at = (System.nanoTime() - start) / 1e9;
                    while (m < marks.length && received > before[m]) {
                        assertTrue(at >= due[m] - 0.005, "the chunk recorded at " + due[m] * speed + " s came at " + at * speed
                                + " s (recorded time)");
                        assertTrue(at < due[m] + 1, "the chunk recorded at " + due[m] * speed + " s was late: " + at * speed);
                        m++;
                    }
                }
            }
        }
    }

    @Test
    void eachPassIsANewConnectionServedFromTheStart() throws Exception {
        double speed = 16;
        try (RecordedPlayer player = player(speed)) {
            List<RecordedRobot.Pass> passes = new ArrayList<>();
            new RecordedRobot(recording, new InetSocketAddress(InetAddress.getLoopbackAddress(), player.ports().get(0)), speed,
                    passes::add).run(2, Duration.ofSeconds(5));
            assertEquals(List.of(1, 2), passes.stream().map(RecordedRobot.Pass::number).toList());
            assertTrue(passes.stream().allMatch(p -> p.result() != null && p.result().matches()), passes.toString());
            assertTrue(nextServed().result().matches());
            assertTrue(nextServed().result().matches());
        }
    }

    @Test
    void aClientThatBreaksOffSaysWhereItLeftTheRecording() throws Exception {
        try (RecordedPlayer player = player(16)) {
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), player.ports().get(0))) {
                byte[] other = conn.clientBytes().clone();
                other[5] ^= 0x55; // another program: the same start, then something else
                s.getInputStream().readNBytes(32); // the banner
                s.getOutputStream().write(other, 0, 40);
            } // and it goes away while the recorded Player still has data to send
            RecordedPlayer.Served served = nextServed();
            assertNotNull(served.error(), served.describe());
            assertTrue(served.describe().contains("ended early: ") && served.describe().endsWith(
                    "(after receiving 40 bytes, which differ from the recording from byte 5)"), served.describe());
        }
    }

    @Test
    void aRobotWithNothingToTalkToGivesUpAfterItsDeadline() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        RecordedRobot robot = new RecordedRobot(recording, new InetSocketAddress("127.0.0.1", port), 1, p -> {
        });
        IOException e = assertThrows(IOException.class, () -> robot.run(1, Duration.ofMillis(300)));
        assertEquals("nothing accepted a connection on 127.0.0.1:" + port + " in time (is Player running?)", e.getMessage());
    }

    @Test
    void aPortInUseIsNamedAndNothingStaysBound() throws Exception {
        try (RecordedPlayer first = player(1)) {
            int taken = first.ports().get(0);
            int free = Ports.free("127.0.0.1", 1).get(0);
            RecordedPlayer second = new RecordedPlayer(recording, 1, served::add);
            IOException e = assertThrows(IOException.class, () -> second.start(List.of(free, taken)));
            assertTrue(e.getMessage().startsWith("cannot listen on port " + taken + ": "), e.getMessage());
            assertTrue(Ports.isFree("127.0.0.1", free), "the port it could bind was released");
        }
    }
}
