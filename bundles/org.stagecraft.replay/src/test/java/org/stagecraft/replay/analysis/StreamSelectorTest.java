package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.stagecraft.streams.StreamPattern;

class StreamSelectorTest {
    @Test
    void deviceNamesMeanTheirData() {
        assertEquals(StreamPattern.any().deviceType(6).messageType(1), StreamSelector.parse("laser", ListLog.REGISTRY));
        assertEquals(StreamPattern.any().deviceType(62).index(1).messageType(1), StreamSelector.parse("ranger:1", ListLog.REGISTRY));
        assertEquals(StreamPattern.any().deviceType(4).index(0).messageType(2), StreamSelector.parse("position2d:0 cmd", ListLog.REGISTRY));
        assertEquals(StreamPattern.any().deviceType(4), StreamSelector.parse("position2d:* *", ListLog.REGISTRY));
        assertEquals(StreamPattern.parse("type=1 dev=6"), StreamSelector.parse(" type=1 dev=6 ", ListLog.REGISTRY));
        assertEquals(StreamPattern.any(), StreamSelector.parse("  ", ListLog.REGISTRY));
    }

    @Test
    void whatIsNotUnderstoodIsNamed() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> StreamSelector.parse("lazer", ListLog.REGISTRY))
                .getMessage().contains("'lazer'"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> StreamSelector.parse("laser:x", ListLog.REGISTRY))
                .getMessage().contains("'x'"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> StreamSelector.parse("laser DATUM", ListLog.REGISTRY))
                .getMessage().contains("'DATUM'"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> StreamSelector.parse("type=x", ListLog.REGISTRY))
                .getMessage().contains("type=x"));
    }
}
