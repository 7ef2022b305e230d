package org.stagecraft.player.wire;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.stagecraft.player.Streams.concat;
import static org.stagecraft.player.Streams.covered;
import static org.stagecraft.player.Streams.header;
import static org.stagecraft.player.Streams.message;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.Streams;
import org.stagecraft.player.codec.EmptyBody;
import org.stagecraft.player.codec.RawBody;
import org.stagecraft.player.xdr.XdrWriter;

class PlayerFramerTest {

    private static final byte[] BANNER = Streams.ident("Player v.3.1.1-dev");
    private static final byte[] ACK = message(header(1, 0, 4, 5, 0.6), EmptyBody.INSTANCE);
    private static final byte[] STATE = message(header(4, 0, 1, 1, 0.9), new RawBody(new byte[52]));
    private static final byte[] BIG = message(header(6, 0, 1, 1, 1.0), new RawBody(new byte[5000]));

    private static byte[] serverStream() {
        return concat(BANNER, ACK, STATE, BIG, ACK, STATE);
    }

    @Test
    void framesBannerAndMessagesOfTheServerStream() {
        List<WireEvent> events = Streams.frameWhole(Direction.SERVER_TO_CLIENT, serverStream());
        assertEquals(6, events.size());
        WireEvent.Banner b = assertInstanceOf(WireEvent.Banner.class, events.get(0));
        assertEquals("Player v.3.1.1-dev", b.ident());
        WireEvent.Frame big = assertInstanceOf(WireEvent.Frame.class, events.get(3));
        assertEquals(5000, big.header().size());
        assertEquals(32 + 40 + 92, big.offset());
        assertEquals(6, big.header().interf());
    }

    @Test
    void clientStreamHasNoBanner() {
        List<WireEvent> events = Streams.frameWhole(Direction.CLIENT_TO_SERVER, concat(ACK, STATE));
        assertEquals(2, events.size());
        assertInstanceOf(WireEvent.Frame.class, events.get(0));
    }

    @Test
    void anyChunkingGivesTheSameEvents() {
        byte[] stream = serverStream();
        List<String> whole = Streams.summary(Streams.frameWhole(Direction.SERVER_TO_CLIENT, stream));
        assertEquals(whole, Streams.summary(Streams.frameByteByByte(Direction.SERVER_TO_CLIENT, stream)));
        Random random = new Random(42);
        for (int i = 0; i < 50; i++) {
            assertEquals(whole, Streams.summary(Streams.frameRandomly(Direction.SERVER_TO_CLIENT, stream, random)));
        }
    }

    @Test
    void aCorruptHeaderIsSkippedReportedAndFramingResumes() {
        byte[] bad = ACK.clone();
        bad[19] = 9; // message type 9
        byte[] stream = concat(BANNER, ACK, bad, STATE, ACK);
        List<WireEvent> events = Streams.frameWhole(Direction.SERVER_TO_CLIENT, stream);
        WireEvent.Unframed u = assertInstanceOf(WireEvent.Unframed.class, events.get(2));
        assertEquals(32 + 40, u.offset());
        assertTrue(u.reason().contains("message type 9"), u.reason());
        assertTrue(u.reason().contains("offset 72"), u.reason());
        assertEquals(40, u.length(), "exactly the corrupt header is skipped");
        assertInstanceOf(WireEvent.Frame.class, events.get(3));
        assertEquals(5, events.size());
        assertArrayEquals(stream, covered(events));
    }

    @Test
    void anOversizePayloadIsRefusedWithoutBufferingIt() {
        byte[] huge = ACK.clone();
        huge[36] = 0x7F; // size 0x7F000000
        byte[] stream = concat(BANNER, huge, STATE);
        List<WireEvent> events = Streams.frameWhole(Direction.SERVER_TO_CLIENT, stream);
        WireEvent.Unframed u = assertInstanceOf(WireEvent.Unframed.class, events.get(1));
        assertTrue(u.reason().contains("exceeds Player's limit"), u.reason());
        assertInstanceOf(WireEvent.Frame.class, events.get(2));
        assertArrayEquals(stream, covered(events));
    }

    @Test
    void aTruncatedStreamReportsTheUnfinishedMessage() {
        byte[] stream = concat(BANNER, ACK, BIG);
        byte[] cut = java.util.Arrays.copyOf(stream, stream.length - 100);
        List<WireEvent> events = Streams.frameWhole(Direction.SERVER_TO_CLIENT, cut);
        WireEvent.Unframed u = assertInstanceOf(WireEvent.Unframed.class, events.get(2));
        assertEquals(72, u.offset());
        assertTrue(u.reason().contains("stream ended inside a message"), u.reason());
        assertTrue(u.reason().contains("4900 of 5000"), u.reason());
        assertArrayEquals(cut, covered(events));

        byte[] inHeader = java.util.Arrays.copyOf(stream, 32 + 40 + 10);
        List<WireEvent> e2 = Streams.frameByteByByte(Direction.SERVER_TO_CLIENT, inHeader);
        assertTrue(((WireEvent.Unframed) e2.get(2)).reason().contains("inside a message header"));
        assertArrayEquals(inHeader, covered(e2));
    }

