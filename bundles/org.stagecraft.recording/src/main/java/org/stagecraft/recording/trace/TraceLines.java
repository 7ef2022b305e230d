package org.stagecraft.recording.trace;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

import org.eclipse.jdt.annotation.Nullable;

/**
 * The lines of a JSON-lines file as text, read with bounded memory: a line longer than
 * {@link #MAX_LINE_BYTES} is refused as soon as its first {@code MAX_LINE_BYTES + 1} bytes are in,
 * before it is decoded or parsed (a {@code BufferedReader} would first build the whole line, however
 * long). Each line must be UTF-8 text without control characters (JSON allows none outside strings
 * except tabs, and escapes them inside), so binary input is named as such, with the line and column
 * of the first bad byte, instead of a decoder's "Input length = 1".
 *
 * <p>
 * Lines end with {@code \n} (a {@code \r} before it is dropped). Not thread-safe.
 */
final class TraceLines implements Closeable {
    /**
     * The longest line accepted: a chunk line carries one {@code recv()} in base64, and one whole Player
     * message (at most 8 MiB of payload, 11.2 MB in base64) must fit.
     */
    static final int MAX_LINE_BYTES = 16 << 20;

    private final String name;
    private final InputStream in;
    private final int maxLineBytes;
    private final byte[] chunk = new byte[1 << 16];
    private int chunkPos;
    private int chunkEnd;
    private boolean eof;
    private byte[] line = new byte[1 << 12];
    private long lineNumber;
    private final CharsetDecoder utf8 = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
            .onUnmappableCharacter(CodingErrorAction.REPORT);

    TraceLines(String name, InputStream in) {
        this(name, in, MAX_LINE_BYTES);
    }

    TraceLines(String name, InputStream in, int maxLineBytes) {
        this.name = name;
        this.in = in;
        this.maxLineBytes = maxLineBytes;
    }

    /** 1-based number of the line {@link #next()} returned last. */
    long lineNumber() {
        return lineNumber;
    }

    /** @return the next line without its end, or null at the end of the input */
    @Nullable String next() throws IOException {
        int length = 0;
        boolean any = false;
        while (true) {
            if (chunkPos == chunkEnd) {
                if (eof || !fill()) {
                    if (!any) {
                        return null;
                    }
                    break;
                }
            }
            any = true;
            int nl = indexOfNewline(chunkPos, chunkEnd);
            int end = nl < 0 ? chunkEnd : nl;
            int take = end - chunkPos;
            if (length + take > maxLineBytes) {
                lineNumber++;
                throw new TraceFormatException(name, lineNumber, "line too long (more than "
                        + describe(maxLineBytes) + "; a player-trace line holds one recv() of at most "
                        + describe(MAX_LINE_BYTES) + ")");
            }
            if (length + take > line.length) {
                line = Arrays.copyOf(line, Math.min(maxLineBytes, Math.max(length + take, line.length * 2)));
            }
            System.arraycopy(chunk, chunkPos, line, length, take);
            length += take;
            chunkPos = end;
            if (nl >= 0) {
                chunkPos++; // past the \n
                break;
            }
        }
        lineNumber++;
        if (length > 0 && line[length - 1] == '\r') {
            length--;
        }
        return text(length);
    }

    private boolean fill() throws IOException {
        int n;
        do {
            n = in.read(chunk, 0, chunk.length); // 0 only from a stream that breaks read()'s contract
        } while (n == 0);
        if (n < 0) {
            eof = true;
            return false;
        }
        chunkPos = 0;
        chunkEnd = n;
        return true;
    }

    private int indexOfNewline(int from, int to) {
        for (int i = from; i < to; i++) {
            if (chunk[i] == '\n') {
                return i;
            }
        }
        return -1;
    }

    /** The line as text: ASCII (a trace's usual content) directly, anything else through a strict UTF-8 decoder. */
    private String text(int length) throws TraceFormatException {
        boolean ascii = true;
        int control = -1;
        for (int i = 0; i < length; i++) {
            int b = line[i];
            if (b < 0) {
                ascii = false;
            } else if (b < 0x20 && b != '\t' || b == 0x7f) {
                control = i;
                break;
            }
        }
        int textEnd = control < 0 ? length : control;
        String text;
        if (ascii) {
            text = new String(line, 0, textEnd, StandardCharsets.ISO_8859_1);
        } else { // the first problem in the line is named: a byte that is not UTF-8 before any control byte
            ByteBuffer bytes = ByteBuffer.wrap(line, 0, textEnd);
            CharBuffer chars = CharBuffer.allocate(textEnd);
            utf8.reset();
            CoderResult r = utf8.decode(bytes, chars, true);
            if (r.isError()) {
                int at = bytes.position();
                throw bad(at, "not UTF-8 text (byte 0x" + hex(line[at]) + "); a player-trace is UTF-8 JSON lines");
            }
            utf8.flush(chars);
            chars.flip();
            text = chars.toString();
        }
        if (control >= 0) {
            throw bad(control, "binary data, not text (byte 0x" + hex(line[control]) + ")");
        }
        return text;
    }

    private TraceFormatException bad(int index, String why) {
        return new TraceFormatException(name, lineNumber, "column " + (index + 1) + ": " + why);
    }

    private static String hex(int b) {
        return String.format("%02x", b & 0xff);
    }

    private static String describe(int bytes) {
        return bytes % (1 << 20) == 0 ? (bytes >> 20) + " MiB" : bytes + " bytes";
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
