package org.stagecraft.demo.recorded;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;

import org.stagecraft.recording.play.RecordedPlayer;
import org.stagecraft.recording.play.RecordingException;
import org.stagecraft.recording.play.TimedConnection;
import org.stagecraft.recording.play.TimedRecording;
import org.stagecraft.tools.cfg.CfgException;
import org.stagecraft.tools.cfg.PlayerCfg;

/**
 * The recorded Player as a program, run the way Player is run: {@code -p PORT file.cfg}. It listens
 * on every port the cfg's {@code provides} name ({@code -p} for those that name none), which is how a
 * Robot Session starts its "Player" on the rewritten copy, and serves the recording given by
 * {@code --recording FILE} or {@code STAGECRAFT_RECORDING}, in a loop (each connection from the start).
 *
 * <p>Exit codes: 2 for a usage error, 1 when the recording or the cfg cannot be used or a port is
 * taken; otherwise it runs until it is stopped.
 */
public final class RecordedPlayerMain {
    private RecordedPlayerMain() {
    }

    public static void main(String[] args) throws InterruptedException {
        Options o;
        List<Integer> ports;
        Path cfgFile;
        try {
            o = new Options(args, List.of("-p", "--recording", "--speed"), System.getenv());
            if (o.positional().size() != 1) {
                throw new IllegalArgumentException("expected one cfg file");
            }
            cfgFile = Path.of(o.positional().get(0));
            ports = List.copyOf(PlayerCfg.read(cfgFile).listenPorts(o.integer("-p", 6665)).keySet());
        } catch (IllegalArgumentException e) {
            System.err.println("recorded Player: " + e.getMessage());
            System.err.println("usage: recorded-player [-p PORT] [--recording FILE] [--speed X] file.cfg");
            System.exit(2);
            return;
        } catch (CfgException e) {
            System.err.println("recorded Player: " + e.getMessage());
            System.exit(1);
            return;
        }
        TimedRecording recording;
        try {
            recording = TimedRecording.read(o.recording());
        } catch (RecordingException e) {
            System.err.println("recorded Player: " + e.getMessage());
            System.exit(1);
            return;
        }
        RecordedPlayer player = new RecordedPlayer(recording, o.speed(), s -> System.out.println("recorded Player: " + s.describe()));
        try {
            player.start(ports);
        } catch (IOException e) {
            System.err.println("recorded Player: " + e.getMessage());
            System.exit(1);
            return;
        }
        double longest = recording.connections().stream().mapToDouble(TimedConnection::length).max().orElse(0);
        System.out.println(String.format(Locale.ROOT, "recorded Player: serving %s (%d connection(s), %.1f s) at %sx for %s, on %s",
                recording.file(), recording.connections().size(), longest, o.speed(), cfgFile,
                ports.stream().map(p -> "127.0.0.1:" + p).toList()));
        Runtime.getRuntime().addShutdownHook(new Thread(player::close));
        new CountDownLatch(1).await(); // serves until the process is stopped, as Player does
    }
}
