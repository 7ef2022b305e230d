package org.stagecraft.replay.writelog;

import java.io.BufferedReader;
import java.io.Closeable;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.replay.log.LogProblem;

/**
 * Reads a Player writelog file (file version 0.3.0, Player 2 and 3; Player's own or one
 * {@link WritelogWriter} wrote) line by line into {@link WritelogRecord}s. Lines are split on
 * whitespace as readlog splits them; a line whose first value is {@code #} is a comment, one that
 * starts with {@code ##} is metadata (the Player and file version). Every line that cannot be read
 * becomes a {@link LogProblem} naming it, and reading goes on with the next line.
 */
public final class WritelogReader implements Closeable {
    /** The file version of Player 2 and 3, whose header has message type and subtype. */
    public static final String FILE_VERSION = "0.3.0";
    static final int HEADER_VALUES = 7;

    private final String name;
    private final BufferedReader in;
    private final CodecRegistry registry;
    private final List<LogProblem> problems = new ArrayList<>();
    private long line;
    private long lastNanos;
    private @Nullable String playerVersion;
    private @Nullable String fileVersion;
    private boolean stopped;
    private LineNote note = LineNote.NONE;

    public WritelogReader(Path file) throws IOException {
        this(file.toString(), Files.newBufferedReader(file, StandardCharsets.ISO_8859_1));
    }

    public WritelogReader(String name, BufferedReader in) {
        this(name, in, CodecRegistry.standard());
    }

    public WritelogReader(String name, BufferedReader in, CodecRegistry registry) {
        this.name = name;
        this.in = in;
        this.registry = registry;
    }

    /** The next message line, or null at the end of the file. */
    public @Nullable WritelogRecord next() throws IOException {
        while (!stopped) {
            String text = in.readLine();
            if (text == null) {
                return null;
            }
            line++;
            List<String> tokens = split(text);
            if (tokens.isEmpty()) {
                continue;
            }
            if (tokens.get(0).equals("#")) {
                if (tokens.size() > 2 && tokens.get(1).equals(LineNote.PREFIX)) {
                    note = LineNote.of(tokens.get(2));
                }
                continue;
            }
            if (tokens.get(0).equals("##")) {
                metadata(tokens);
                continue;
            }
            LineNote thisLine = note;
            note = LineNote.NONE;
            try {
                WritelogRecord r = record(tokens, thisLine);
                lastNanos = nanos(r.time());
                return r;
            } catch (WritelogSyntaxException e) {
                problems.add(new LogProblem("line " + line, lastNanos, e.getMessage() + "; the line is skipped"));
            }
        }
        return null;
    }

    /** What could not be read so far, one problem per line. */
    public List<LogProblem> problems() {
        return List.copyOf(problems);
    }

    /** The Player version the file names in its metadata, or null. */
    public @Nullable String playerVersion() {
        return playerVersion;
    }

    /** The file version the file names in its metadata, or null. */
    public @Nullable String fileVersion() {
        return fileVersion;
    }

    /** The file's name as given, for messages. */
    public String name() {
        return name;
    }

    static long nanos(double seconds) {
        return Math.round(seconds * 1e9);
    }

    // readlog takes a "##" line of exactly four values as "## <what> version <v>"
    private void metadata(List<String> tokens) {
        if (tokens.size() != 4 || !tokens.get(2).equals("version")) {
            return;
        }
        if (tokens.get(1).equals("Player")) {
            playerVersion = tokens.get(3);
        } else if (tokens.get(1).equals("File")) {
            fileVersion = tokens.get(3);
            if (compareVersions(fileVersion, FILE_VERSION) < 0) {
                problems.add(new LogProblem("line " + line, lastNanos, "file version " + fileVersion
                        + " is Player 1's writelog format (no message type and subtype); only " + FILE_VERSION
                        + " (Player 2 and 3) can be read, so reading stops here"));
                stopped = true;
            }
        }
    }

