package org.stagecraft.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.wire.WireEvent;

/** {@code stagecraft stats FILE}: message counts and bytes per direction, interface, type, subtype. */
final class StatsCommand {

    private record Key(String dir, String iface, String type, String subtype) implements Comparable<Key> {
        @Override
        public int compareTo(Key o) {
            return toString().compareTo(o.toString());
        }
    }

    private static final class Tally {
        long messages;
        long bytes;
    }

    int run(String[] args, PrintStream out, PrintStream err) {
        if (args.length != 1) {
            err.println("usage: stagecraft stats FILE");
            return ExitCode.USAGE;
        }
        Path file = InputFile.readable("stats", args[0], err);
        if (file == null) {
            return ExitCode.FAILED;
        }
        CodecRegistry registry = CodecRegistry.standard();
        PlayerDecoder decoder = new PlayerDecoder(registry);
        Map<Key, Tally> counts = new TreeMap<>();
        long[] totals = new long[5]; // messages, bytes, banners, unframed bytes, decode problems
        LogRecovery recovery;
        try {
            recovery = Recordings.frame(file, (SessionEvent e) -> {
                switch (e.event()) {
                    case WireEvent.Banner b -> totals[2]++;
                    case WireEvent.Unframed u -> totals[3] += u.length();
                    case WireEvent.Frame f -> {
                        MessageHeader h = f.header();
                        String iface = registry.interfaceName(h.interf());
                        MessageType type = h.messageType();
                        Key k = new Key(e.stream().dir().label(), iface != null ? iface : "interface-" + h.interf(),
                                type.name(), registry.subtypeName(h.interf(), h.type(), h.subtype()));
                        Tally t = counts.computeIfAbsent(k, x -> new Tally());
                        t.messages++;
                        t.bytes += f.wireSize();
                        totals[0]++;
                        totals[1] += f.wireSize();
                        DecodedMessage m = decoder.decode(f);
                        if (m.hasProblem()) {
                            totals[4]++;
                        }
                    }
                }
            });
        } catch (IOException e) {
            err.println("stagecraft stats: " + e.getMessage());
            return ExitCode.FAILED;
        } catch (RuntimeException | OutOfMemoryError e) {
            err.println("stagecraft stats: " + CommandFailure.describe(file, e));
            return ExitCode.FAILED;
        }
        if (recovery.nothingRead()) {
            return recovery.report("stats", file, err); // no table of zeros for a file nothing could be read from
        }
        out.printf("%-4s %-12s %-10s %-18s %10s %12s%n", "dir", "interface", "type", "subtype", "messages", "bytes");
        for (Map.Entry<Key, Tally> en : counts.entrySet()) {
            Key k = en.getKey();
            out.printf("%-4s %-12s %-10s %-18s %10d %12d%n", k.dir(), k.iface(), k.type(), k.subtype(),
                    en.getValue().messages, en.getValue().bytes);
        }
        out.printf("total: %d messages, %d bytes, %d banners, %d unframed bytes, %d decode errors%n", totals[0],
                totals[1], totals[2], totals[3], totals[4]);
        return recovery.report("stats", file, err);
    }
}
