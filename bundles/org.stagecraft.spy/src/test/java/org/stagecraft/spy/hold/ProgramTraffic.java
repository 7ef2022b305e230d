package org.stagecraft.spy.hold;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;

/** A recorded robot program's stream to Player, and the tests' own framing of streams into messages. */
final class ProgramTraffic {
    /** A recorded Pioneer session: 288 position2d CMD_VELs between data requests. */
    static final String TRACE = "pioneer-laser-sonar.gt.trace.jsonl";

    record Msg(int offset, MessageHeader header, int length) {
        int end() {
            return offset + length;
        }

        boolean motion() {
            return header.interf() == 4 && header.type() == 2;
        }
    }

    private ProgramTraffic() {
    }

    /** The client-to-server bytes of the trace's first connection, exactly as recorded. */
    static byte[] program() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (TraceReader r = new TraceReader(TraceCorpus.file(TRACE))) {
            for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                if (rec instanceof TraceRecord.Chunk c && c.stream().conn() == 1
                        && c.stream().dir() == Direction.CLIENT_TO_SERVER) {
                    out.write(c.data());
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }

    /**
     * Frames a stream into whole Player messages.
     *
     * @throws AssertionError if a header is not a Player header or the stream ends inside a message
     */
    static List<Msg> frame(byte[] s) {
        List<Msg> out = new ArrayList<>();
        int p = 0;
        while (p < s.length) {
            if (s.length - p < MessageHeader.SIZE) {
                throw new AssertionError("stream ends inside a header at " + p);
            }
            MessageHeader h = MessageHeader.read(s, p);
            if (h.problem() != null) {
                throw new AssertionError("no message boundary at " + p + ": " + h.problem());
            }
            int len = MessageHeader.SIZE + h.size();
            if (p + len > s.length) {
                throw new AssertionError("stream ends inside a message at " + p);
            }
            out.add(new Msg(p, h, len));
            p += len;
        }
        return out;
    }

    /** The velocities of a CMD_VEL message. */
    static double[] vel(byte[] message) {
        XdrReader r = new XdrReader(message, MessageHeader.SIZE, message.length - MessageHeader.SIZE);
        return new double[] { r.float64(), r.float64(), r.float64() };
    }
}
