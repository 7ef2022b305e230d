package org.stagecraft.replay.writelog;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.replay.log.LogMessage;

/**
 * Writes decoded Player messages as a writelog file (file version 0.3.0) that Player's readlog can
 * serve: the data devices published and the geometry and config replies writelog keeps, one line each,
 * in the order given. Numbers are written with every digit they need to read back to the same float
 * or double (readlog reads them with atof, which takes any number of digits), so a re-import gives
 * exactly the values written.
 *
 * <p>What writelog cannot express is skipped and counted by reason: client messages (writelog logs
 * what devices publish), requests, other replies, interfaces without writelog text. Some kinds are
 * written with less than they hold (e.g. a laser geometry keeps x, y, yaw, length and width only);
 * those are counted as approximated. A message written once is not written again when it comes
 * again (same device, timestamp and payload: Player resends unchanged data in PULL mode, and several
 * clients receive the same data), as writelog logs each publication once.
 */
public final class WritelogWriter {
    private static final int RECENT = 32;

    /** What was written and what was not. */
    public record Summary(long written, long approximated, long duplicates, Map<String, Long> skipped) {
        public long skippedTotal() {
            return skipped.values().stream().mapToLong(Long::longValue).sum();
        }
    }

    private record Device(int host, int robot, int interf, int index, int type, int subtype) {
    }

    private record Seen(double timestamp, int hash, int length) {
    }

    private final Writer out;
    private final CodecRegistry registry;
    private final Map<Device, ArrayDeque<Seen>> recent = new HashMap<>();
    private final Map<String, Long> skipped = new TreeMap<>();
    private final StringBuilder line = new StringBuilder(4096);
    private long written;
    private long approximated;
    private long duplicates;

    /**
     * Writes the file's metadata lines.
     *
     * @param playerVersion the recorded Player's version (e.g. from its banner), or null if unknown
     * @param source        what the messages come from, for a comment line
     */
    public WritelogWriter(Writer out, CodecRegistry registry, @Nullable String playerVersion, String source) throws IOException {
        this.out = out;
        this.registry = registry;
        String version = playerVersion == null || playerVersion.isBlank() ? "unknown" : playerVersion.trim();
        out.write("## Player version " + version.replaceAll("\\s+", "_") + " \n");
        out.write("## File version " + WritelogReader.FILE_VERSION + " \n");
        out.write("# Written by Stagecraft from " + oneLine(source) + "\n");
        out.write("# Each line: time host robot interface index type subtype, then the message as Player's"
                + " writelog writes it;\n");
        out.write("# numbers have every digit needed to read back to the recorded values.\n");
    }

    /**
     * Whether a logged message is a reply from Player (RESP_ACK, server to client): what readlog
     * needs on the file's leading lines (see {@code WritelogExport}).
     */
    public static boolean isReply(LogMessage m) {
        return m.kind() == LogMessage.Kind.FRAME && m.decoded() != null && m.dir() == Direction.SERVER_TO_CLIENT
                && m.decoded().header().type() == MessageType.RESP_ACK.code();
    }

    /** Writes a logged message if it is a server-to-client Player message writelog can hold. */
    public boolean write(LogMessage m) throws IOException {
        if (m.kind() != LogMessage.Kind.FRAME || m.decoded() == null) {
            return false; // connection events, banners and bytes that are no message are not messages
        }
        if (m.dir() != Direction.SERVER_TO_CLIENT) {
            skip("messages from clients (writelog logs what devices publish)");
            return false;
        }
        return write(m.decoded().header(), m.decoded().body());
    }

    /** Writes one message if writelog can hold it; else counts why not. */
    public boolean write(MessageHeader h, MessageBody body) throws IOException {
        String iface = registry.interfaceName(h.interf());
        String kind = (iface != null ? iface : "interface " + h.interf()) + " "
                + (h.messageType() != null ? h.messageType().name() : "type " + h.type()) + " "
                + registry.subtypeName(h.interf(), h.type(), h.subtype());
        if (h.type() != MessageType.DATA.code() && h.type() != MessageType.RESP_ACK.code()) {
            skip(kind + ": writelog keeps only data and replies");
            return false;
        }
        PayloadText text = PayloadTexts.of(h.interf());
        if (text == null || iface == null) {
            skip(kind + ": no writelog text for this interface");
            return false;
        }
        String why = text.cannotWrite(h.type(), h.subtype(), body);
        if (why != null) {
            skip(kind + ": " + why);
            return false;
        }
        byte[] payload = PlayerEncoder.encodeBody(body);
        if (seenBefore(h, payload)) {
            duplicates++;
            return false;
        }
        line.setLength(0);
        LineNote note = text.noteFor(body);
        if (note != LineNote.NONE) {
            line.append(note.line());
        }
        line.append(NumberText.float64(h.timestamp())).append(' ').append(Integer.toUnsignedString(h.host()))
                .append(' ').append(Integer.toUnsignedString(h.robot())).append(' ').append(iface).append(' ')
                .append(h.index()).append(' ').append(h.type()).append(' ').append(h.subtype());
        int payloadStart = line.length();
        text.write(h.type(), h.subtype(), body, new TextOut(line));
        if (!readsBackExactly(text, h, payload, line.substring(payloadStart), note)) {
            approximated++;
        }
        line.append('\n');
        out.append(line);
        written++;
        return true;
    }

    public Summary summary() {
        return new Summary(written, approximated, duplicates, Map.copyOf(skipped));
    }

    public void flush() throws IOException {
        out.flush();
    }

    private void skip(String reason) {
        skipped.merge(reason, 1L, Long::sum);
    }

    private boolean seenBefore(MessageHeader h, byte[] payload) {
        Device d = new Device(h.host(), h.robot(), h.interf(), h.index(), h.type(), h.subtype());
        Seen s = new Seen(h.timestamp(), Arrays.hashCode(payload), payload.length);
        ArrayDeque<Seen> q = recent.computeIfAbsent(d, k -> new ArrayDeque<>());
        if (q.contains(s)) {
            return true;
        }
        if (q.size() == RECENT) {
            q.removeFirst();
        }
        q.addLast(s);
        return false;
    }

    private static boolean readsBackExactly(PayloadText text, MessageHeader h, byte[] payload, String written,
            LineNote note) {
        try {
            Tokens in = new Tokens(WritelogReader.split(written), 0);
            MessageBody back = text.read(h.type(), h.subtype(), in, note);
            return in.atEnd() && Arrays.equals(payload, PlayerEncoder.encodeBody(back));
        } catch (WritelogSyntaxException e) {
            throw new IllegalStateException("writelog text written for " + h + " does not read back: " + e.getMessage(), e);
        }
    }

    private static String oneLine(String s) {
        return s == null ? "a session log" : s.replaceAll("[\\r\\n]+", " ");
    }
}
