package org.stagecraft.player.session;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.stagecraft.player.Streams.concat;
import static org.stagecraft.player.Streams.header;
import static org.stagecraft.player.Streams.message;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.Streams;
import org.stagecraft.player.codec.RawBody;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;

/**
 * The session framer keeps no framer for a direction standing at a message boundary or holding
 * only a partial header (issue 17 item 7: decode of a million never-closed connections), and reports
 * exactly what one framer per direction would, whatever the chunking and the garbage.
 */
class SessionFramerTest {
    private static final byte[] BANNER = Streams.ident("Player v.3.1.1-dev");

    private static byte[] msg(int type, int payload) {
        byte[] body = new byte[payload];
        for (int i = 0; i < payload; i++) {
            body[i] = (byte) (i * 7);
        }
        return message(header(4, 0, type, 1, 12.5), new RawBody(body));
    }

    private static StreamId c2s(int conn) {
        return new StreamId(conn, 6665, Direction.CLIENT_TO_SERVER);
    }

    private static StreamId s2c(int conn) {
        return new StreamId(conn, 6665, Direction.SERVER_TO_CLIENT);
    }

    @Test
    void connectionsBetweenMessagesOrInsideAHeaderHoldNoFramer() {
        List<SessionEvent> events = new ArrayList<>();
        SessionFramer f = new SessionFramer(events::add);
        byte[] request = msg(3, 8);
        for (int conn = 1; conn <= 10_000; conn++) {
            f.chunk(0, s2c(conn), BANNER);
            f.chunk(0, c2s(conn), request);
            f.chunk(0, c2s(conn), java.util.Arrays.copyOf(request, 20)); // half of the next header
        }
        assertEquals(10_000, f.openConnections());
        assertEquals(0, f.activeFramers(), "parked: offsets and 20 held bytes, no framer");
        assertEquals(20_000, events.size());

        f.chunk(0, c2s(7), java.util.Arrays.copyOfRange(request, 20, 40)); // the header completes; its payload is due
        f.chunk(0, s2c(8), msg(1, 100), 0, 60); // 60 unreported bytes, within the header plus 20: parked too
        f.chunk(0, s2c(9), msg(1, 100), 0, 100); // a message under way: its framer stays
        assertEquals(1, f.activeFramers());
        f.close(1, 9);
        assertEquals(0, f.activeFramers());
        WireEvent cut = events.getLast().event();
        assertEquals(9, events.getLast().stream().conn());
        assertEquals(100, cut.bytes().length);
        assertEquals(32, cut.offset(), "offsets are the stream's, whatever framer reported them");

        f.chunk(1, c2s(7), java.util.Arrays.copyOfRange(request, 40, request.length));
        SessionEvent done = events.getLast();
        assertArrayEquals(request, done.event().bytes(), "the held bytes were fed to the new framer first");
        assertEquals(request.length, done.event().offset());
        f.endAll(2);
        assertEquals(0, f.openConnections());
    }

    @Test
    void reportsExactlyWhatOneFramerPerDirectionReports() {
        Random random = new Random(17);
        byte[] garbage = new byte[300];
        random.nextBytes(garbage);
        byte[] client = concat(msg(3, 8), msg(3, 0), garbage, msg(2, 40), java.util.Arrays.copyOf(msg(3, 24), 30));
        byte[] server = concat(BANNER, msg(1, 200), msg(4, 0), garbage, msg(1, 3), java.util.Arrays.copyOf(msg(1, 70), 90));
        for (int round = 0; round < 200; round++) {
            List<SessionEvent> events = new ArrayList<>();
            SessionFramer f = new SessionFramer(events::add);
            int[] at = { 0, 0 };
            byte[][] streams = { client, server };
            StreamId[] ids = { c2s(1), s2c(1) };
            List<List<Integer>> cuts = List.of(new ArrayList<>(), new ArrayList<>());
            while (at[0] < client.length || at[1] < server.length) {
                int s = at[0] >= client.length ? 1 : at[1] >= server.length ? 0 : random.nextInt(2);
                int n = Math.min(streams[s].length - at[s], random.nextBoolean() ? 1 + random.nextInt(6) : 1 + random.nextInt(120));
                f.chunk(0, ids[s], streams[s], at[s], n);
                at[s] += n;
                cuts.get(s).add(at[s]);
            }
            f.close(1, 1);
            for (int s = 0; s < 2; s++) {
                StreamId id = ids[s];
                List<WireEvent> got = events.stream().filter(e -> e.stream().equals(id)).map(SessionEvent::event).toList();
                List<WireEvent> expected = Streams.frame(id.dir(), streams[s], cuts.get(s).stream().mapToInt(Integer::intValue).toArray());
                assertEquals(describe(expected), describe(got), "round " + round + ", " + id);
            }
        }
    }

    private static List<String> describe(List<WireEvent> events) {
        return events.stream().map(e -> e.getClass().getSimpleName() + "@" + e.offset() + "+" + e.bytes().length
                + java.util.Arrays.hashCode(e.bytes()) + (e instanceof WireEvent.Unframed u ? " " + u.reason() : "")).toList();
    }
}
