package org.stagecraft.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;

import org.stagecraft.recording.play.PlayableConnection;
import org.stagecraft.recording.play.RecordedPlayer;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;

/**
 * {@code stagecraft replay FILE --to [PORT=]HOST:PORT [...] [--speed X] [--loop]}: stands in for the
 * recorded Player. For each recorded Player port (in the order the log met them, or as mapped with
 * {@code PORT=}) it listens on the given address and serves each client that connects the recorded
 * banner and server-to-client stream of a connection recorded on that port, at the recorded pace
 * scaled by the speed. What the client sends is read and compared with what the recorded client sent;
 * a difference is a warning, the replay goes on. Without {@code --loop} it ends when every recorded
 * connection has been served once.
 */
final class ReplayCommand {
    static final String USAGE = "usage: stagecraft replay FILE --to [PORT=]HOST:PORT [--to ...] [--speed X] [--loop]";

    int run(String[] args, PrintStream out, PrintStream err) {
        String file = null;
        List<String> targets = new ArrayList<>();
        double speed = 1;
        boolean loop = false;
        try {
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                switch (a) {
                    case "--to" -> {
                        if (++i >= args.length) {
                            throw new IllegalArgumentException("--to needs [PORT=]HOST:PORT");
                        }
                        targets.add(args[i]);
                    }
                    case "--speed" -> {
                        if (++i >= args.length) {
                            throw new IllegalArgumentException("--speed needs a number");
                        }
                        speed = speed(args[i]);
                    }
                    case "--loop" -> loop = true;
                    default -> {
                        if (a.startsWith("--") || file != null) {
                            throw new IllegalArgumentException("unexpected argument '" + a + "'");
                        }
                        file = a;
                    }
                }
            }
            if (file == null) {
                throw new IllegalArgumentException("no FILE given");
            }
            if (targets.isEmpty()) {
                throw new IllegalArgumentException("no --to given: where should the recorded Player listen?");
            }
        } catch (IllegalArgumentException e) {
            err.println("stagecraft replay: " + e.getMessage());
            err.println(USAGE);
            return ExitCode.USAGE;
        }
        Path input = InputFile.readable("replay", file, err);
        if (input == null) {
            return ExitCode.FAILED;
        }
        // the log stays open while serving: each served connection streams from it
        try (SessionLog log = SessionLogs.open(input)) {
            List<RecordedServerStreams.LogConnection> recorded = RecordedServerStreams.read(log);
            // said before serving: reading the recorded streams has met whatever damage the log has
            int losses = LogLosses.report("replay", log, err);
            if (recorded.isEmpty()) {
                err.println("stagecraft replay: " + input + ": no connection in which the Player server sent anything");
                return ExitCode.FAILED;
            }
            int served = serve(recorded, targets, speed, loop, out, err);
            return served == ExitCode.DONE ? losses : served;
        } catch (IOException e) {
            err.println("stagecraft replay: " + e.getMessage());
            return ExitCode.FAILED;
        } catch (RuntimeException | OutOfMemoryError e) {
            err.println("stagecraft replay: " + CommandFailure.describe(input, e));
            return ExitCode.FAILED;
        }
    }

    private static int serve(List<? extends PlayableConnection> recorded, List<String> targets, double speed, boolean loop,
            PrintStream out, PrintStream err) {
        Map<Integer, List<PlayableConnection>> byPort = new LinkedHashMap<>();
        for (PlayableConnection c : recorded) {
            byPort.computeIfAbsent(c.port(), k -> new ArrayList<>()).add(c);
        }
        List<RecordedPlayer.Listener> listeners;
        try {
            listeners = listeners(targets, byPort);
        } catch (IllegalArgumentException | UnknownHostException e) {
            err.println("stagecraft replay: " + e.getMessage());
            return ExitCode.USAGE;
        }
        int toServe = listeners.stream().mapToInt(l -> l.connections().size()).sum();
        CountDownLatch served = new CountDownLatch(toServe);
        RecordedPlayer player = new RecordedPlayer(speed, s -> {
            if (s.error() != null || !s.result().matches()) {
                err.println("stagecraft replay: warning: " + s.describe());
            } else {
                out.println("stagecraft replay: " + s.describe());
            }
            served.countDown();
        });
        try (player) {
            player.start(listeners);
            List<Integer> bound = player.ports();
            for (int i = 0; i < listeners.size(); i++) {
                RecordedPlayer.Listener l = listeners.get(i);
                out.println("stagecraft replay: recorded port " + l.connections().get(0).port() + " (" + l.connections().size()
                        + " connection" + (l.connections().size() == 1 ? "" : "s") + ") listening on "
                        + l.address().getHostString() + ":" + bound.get(i));
            }
            out.flush();
            if (loop) {
                new CountDownLatch(1).await(); // until the process is stopped
            } else {
                served.await();
            }
            return ExitCode.DONE;
        } catch (IOException e) {
            err.println("stagecraft replay: " + e.getMessage());
            return ExitCode.FAILED;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return ExitCode.FAILED;
        }
    }

    /** {@code HOST:PORT} in the order of the recorded ports, or {@code PORT=HOST:PORT} for a given one. */
    static List<RecordedPlayer.Listener> listeners(List<String> targets, Map<Integer, ? extends List<? extends PlayableConnection>> byPort)
            throws UnknownHostException {
        List<Integer> ports = new ArrayList<>(byPort.keySet());
        List<RecordedPlayer.Listener> out = new ArrayList<>();
        int nextInOrder = 0;
        for (String t : targets) {
            int eq = t.indexOf('=');
            int recordedPort;
            if (eq >= 0) {
                recordedPort = port(t.substring(0, eq), t);
                if (!byPort.containsKey(recordedPort)) {
                    throw new IllegalArgumentException("--to " + t + ": the log has no connection to port " + recordedPort
                            + " (its ports: " + ports + ")");
                }
            } else {
                if (nextInOrder >= ports.size()) {
                    throw new IllegalArgumentException("--to " + t + ": the log has only " + ports.size()
                            + " Player port" + (ports.size() == 1 ? "" : "s") + " " + ports);
                }
                recordedPort = ports.get(nextInOrder++);
            }
            String address = eq >= 0 ? t.substring(eq + 1) : t;
            int colon = address.lastIndexOf(':');
            String host = colon > 0 ? address.substring(0, colon) : null;
            int listenPort = port(colon >= 0 ? address.substring(colon + 1) : address, t);
            InetAddress bind = host == null ? InetAddress.getLoopbackAddress() : InetAddress.getByName(host);
            for (RecordedPlayer.Listener l : out) {
                if (l.connections().get(0).port() == recordedPort) {
                    throw new IllegalArgumentException("--to " + t + ": recorded port " + recordedPort + " is given twice");
                }
            }
            out.add(new RecordedPlayer.Listener(new InetSocketAddress(bind, listenPort), byPort.get(recordedPort)));
        }
        return out;
    }

    private static int port(String text, String target) {
        try {
            int p = Integer.parseInt(text);
            if (p < 0 || p > 65535) {
                throw new NumberFormatException();
            }
            return p;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--to " + target + ": '" + text + "' is not a port number");
        }
    }

    private static double speed(String text) {
        try {
            double v = Double.parseDouble(text);
            if (!(v > 0) || Double.isInfinite(v)) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--speed needs a positive number, not '" + text + "'");
        }
    }
}
