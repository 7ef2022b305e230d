package org.stagecraft.spy.hold;

import java.io.IOException;
import java.io.OutputStream;

import org.eclipse.jdt.annotation.Nullable;

/**
 * Writes the parts of one relayed chunk that go on, in order: adjacent spans of the chunk are written
 * together (one write per read, as the plain relay does), and a whole message of the spy's own, or bytes it
 * kept back, is written between them after what came before it. Counts every byte written, which is where
 * the next byte lands in the stream the other side receives. Used by one relay thread (its owner's lock).
 */
public final class SpanWriter {
    private final OutputStream out;
    private byte @Nullable [] chunk;
    private int start;
    private int length;
    private long written;

    public SpanWriter(OutputStream out) {
        this.out = out;
    }

    /** A chunk begins: spans given to {@link #later} are in {@code buf}. */
    public void begin(byte[] buf, int off) {
        chunk = buf;
        start = off;
        length = 0;
    }

    /** The chunk's bytes [pos, pos + n) go on, with the spans next to them. */
    public void later(int pos, int n) throws IOException {
        if (length > 0 && start + length != pos) {
            flush();
        }
        if (length == 0) {
            start = pos;
        }
        length += n;
    }

    /** Writes the spans given so far. */
    public void flush() throws IOException {
        byte[] b = chunk;
        if (b != null && length > 0) {
            out.write(b, start, length);
            written += length;
            start += length;
            length = 0;
        }
    }

    /** Writes {@code bytes} after the spans given so far. */
    public void write(byte[] bytes) throws IOException {
        write(bytes, bytes.length);
    }

    /** Writes the first {@code n} of {@code bytes} after the spans given so far. */
    public void write(byte[] bytes, int n) throws IOException {
        flush();
        out.write(bytes, 0, n);
        written += n;
    }

    /** The chunk is done (its spans were flushed): forget it. */
    public void end() {
        chunk = null;
        length = 0;
    }

    /** Bytes written so far: the offset of the next byte in the stream the other side receives. */
    public long written() {
        return written;
    }
}
