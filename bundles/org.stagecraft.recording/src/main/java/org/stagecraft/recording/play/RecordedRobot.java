package org.stagecraft.recording.play;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.time.Duration;
import java.util.function.Consumer;

import org.eclipse.jdt.annotation.Nullable;

/**
 * Stands in for a robot program with a recording: connects to Player's port, sends what the
 * recorded client sent, each chunk at its recorded moment (subscriptions, geometry requests, data
 * requests, velocity commands), and reads what comes back, comparing it with what the recorded
 * Player sent. Each pass is a new connection, as when a program is run again.
 *
 * <p>It may be started before anything listens (a Robot Session starts helper tools before Player
 * and the spy), so the first connection is retried until a deadline, as robot programs that wait for
 * Player do.
 */
public final class RecordedRobot {
    /** One pass over a recorded connection, reported when it ended. */
    public record Pass(int number, int recordedConn, @Nullable ExchangeResult result, @Nullable String error) {
        public String describe() {
            return "pass " + number + " (recorded connection " + recordedConn + "): "
                    + (error != null ? "ended early: " + error : result.describe("Player"));
        }
    }

    /** How long to wait between attempts to reach a port that does not listen yet. */
    private static final Duration RETRY = Duration.ofMillis(100);

    private final TimedRecording recording;
    private final InetSocketAddress player;
    private final double speed;
    private final Consumer<Pass> report;

    public RecordedRobot(TimedRecording recording, InetSocketAddress player, double speed, Consumer<Pass> report) {
        this.recording = recording;
        this.player = player;
        this.speed = speed;
        this.report = report;
    }

    /**
     * Plays {@code passes} passes (0: until interrupted).
     *
     * @param connectWithin how long the first connection may be retried while nothing listens
     * @throws IOException when the first connection cannot be made in time
     */
    public void run(int passes, Duration connectWithin) throws IOException, InterruptedException {
        Socket first = connect(System.nanoTime() + connectWithin.toNanos());
        for (int n = 1; passes == 0 || n <= passes; n++) {
            TimedConnection conn = recording.connections().get((n - 1) % recording.connections().size());
            Socket socket = n == 1 ? first : connect(System.nanoTime() + connectWithin.toNanos());
            try (ChunkSource send = conn.openClient(); ChunkSource expected = conn.openServer()) {
                ExchangeResult r = Exchange.play(socket, send, expected, conn.length(), speed);
                report.accept(new Pass(n, conn.conn(), r, null));
            } catch (IOException e) {
                report.accept(new Pass(n, conn.conn(), null, e.getMessage()));
            }
            if (Thread.currentThread().isInterrupted()) {
                throw new InterruptedException("stopped after pass " + n);
            }
        }
    }

    private Socket connect(long deadline) throws IOException, InterruptedException {
        while (true) {
            Socket s = new Socket();
            try {
                s.connect(player, 5000);
                return s;
            } catch (ConnectException e) {
                s.close();
                if (System.nanoTime() > deadline) {
                    throw new IOException("nothing accepted a connection on " + player.getHostString() + ":"
                            + player.getPort() + " in time (is Player running?)", e);
                }
                // a retry interval, not synchronisation: nothing tells a client when a port opens
                Thread.sleep(RETRY);
            }
        }
    }
}
