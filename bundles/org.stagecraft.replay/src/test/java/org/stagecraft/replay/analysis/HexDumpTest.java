package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class HexDumpTest {
    @Test
    void sixteenBytesALineWithOffsetsHexAndText() {
        byte[] b = new byte[18];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) ('A' + i);
        }
        b[1] = 0;
        b[17] = (byte) 0xff;
        assertEquals("""
                00000000  41 00 43 44 45 46 47 48  49 4a 4b 4c 4d 4e 4f 50  |A.CDEFGHIJKLMNOP|
                00000010  51 ff                                             |Q.|
                """, HexDump.of(b));
        assertEquals("", HexDump.of(new byte[0]));
    }
}
