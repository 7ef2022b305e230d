package org.stagecraft.player.codec;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.stagecraft.player.Streams.header;

import java.io.ByteArrayOutputStream;
import java.util.List;
import java.util.Random;
import java.util.zip.Deflater;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.FloatArray;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.MapInterface;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

class PlayerDecoderTest {
    private final PlayerDecoder decoder = new PlayerDecoder(CodecRegistry.standard());

    private DecodedMessage decode(int interf, int type, int subtype, byte[] payload) {
        return decoder.decode(header(interf, 0, type, subtype, 1.5).withSize(payload.length), payload);
    }

    private static byte[] body(MessageBody b) {
        return PlayerEncoder.encodeBody(b);
    }

    @Test
    void laserScanDecodesByPlayerNamesAndEncodesBack() {
        Laser.Scan scan = new Laser.Scan(-1.5707964f, 1.5707964f, 0.017453292f, 8f, 3, FloatArray.of(1f, 2.5f, 8f), 3,
                ByteArray.of((byte) 0, (byte) 1, (byte) 255), 42);
        byte[] payload = body(scan);
        assertEquals(4 * 4 + 4 + 4 + 12 + 4 + 4 + 4 + 4, payload.length);
        DecodedMessage m = decode(6, 1, 1, payload);
        assertNull(m.problem());
        assertEquals(scan, m.body());
        assertArrayEquals(payload, body(m.body()));
        java.util.Map<String, Object> fields = Fields.of(m.body());
        assertEquals(List.of("min_angle", "max_angle", "resolution", "max_range", "ranges_count", "ranges",
                "intensity_count", "intensity", "id"), List.copyOf(fields.keySet()));
        assertEquals(List.of(0L, 1L, 255L), fields.get("intensity"));
    }

    @Test
    void repliesUseTheRequestLayout() {
        Position2d.SetOdom odom = new Position2d.SetOdom(new Pose2d(1, 2, 0.5));
        byte[] payload = body(odom);
        assertEquals(odom, decode(4, MessageType.REQ.code(), 5, payload).body());
        assertEquals(odom, decode(4, MessageType.RESP_ACK.code(), 5, payload).body());
        assertEquals(odom, decode(4, MessageType.RESP_NACK.code(), 5, payload).body());
    }

    @Test
    void emptyPayloadsAreEmptyBodiesWhateverTheLayout() {
        DecodedMessage m = decode(6, 3, 1, new byte[0]);
        assertEquals(EmptyBody.INSTANCE, m.body());
        assertFalse(m.hasProblem());
    }

    @Test
    void unknownInterfacesStayRawWithoutError() {
        byte[] payload = {1, 2, 3, 4, 5, 6, 7, 8};
        DecodedMessage m = decode(77, 1, 1, payload);
        RawBody raw = assertInstanceOf(RawBody.class, m.body());
        assertArrayEquals(payload, raw.bytes());
        assertFalse(m.hasProblem());
    }

    @Test
    void universalRequestsDecodeOnAnyInterface() {
        byte[] payload = new XdrWriter().uint32(6).bytes("max_speed\0".getBytes()).float64(0.5).toByteArray();
        DecodedMessage m = decode(62, 3, 252, payload);
        assertNull(m.problem());
        assertEquals("max_speed", Fields.of(m.body()).get("key"));
        assertEquals(0.5, Fields.of(m.body()).get("value"));
    }

    @Test
    void aHostileArrayCountBecomesAProblemAndTheBytesStay() {
        byte[] payload = new XdrWriter().float32(0).float32(0).float32(0).float32(8).uint32(180).int32(0x3FFFFFFF)
                .float32(1).toByteArray();
        DecodedMessage m = decode(6, 1, 1, payload);
        assertTrue(m.hasProblem());
        assertEquals(20, m.problem().payloadOffset());
        assertTrue(m.problem().reason().startsWith("laser SCAN payload of 28 bytes"), m.problem().reason());
        assertArrayEquals(payload, assertInstanceOf(RawBody.class, m.body()).bytes());
    }

    @Test
    void trailingBytesAreAProblem() {
        byte[] payload = new XdrWriter().uint8(2).int32(0).toByteArray();
        DecodedMessage m = decode(1, 3, 5, payload);
        assertTrue(m.hasProblem());
        assertTrue(m.problem().reason().contains("trailing"), m.problem().reason());
    }

    @Test
    void aFailingPluginDecoderCannotEscape() {
        CodecRegistry r = CodecRegistry.standard();
        r.register(200, MessageType.DATA, 1, "BROKEN", in -> {
            throw new IllegalStateException("bug in a plug-in");
        });
        DecodedMessage m = new PlayerDecoder(r).decode(header(200, 0, 1, 1, 0).withSize(4), new byte[4]);
        assertTrue(m.problem().reason().contains("bug in a plug-in"));
        assertInstanceOf(RawBody.class, m.body());
    }

