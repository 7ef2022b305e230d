package org.stagecraft.replay.writelog;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * Writes a writelog file into a spy log as if a spy had watched Player serve it: one connection per
 * robot (Player port) in the file, opened at its first line's time with client {@code writelog} and
 * listen address {@code writelog:<port>}, a server banner, then every readable line as a
 * server-to-client Player message (header rebuilt from the line, sequence number 0: the file carries
 * none, and Player sends 0 in every recorded trace), and every connection closed at the file's last time.
 */
public final class WritelogImport {
    static final String CLIENT = "writelog";
    private static final int BANNER_SIZE = 32;
    /** What Player puts in a header's seq field (it never counts); a writelog line has no seq to keep. */
    static final int PLAYER_SEQ = 0;

    private WritelogImport() {
    }

    private static final class Connection {
        final int conn;
        final int port;
        long offset;
        long lastNanos = Long.MIN_VALUE;

        Connection(int conn, int port) {
            this.conn = conn;
            this.port = port;
        }
    }

    /** @return what could not be read (empty when every line went in) */
    public static List<LogProblem> convert(Path writelog, SpyLogWriter out) throws IOException {
        Map<Long, Connection> byRobot = new LinkedHashMap<>();
        long endNanos = Long.MIN_VALUE;
        try (WritelogReader reader = new WritelogReader(writelog)) {
            for (WritelogRecord r = reader.next(); r != null; r = reader.next()) {
                long t = WritelogReader.nanos(r.time());
                @Nullable Connection c = byRobot.get(r.robot());
                if (c == null) {
                    c = new Connection(byRobot.size() + 1, (int) r.robot());
                    byRobot.put(r.robot(), c);
                    String listen = "writelog:" + Integer.toUnsignedString(c.port);
                    out.connectionOpened(t, c.conn, CLIENT, listen, writelog.getFileName().toString());
                    byte[] banner = banner(reader.playerVersion());
                    out.wire(t, c.conn, c.port, Direction.SERVER_TO_CLIENT, 0, LogEntry.Kind.BANNER, banner, "");
                    c.offset = banner.length;
                }
                // a spy log's streams run forward in time; a line that goes back in time (readlog
                // just does not wait for it) is logged at its connection's latest time
                c.lastNanos = Math.max(c.lastNanos, t);
                byte[] bytes = PlayerEncoder.encode(r.header(PLAYER_SEQ), r.body());
                out.wire(c.lastNanos, c.conn, c.port, Direction.SERVER_TO_CLIENT, c.offset, LogEntry.Kind.FRAME, bytes, "");
                c.offset += bytes.length;
                endNanos = Math.max(endNanos, c.lastNanos);
            }
            for (Connection c : byRobot.values()) {
                out.connectionClosed(endNanos, c.conn, "end of the writelog file");
            }
            return new ArrayList<>(reader.problems());
        }
    }

    /** A Player ident banner naming the version the file names: "Player v.X.Y.Z", NUL-padded. */
    static byte[] banner(@Nullable String playerVersion) {
        String text = "Player v." + (playerVersion == null ? "unknown" : playerVersion);
        return Arrays.copyOf(text.getBytes(StandardCharsets.ISO_8859_1), BANNER_SIZE);
    }

    /**
     * Whether the start of a file looks like a writelog file: its first line that is not blank or a
     * plain comment is writelog metadata ({@code ##}) or a message line with a known interface name.
     */
    public static boolean looksLikeWritelog(byte[] head) {
        String text = new String(head, StandardCharsets.ISO_8859_1);
        if (text.indexOf('\0') >= 0) {
            return false;
        }
        String[] lines = text.split("\n", -1);
        // the last piece may be cut off by the head's length; judge it only if it is all there is
        int complete = lines.length > 1 ? lines.length - 1 : lines.length;
        for (int i = 0; i < complete; i++) {
            List<String> t = WritelogReader.split(lines[i]);
            if (t.isEmpty() || t.get(0).equals("#")) {
                continue;
            }
            if (t.get(0).equals("##")) {
                return true;
            }
            return t.size() >= WritelogReader.HEADER_VALUES && isNumber(t.get(0))
                    && org.stagecraft.player.codec.CodecRegistry.standard().interfaceCode(t.get(3)) >= 0;
        }
        return false;
    }

    private static boolean isNumber(String s) {
        try {
            NumberText.parseDouble(s);
            return true;
        } catch (NumberFormatException e) {
            return false;
        }
    }
}
