package org.stagecraft.demo.recorded;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import org.stagecraft.recording.play.RecordedRobot;
import org.stagecraft.recording.play.TimedRecording;

/**
 * The recorded robot program as a program:
 * {@code --connect HOST:PORT --recording FILE [--passes N] [--speed X] [--connect-within SECONDS]}.
 * Passes: 0 (the default) repeats the recorded session until the process is stopped.
 */
public final class RecordedRobotMain {
    private RecordedRobotMain() {
    }

    public static void main(String[] args) throws InterruptedException {
        Options o;
        InetSocketAddress player;
        int passes, within;
        double speed;
        try {
            o = new Options(args, List.of("--connect", "--recording", "--passes", "--speed", "--connect-within"),
                    System.getenv());
            player = address(o.get("--connect", "127.0.0.1:6665"));
            passes = o.integer("--passes", 0);
            within = o.integer("--connect-within", 60);
            speed = o.speed();
            if (!o.positional().isEmpty()) {
                throw new IllegalArgumentException("unexpected " + o.positional());
            }
        } catch (IllegalArgumentException e) {
            System.err.println("recorded robot: " + e.getMessage());
            System.err.println("usage: recorded-robot [--connect HOST:PORT] [--recording FILE] [--passes N] [--speed X]"
                    + " [--connect-within SECONDS]");
            System.exit(2);
            return;
        }
        try {
            TimedRecording recording = TimedRecording.read(o.recording());
            System.out.println(String.format(Locale.ROOT, "recorded robot: replaying the robot program of %s at %sx against %s:%d",
                    recording.file(), speed, player.getHostString(), player.getPort()));
            new RecordedRobot(recording, player, speed, p -> System.out.println("recorded robot: " + p.describe()))
                    .run(passes, Duration.ofSeconds(within));
        } catch (IOException e) {
            System.err.println("recorded robot: " + e.getMessage());
            System.exit(1);
        }
    }

    static InetSocketAddress address(String text) {
        int colon = text.lastIndexOf(':');
        try {
            return new InetSocketAddress(text.substring(0, colon), Integer.parseInt(text.substring(colon + 1)));
        } catch (RuntimeException e) {
            throw new IllegalArgumentException("--connect needs HOST:PORT, not '" + text + "'");
        }
    }
}
