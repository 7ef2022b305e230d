package org.stagecraft.replay.fields;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.MessageHeader;

/** The breakpoint offered for a field of the inspector: it reads, and it holds on the message it came from. */
class BreakpointTextTest {
    private static MessageHeader header(int interf, int index, int type) {
        return new MessageHeader(0, 0, interf, index, type, 1, 0.0, 0, 0);
    }

    private static Field num(String name, Field.Kind kind, Object v) {
        return new Field(name, kind, v, List.of());
    }

    @Test
    void aListOfNumbersOffersItsMinimum() {
        Field ranges = new Field("ranges", Field.Kind.LIST, null,
                List.of(num(null, Field.Kind.FLOAT32, 2.0f), num(null, Field.Kind.FLOAT32, 0.287f)));
        String t = BreakpointText.of("laser", header(6, 0, 1), "ranges", ranges);
        assertEquals("laser:0 min(ranges) < 0.287", t);
        StreamCondition c = StreamCondition.parse(t, CodecRegistry.standard());
        Field body = new Field(FieldTree.ROOT, Field.Kind.STRUCT, null, List.of(ranges));
        assertEquals(false, c.condition().test(body).holds(), "strictly below what it was: not this message");
        assertEquals(true, StreamCondition.parse(t.replace("<", "<="), CodecRegistry.standard()).condition().test(body).holds());
    }

    @Test
    void numbersAndMessageTypes() {
        assertEquals("position2d:1 stall == 0", BreakpointText.of("position2d", header(4, 1, 1), "stall", num("stall", Field.Kind.INTEGER, 0L)));
        assertEquals("position2d:0 CMD vel.px < 0.4",
                BreakpointText.of("position2d", header(4, 0, 2), "vel.px", num("px", Field.Kind.FLOAT64, 0.4)));
        StreamCondition.parse("position2d:0 CMD vel.px < 0.4", CodecRegistry.standard());
        assertNull(BreakpointText.of("speech", header(12, 0, 2), "string", num("string", Field.Kind.TEXT, "hello")));
    }
}
