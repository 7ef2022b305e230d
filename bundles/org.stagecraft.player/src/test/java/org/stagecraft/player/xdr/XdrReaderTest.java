package org.stagecraft.player.xdr;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class XdrReaderTest {

    @Test
    void primitivesRoundTripThroughTheWriter() {
        byte[] bytes = new XdrWriter().int32(-5).uint32(0xFFFFFFFF).uint8(200).int8(-3).uint16(65535).int16(-2)
                .bool(true).float32(Float.intBitsToFloat(0x7FC00123)).float64(4.68e-310).int64(Long.MIN_VALUE)
                .bytes(new byte[] {1, 2, 3}).toByteArray();
        XdrReader r = new XdrReader(bytes);
        assertEquals(-5, r.int32());
        assertEquals(0xFFFFFFFF, r.uint32());
        assertEquals(200, r.uint8());
        assertEquals(-3, r.int8());
        assertEquals(65535, r.uint16());
        assertEquals(-2, r.int16());
        assertTrue(r.bool());
        assertEquals(0x7FC00123, Float.floatToRawIntBits(r.float32()), "NaN payload must survive");
        assertEquals(4.68e-310, r.float64());
        assertEquals(Long.MIN_VALUE, r.int64());
        assertArrayEquals(new byte[] {1, 2, 3}, r.bytes());
        r.expectEnd();
    }

    @Test
    void charsAndShortsTakeFourBytesWithTheValueLast() {
        assertArrayEquals(new byte[] {0, 0, 0, (byte) 0xB4}, new XdrWriter().uint8(0xB4).toByteArray());
        assertArrayEquals(new byte[] {(byte) 0xFF, (byte) 0xFF, (byte) 0xFF, (byte) 0xFE}, new XdrWriter().int8(-2).toByteArray());
    }

    @Test
    void bytesArePaddedToFourWithZeros() {
        byte[] enc = new XdrWriter().bytes("stage\0".getBytes()).toByteArray();
        assertEquals(4 + 8, enc.length);
        assertEquals(6, enc[3]);
        assertEquals(0, enc[10]);
        assertEquals(0, enc[11]);
    }

    @Test
    void aHostileCountFailsBeforeAnyAllocation() {
        byte[] bytes = new XdrWriter().int32(0x7FFFFFFF).int32(1).toByteArray();
        XdrException e = assertThrows(XdrException.class, () -> new XdrReader(bytes).count(8));
        assertEquals(0, e.offset());
        assertTrue(e.getMessage().contains("2147483647"), e.getMessage());
        assertThrows(XdrException.class, () -> new XdrReader(bytes).bytes());
    }

    @Test
    void nonCanonicalWordsAreRejectedWithTheirOffset() {
        byte[] bytes = new XdrWriter().int32(0).int32(0x100).toByteArray();
        XdrReader r = new XdrReader(bytes);
        r.uint8();
        XdrException e = assertThrows(XdrException.class, r::uint8);
        assertEquals(4, e.offset());
        assertThrows(XdrException.class, () -> new XdrReader(new XdrWriter().int32(2).toByteArray()).bool());
    }

    @Test
    void nonZeroPaddingIsRejected() {
        byte[] bytes = {0, 0, 0, 1, 'a', 'b', 0, 0};
        assertThrows(XdrException.class, () -> new XdrReader(bytes).bytes());
    }

    @Test
    void truncationAndTrailingBytesAreReported() {
        assertThrows(XdrException.class, () -> new XdrReader(new byte[7]).float64());
        XdrReader r = new XdrReader(new byte[8]);
        r.int32();
        XdrException e = assertThrows(XdrException.class, r::expectEnd);
        assertEquals(4, e.offset());
    }
}