    @Test
    void garbageAfterTheBannerIsReportedThenMessagesFollow() {
        byte[] garbage = "this is not XDR at all, just text!!".getBytes();
        byte[] stream = concat(BANNER, garbage, ACK, STATE);
        List<WireEvent> events = Streams.frameByteByByte(Direction.SERVER_TO_CLIENT, stream);
        assertInstanceOf(WireEvent.Banner.class, events.get(0));
        WireEvent.Unframed u = assertInstanceOf(WireEvent.Unframed.class, events.get(1));
        assertEquals(32, u.offset());
        assertEquals(garbage.length, u.length());
        assertInstanceOf(WireEvent.Frame.class, events.get(2));
        assertInstanceOf(WireEvent.Frame.class, events.get(3));
        assertArrayEquals(stream, covered(events));
    }

    @Test
    void aServerStreamWithoutIdentIsReported() {
        byte[] stream = concat(new byte[32], ACK);
        List<WireEvent> events = Streams.frameWhole(Direction.SERVER_TO_CLIENT, stream);
        WireEvent.Unframed u = assertInstanceOf(WireEvent.Unframed.class, events.get(0));
        assertTrue(u.reason().contains("ident"), u.reason());
        assertInstanceOf(WireEvent.Frame.class, events.get(1));
    }

    @Test
    void longGarbageIsReportedInBoundedPieces() {
        byte[] garbage = new byte[200_000];
        java.util.Arrays.fill(garbage, (byte) 0xEE);
        byte[] stream = concat(garbage, ACK);
        List<WireEvent> events = Streams.frameWhole(Direction.CLIENT_TO_SERVER, stream);
        long pieces = events.stream().filter(e -> e instanceof WireEvent.Unframed).count();
        assertTrue(pieces >= 3, "pieces: " + pieces);
        events.stream().filter(e -> e instanceof WireEvent.Unframed)
                .forEach(e -> assertTrue(e.bytes().length <= 64 * 1024));
        assertInstanceOf(WireEvent.Frame.class, events.get(events.size() - 1));
        assertArrayEquals(stream, covered(events));
    }

    @Test
    void fuzzedStreamsNeverThrowAndNeverLoseBytes() {
        Random random = new Random(7);
        byte[] base = serverStream();
        for (int round = 0; round < 2000; round++) {
            byte[] s = base.clone();
            int flips = 1 + random.nextInt(12);
            for (int i = 0; i < flips; i++) {
                s[random.nextInt(s.length)] = (byte) random.nextInt(256);
            }
            if (random.nextInt(4) == 0) {
                s = java.util.Arrays.copyOf(s, random.nextInt(s.length));
            }
            Direction d = random.nextBoolean() ? Direction.SERVER_TO_CLIENT : Direction.CLIENT_TO_SERVER;
            List<WireEvent> events = Streams.frameRandomly(d, s, random);
            assertArrayEquals(s, covered(events), "round " + round);
        }
    }

    @Test
    void aGapInObservationReportsTheCutMessageAndResumesAtTheRightOffset() {
        byte[] stream = concat(BANNER, ACK, BIG, STATE, ACK);
        List<WireEvent> events = new java.util.ArrayList<>();
        PlayerFramer f = new PlayerFramer(Direction.SERVER_TO_CLIENT, events::add);
        int cut = 32 + 40 + 1000; // inside BIG's payload
        f.accept(stream, 0, cut);
        int resume = 32 + 40 + BIG.length; // the observer lost the rest of BIG
        f.gap(resume - cut, "observer queue full");
        assertEquals(resume, f.nextOffset());
        f.accept(stream, resume, stream.length - resume);
        f.end();
        WireEvent.Unframed u = assertInstanceOf(WireEvent.Unframed.class, events.get(2));
        assertEquals(72, u.offset());
        assertEquals(1000, u.length());
        assertTrue(u.reason().contains("observer queue full"), u.reason());
        WireEvent.Frame next = assertInstanceOf(WireEvent.Frame.class, events.get(3));
        assertEquals(resume, next.offset());
        assertEquals(4, next.header().interf());
        assertEquals(5, events.size());
    }

    @Test
    void headerEncodesBackToItsExactBytes() {
        byte[] raw = new XdrWriter().int32(0).int32(0).int32(1).int32(0).int32(5).int32(1)
                .int64(0x0000562BDEADBEEFL).int32(55741367).int32(0).toByteArray();
        MessageHeader h = MessageHeader.read(raw, 0);
        XdrWriter w = new XdrWriter();
        h.write(w);
        assertArrayEquals(raw, w.toByteArray(), "garbage SYNCH timestamp and seq survive");
        assertEquals(null, h.problem());
    }

