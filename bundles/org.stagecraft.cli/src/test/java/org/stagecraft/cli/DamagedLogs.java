package org.stagecraft.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import org.stagecraft.recording.trace.TraceFraming;
import org.stagecraft.spy.log.SpyLogWriter;

/** Spy logs made from a trace the spy's way, and the damage a crash, a full disk or a bad disk does to them. */
final class DamagedLogs {
    private DamagedLogs() {
    }

    /** Every framed event of the trace, stamped with its receive time, in chunks of {@code chunkSize} bytes. */
    static Path logOf(Path trace, Path log, int chunkSize) throws IOException {
        try (SpyLogWriter w = SpyLogWriter.create(FileChannel.open(log, StandardOpenOption.CREATE,
                StandardOpenOption.TRUNCATE_EXISTING, StandardOpenOption.WRITE), Map.of(), chunkSize)) {
            TraceFraming.frame(trace, e -> {
                try {
                    w.wire(Math.round(e.t() * 1e9), e.stream().conn(), e.stream().port(), e.stream().dir(), e.event());
                } catch (IOException ex) {
                    throw new UncheckedIOException(ex);
                }
            });
        }
        return log;
    }

    /** File offsets of the chunk records, walking the records from the start (MCAP: opcode u8, length u64 LE). */
    static List<Long> chunkOffsets(byte[] file) {
        List<Long> out = new ArrayList<>();
        int p = 8;
        while (p + 9 <= file.length) {
            int op = file[p] & 0xff;
            long len = ByteBuffer.wrap(file, p + 1, 8).order(ByteOrder.LITTLE_ENDIAN).getLong();
            if (op == 0x06) {
                out.add((long) p);
            }
            if (op == 0x0F) {
                break; // data end: the summary follows
            }
            p += 9 + (int) len;
        }
        return out;
    }

    /** Zeroes 64 bytes in the middle of chunk {@code n}'s compressed records (its CRC fails). */
    static byte[] damageChunk(byte[] file, int n) {
        byte[] b = file.clone();
        List<Long> chunks = chunkOffsets(file);
        long at = chunks.get(n);
        long end = n + 1 < chunks.size() ? chunks.get(n + 1) : at + 200;
        Arrays.fill(b, (int) (at + (end - at) / 2), (int) (at + (end - at) / 2) + 64, (byte) 0);
        return b;
    }

    /** Flips a bit of chunk {@code n}'s record length: the records after it no longer line up. */
    static byte[] damageChunkLength(byte[] file, int n) {
        byte[] b = file.clone();
        b[(int) (chunkOffsets(file).get(n) + 1)] ^= 0x40;
        return b;
    }

    /** The file without its footer and closing magic, as a crash after the last chunk leaves it. */
    static byte[] withoutFooter(byte[] file) {
        return Arrays.copyOf(file, file.length - (9 + 20 + 8));
    }

    /** Messages lost, as the commands count them on stderr ("...; 312 messages lost"). */
    static long messagesLost(String err) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("; (\\d+) messages? lost").matcher(err);
        long n = 0;
        while (m.find()) {
            n += Long.parseLong(m.group(1));
        }
        return n;
    }
}