    private WritelogRecord record(List<String> t, LineNote lineNote) throws WritelogSyntaxException {
        if (t.size() < HEADER_VALUES) {
            throw new WritelogSyntaxException("only " + t.size() + " values; a message line starts with "
                    + "time host robot interface index type subtype");
        }
        double time = number(t.get(0), "time");
        long host = integer(t.get(1), "host");
        long robot = integer(t.get(2), "robot");
        String iface = t.get(3);
        int interf = registry.interfaceCode(iface);
        if (interf < 0) {
            throw new WritelogSyntaxException("unknown interface '" + iface + "'");
        }
        int index = (int) integer(t.get(4), "index");
        int type = (int) integer(t.get(5), "type");
        int subtype = (int) integer(t.get(6), "subtype");
        PayloadText payload = PayloadTexts.of(interf);
        if (payload == null) {
            throw new WritelogSyntaxException(iface + " lines are not read: Stagecraft's codec has no " + iface
                    + " messages");
        }
        Tokens in = new Tokens(unglue(t), HEADER_VALUES);
        MessageBody body;
        try {
            body = payload.read(type, subtype, in, lineNote);
            in.expectEnd();
        } catch (WritelogSyntaxException e) {
            throw new WritelogSyntaxException(iface + " " + type + ":" + subtype + ": " + e.getMessage());
        }
        return new WritelogRecord(line, time, host, robot, iface, interf, index, type, subtype, body);
    }

    private static double number(String s, String what) throws WritelogSyntaxException {
        try {
            return NumberText.parseDouble(s);
        } catch (NumberFormatException e) {
            throw new WritelogSyntaxException(what + " '" + s + "' is not a number");
        }
    }

    private static long integer(String s, String what) throws WritelogSyntaxException {
        try {
            return NumberText.parseInteger(s) & 0xFFFFFFFFL;
        } catch (NumberFormatException e) {
            throw new WritelogSyntaxException(what + " '" + s + "' is not an integer");
        }
    }

    /** Splits on the characters C's isspace() accepts, as readlog does. */
    static List<String> split(String text) {
        List<String> out = new ArrayList<>();
        int start = -1;
        for (int i = 0; i <= text.length(); i++) {
            boolean space = i == text.length() || isSpace(text.charAt(i));
            if (space && start >= 0) {
                out.add(text.substring(start, i));
                start = -1;
            } else if (!space && start < 0) {
                start = i;
            }
        }
        return out;
    }

    private static boolean isSpace(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\u000B' || c == '\f' || c == '\r';
    }

    /**
     * Player's writelog prints two fiducial geometry values with no space between them
     * ("+0.000+0.000"); a sign right after a digit starts a new value.
     */
    private static List<String> unglue(List<String> tokens) {
        List<String> out = new ArrayList<>(tokens.size());
        for (int k = 0; k < tokens.size(); k++) {
            String s = tokens.get(k);
            if (k < HEADER_VALUES) {
                out.add(s);
                continue;
            }
            int from = 0;
            for (int i = 1; i < s.length(); i++) {
                char c = s.charAt(i);
                if ((c == '+' || c == '-') && Character.isDigit(s.charAt(i - 1))) {
                    out.add(s.substring(from, i));
                    from = i;
                }
            }
            out.add(s.substring(from));
        }
        return out;
    }

    static int compareVersions(String a, String b) {
        String[] x = a.split("\\.");
        String[] y = b.split("\\.");
        for (int i = 0; i < Math.max(x.length, y.length); i++) {
            int p = i < x.length ? parsePart(x[i]) : 0;
            int q = i < y.length ? parsePart(y[i]) : 0;
            if (p != q) {
                return Integer.compare(p, q);
            }
        }
        return 0;
    }

    private static int parsePart(String s) {
        int end = 0;
        while (end < s.length() && Character.isDigit(s.charAt(end))) {
            end++;
        }
        return end == 0 ? 0 : Integer.parseInt(s.substring(0, Math.min(end, 9)));
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