    /** Bytes allocated by this thread so far (HotSpot's per-thread counter). */
    private static long allocated() {
        return ((com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean())
                .getCurrentThreadAllocatedBytes();
    }

    @Test
    void plausibleAtAgreesWithTheHeadersOwnCheck() {
        Random random = new Random(11);
        byte[] b = new byte[MessageHeader.SIZE];
        int plausible = 0;
        for (int i = 0; i < 200_000; i++) {
            random.nextBytes(b);
            // bias towards near-valid headers so both answers are exercised
            if (random.nextBoolean()) {
                b[8] = b[9] = b[12] = b[13] = b[20] = b[21] = b[22] = b[16] = b[17] = b[18] = 0;
                b[19] = (byte) random.nextInt(8);
                b[36] = (byte) (random.nextInt(4) == 0 ? random.nextInt(256) : 0);
            }
            boolean p = MessageHeader.plausibleAt(b, 0);
            assertEquals(MessageHeader.read(b, 0).problem() == null, p, java.util.HexFormat.of().formatHex(b));
            plausible += p ? 1 : 0;
        }
        assertTrue(plausible > 1000, "both answers were checked: " + plausible);
    }

    @Test
    void garbageIsScannedWithoutAnAllocationPerSkippedByte() {
        byte[] garbage = new byte[4 << 20];
        new Random(3).nextBytes(garbage);
        for (int i = 16; i < garbage.length; i += 40) {
            garbage[i] = 0x7F; // no word at these positions is a message type: no plausible header anywhere
        }
        long[] skipped = new long[1];
        PlayerFramer f = new PlayerFramer(Direction.CLIENT_TO_SERVER, e -> skipped[0] += ((WireEvent.Unframed) e).length());
        f.accept(new byte[1]); // warm up
        long before = allocated();
        for (int off = 0; off < garbage.length; off += 65536) {
            f.accept(garbage, off, Math.min(65536, garbage.length - off));
        }
        long perByte = (allocated() - before) / garbage.length;
        f.end();
        assertEquals(garbage.length + 1, skipped[0], "every garbage byte reported as unframed");
        // The reported pieces themselves cost a few copies of the bytes; a header object per skipped
        // byte (the old slide) costs well over a hundred bytes per byte.
        assertTrue(perByte < 10, perByte + " bytes allocated per skipped byte");
    }

    @Test
    void garbageEndingInAHeaderFindsItAcrossChunkBoundaries() {
        byte[] garbage = new byte[100_003];
        java.util.Arrays.fill(garbage, (byte) 0xEE);
        byte[] stream = concat(garbage, ACK, STATE, garbage, BIG);
        List<String> whole = Streams.summary(Streams.frameWhole(Direction.CLIENT_TO_SERVER, stream));
        Random random = new Random(5);
        for (int i = 0; i < 20; i++) {
            List<WireEvent> events = Streams.frameRandomly(Direction.CLIENT_TO_SERVER, stream, random);
            assertEquals(whole, Streams.summary(events));
            assertEquals(3, events.stream().filter(e -> e instanceof WireEvent.Frame).count());
            assertArrayEquals(stream, covered(events));
        }
    }

    @Test
    void aPayloadArrivingInPiecesIsHeldAtTheSizeReceived() {
        byte[] hdr = message(header(6, 0, 1, 1, 1.0), new RawBody(new byte[MessageHeader.MAX_PAYLOAD]));
        PlayerFramer f = new PlayerFramer(Direction.CLIENT_TO_SERVER, e -> { });
        f.accept(hdr, 0, MessageHeader.SIZE);
        long before = allocated();
        int half = MessageHeader.MAX_PAYLOAD / 2;
        for (int off = MessageHeader.SIZE; off < MessageHeader.SIZE + half; off += 65536) {
            f.accept(hdr, off, 65536);
        }
        long used = allocated() - before;
        assertEquals(MessageHeader.SIZE + half, f.heldBytes());
        // a buffer that doubles holds up to twice what was sent and copies it on every doubling
        assertTrue(used < half * 1.1, used + " bytes allocated to hold " + half);
    }

    @Test
    void anAbandonedMessageIsPassedOverAndFramingContinuesAfterIt() {
        byte[] stream = concat(BANNER, ACK, BIG, STATE, ACK);
        List<WireEvent> events = new java.util.ArrayList<>();
        PlayerFramer f = new PlayerFramer(Direction.SERVER_TO_CLIENT, events::add);
        int cut = 32 + 40 + 40 + 1000; // 1000 bytes into BIG's payload
        f.accept(stream, 0, cut);
        assertEquals(MessageHeader.SIZE + 1000, f.heldBytes());
        assertEquals(72, f.pendingMessageOffset());
        assertEquals(1000, f.abandon());
        assertEquals(0, f.heldBytes());
        assertEquals(cut, f.nextOffset());
        for (int off = cut; off < stream.length; off += 7) {
            f.accept(stream, off, Math.min(7, stream.length - off));
        }
        f.end();
        assertEquals(BIG.length, f.abandonedBytes(), "the whole abandoned message is counted");
        assertEquals(4, events.size(), "banner, ACK, STATE, ACK: " + events);
        WireEvent.Frame next = assertInstanceOf(WireEvent.Frame.class, events.get(2));
        assertEquals(32 + 40 + BIG.length, next.offset());
        assertEquals(4, next.header().interf());
        assertEquals(0, f.unframedBytes(), "passed over, not reported as garbage");
    }
}