    @Test
    void contributionsAddInterfacesAndOverrideLayouts() {
        CodecRegistry r = CodecRegistry.standard();
        r.add(reg -> {
            reg.registerInterface(300, "thermometer");
            reg.register(300, MessageType.DATA, 1, "TEMPERATURE", in -> new Celsius(in.float64()));
        });
        DecodedMessage m = new PlayerDecoder(r).decode(header(300, 0, 1, 1, 0).withSize(8),
                new XdrWriter().float64(21.5).toByteArray());
        assertEquals(new Celsius(21.5), m.body());
        assertEquals("thermometer", r.interfaceName(300));
        assertEquals("TEMPERATURE", r.subtypeName(300, 1, 1));
    }

    @Test
    void standardRegistryIncludesServiceLoaderContributions() {
        assertEquals("odometer", CodecRegistry.standard().interfaceName(400));
        assertEquals("DISTANCE", CodecRegistry.standard().subtypeName(400, 1, 1));
    }

    record Celsius(double value) implements MessageBody {
        @Override
        public void encode(XdrWriter out) {
            out.float64(value);
        }

        @Override
        public void describe(FieldVisitor visitor) {
            visitor.float64("value", value);
        }
    }

    @Test
    void mapTilesInflateTheirZlibCells() throws Exception {
        byte[] cells = new byte[40 * 30];
        for (int i = 0; i < cells.length; i++) {
            cells[i] = (byte) (i % 7 == 0 ? 1 : -1);
        }
        Deflater d = new Deflater();
        d.setInput(cells);
        d.finish();
        ByteArrayOutputStream z = new ByteArrayOutputStream();
        byte[] buf = new byte[4096];
        while (!d.finished()) {
            z.write(buf, 0, d.deflate(buf));
        }
        byte[] zipped = z.toByteArray();
        byte[] payload = new XdrWriter().uint32(0).uint32(0).uint32(40).uint32(30).uint32(zipped.length).int8(1)
                .bytes(zipped).toByteArray();
        DecodedMessage m = decode(42, 4, 2, payload);
        MapInterface.Tile tile = assertInstanceOf(MapInterface.Tile.class, m.body());
        assertTrue(tile.compressed());
        assertArrayEquals(cells, tile.cells());
        assertArrayEquals(payload, body(tile));

        byte[] plain = new XdrWriter().uint32(0).uint32(0).uint32(2).uint32(2).uint32(4).int8(1)
                .bytes(new byte[] {1, -1, 0, 1}).toByteArray();
        MapInterface.Tile t2 = (MapInterface.Tile) decode(42, 4, 2, plain).body();
        assertFalse(t2.compressed());
        assertArrayEquals(new byte[] {1, -1, 0, 1}, t2.cells());
    }

    @Test
    void randomPayloadsForEveryLayoutNeverThrowAndRoundTripWhenDecoded() {
        Random random = new Random(11);
        CodecRegistry r = decoder.registry();
        int decodedCount = 0;
        for (int interf : r.interfaces().keySet()) {
            for (int type = 1; type <= 6; type++) {
                for (int subtype = 0; subtype < 256; subtype++) {
                    if (r.lookup(interf, type, subtype) == null) {
                        continue;
                    }
                    for (int k = 0; k < 20; k++) {
                        byte[] payload = randomXdrish(random);
                        MessageHeader h = header(interf, 0, type, subtype, 0).withSize(payload.length);
                        DecodedMessage m = decoder.decode(h, payload);
                        assertArrayEquals(payload, PlayerEncoder.encodeBody(m.body()),
                                interf + "/" + type + "/" + subtype);
                        if (!(m.body() instanceof RawBody)) {
                            decodedCount++;
                        }
                    }
                }
            }
        }
        assertTrue(decodedCount > 50, "some random payloads must decode: " + decodedCount);
    }

    /** Small counts and zero padding so that random payloads sometimes fit a layout. */
    private static byte[] randomXdrish(Random random) {
        XdrWriter w = new XdrWriter();
        int words = random.nextInt(40);
        for (int i = 0; i < words; i++) {
            w.int32(random.nextInt(3) == 0 ? random.nextInt() : random.nextInt(4));
        }
        return w.toByteArray();
    }

    @Test
    void readerPositionIsRelativeToThePayload() {
        byte[] b = new byte[12];
        XdrReader r = new XdrReader(b, 4, 8);
        r.int32();
        assertEquals(4, r.position());
    }
}
