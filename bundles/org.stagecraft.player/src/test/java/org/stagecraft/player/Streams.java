package org.stagecraft.player;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;

/** Builds Player byte streams and frames them, for tests. */
public final class Streams {
    private Streams() {
    }

    public static byte[] ident(String text) {
        return Arrays.copyOf(text.getBytes(StandardCharsets.US_ASCII), PlayerFramer.IDENT_LENGTH);
    }

    public static MessageHeader header(int interf, int index, int type, int subtype, double timestamp) {
        return new MessageHeader(0x0100007F, 7665, interf, index, type, subtype, timestamp, 0, 0);
    }

    public static byte[] message(MessageHeader h, MessageBody body) {
        return PlayerEncoder.encode(h, body);
    }

    public static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] p : parts) {
            out.writeBytes(p);
        }
        return out.toByteArray();
    }

    /** Frames a stream fed in pieces whose sizes the splitter chooses; returns all events after end(). */
    public static List<WireEvent> frame(Direction dir, byte[] stream, int[] cuts) {
        List<WireEvent> events = new ArrayList<>();
        PlayerFramer f = new PlayerFramer(dir, events::add);
        int prev = 0;
        for (int c : cuts) {
            f.accept(stream, prev, c - prev);
            prev = c;
        }
        f.accept(stream, prev, stream.length - prev);
        f.end();
        return events;
    }

    public static List<WireEvent> frameWhole(Direction dir, byte[] stream) {
        return frame(dir, stream, new int[0]);
    }

    public static List<WireEvent> frameByteByByte(Direction dir, byte[] stream) {
        int[] cuts = new int[Math.max(0, stream.length - 1)];
        for (int i = 0; i < cuts.length; i++) {
            cuts[i] = i + 1;
        }
        return frame(dir, stream, cuts);
    }

    public static List<WireEvent> frameRandomly(Direction dir, byte[] stream, Random random) {
        List<Integer> cuts = new ArrayList<>();
        int at = 0;
        while (true) {
            at += 1 + random.nextInt(random.nextBoolean() ? 8 : 2000);
            if (at >= stream.length) {
                break;
            }
            cuts.add(at);
        }
        return frame(dir, stream, cuts.stream().mapToInt(Integer::intValue).toArray());
    }

    /** The bytes all events cover, in order: must equal the input for a lossless framer. */
    public static byte[] covered(List<WireEvent> events) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (WireEvent e : events) {
            out.writeBytes(e.bytes());
        }
        return out.toByteArray();
    }

    /** A comparable summary of events: kind, offset and bytes. */
    public static List<String> summary(List<WireEvent> events) {
        List<String> out = new ArrayList<>();
        for (WireEvent e : events) {
            out.add(e.getClass().getSimpleName() + "@" + e.offset() + ":" + Arrays.hashCode(e.bytes()) + "/"
                    + e.bytes().length);
        }
        return out;
    }
}
