package org.stagecraft.replay.fields;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.replay.log.Logs;

class FieldPathTest {
    private static final PlayerDecoder DECODER = new PlayerDecoder(CodecRegistry.standard());

    /** The first decoded message of the recorded session whose body is of this class. */
    private static <T> T first(Class<T> type) {
        for (SessionEvent e : Logs.framed(Logs.trace(Logs.GT))) {
            if (e.event() instanceof WireEvent.Frame f) {
                DecodedMessage d = DECODER.decode(f);
                if (type.isInstance(d.body())) {
                    return type.cast(d.body());
                }
            }
        }
        throw new AssertionError("no " + type.getSimpleName() + " in " + Logs.GT);
    }

    private static Ranger.Values firstRanges() {
        for (SessionEvent e : Logs.framed(Logs.trace(Logs.GT))) {
            if (e.event() instanceof WireEvent.Frame f && DECODER.decode(f).body() instanceof Ranger.Values v
                    && v.name().equals("ranges") && v.count() > 16) {
                return v;
            }
        }
        throw new AssertionError("no laser ranger data in " + Logs.GT);
    }

    @Test
    void aDottedPathPicksTheFieldByPlayersName() {
        Position2d.State s = first(Position2d.State.class);
        assertEquals(s.pos().px(), FieldPath.parse("pos.px").evaluate(s).getAsDouble());
        assertEquals(s.vel().pa(), FieldPath.parse("vel.pa").evaluate(s).getAsDouble());
        assertEquals(s.stall(), FieldPath.parse("stall").evaluate(s).getAsDouble());
        assertFalse(FieldPath.parse("pos.nothing").evaluate(s).isPresent());
        assertFalse(FieldPath.parse("pos").evaluate(s).isPresent(), "a struct is not a number");
    }

    @Test
    void aggregatesAndIndexesWorkOnRecordedRanges() {
        Ranger.Values v = firstRanges();
        double[] r = v.values().toArray();
        assertEquals(Arrays.stream(r).min().orElseThrow(), FieldPath.parse("min(ranges)").evaluate(v).getAsDouble());
        assertEquals(Arrays.stream(r).max().orElseThrow(), FieldPath.parse("max(ranges)").evaluate(v).getAsDouble());
        assertEquals(Arrays.stream(r).average().orElseThrow(), FieldPath.parse("mean( ranges )").evaluate(v).getAsDouble(),
                1e-12);
        assertEquals(r.length, FieldPath.parse("count(ranges)").evaluate(v).getAsDouble());
        assertEquals(r[3], FieldPath.parse("ranges[3]").evaluate(v).getAsDouble());
        assertFalse(FieldPath.parse("ranges[" + r.length + "]").evaluate(v).isPresent());
        assertEquals(Arrays.stream(r).max().orElseThrow(), FieldPath.parse("max(ranges[*])").evaluate(v).getAsDouble());
    }

    @Test
    void badPathsAreRefusedSayingWhere() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FieldPath.parse("pos.2x"));
        assertTrue(e.getMessage().contains("\"2x\" at character 5"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> FieldPath.parse(" "));
        IllegalArgumentException star = assertThrows(IllegalArgumentException.class, () -> FieldPath.parse("ranges[*]"));
        assertTrue(star.getMessage().contains("min()"), star.getMessage());
    }

    @Test
    void flatFieldsNameEveryLeafInWireOrder() {
        Position2d.State s = first(Position2d.State.class);
        Map<String, Object> flat = FlatFields.flatten(s);
        assertEquals(List.of("pos.px", "pos.py", "pos.pa", "vel.px", "vel.py", "vel.pa", "stall"), List.copyOf(flat.keySet()));
        assertEquals(s.pos().py(), flat.get("pos.py"));
        Ranger.Values v = firstRanges();
        Map<String, Object> ranges = FlatFields.flatten(v);
        assertEquals(v.values().get(0), ranges.get("ranges[0]"));
        assertEquals(v.count() + 1, ranges.size(), "the count and one entry per range");
    }

    @Test
    void suggestionsOfferScalarsAndListAggregates() {
        assertEquals(List.of("pos.px", "pos.py", "pos.pa", "vel.px", "vel.py", "vel.pa", "stall"),
                FieldPath.suggestions(first(Position2d.State.class)));
        List<String> s = FieldPath.suggestions(firstRanges());
        assertTrue(s.containsAll(List.of("ranges_count", "min(ranges)", "max(ranges)", "mean(ranges)", "count(ranges)")),
                s.toString());
        assertTrue(s.stream().noneMatch(p -> p.startsWith("ranges[")));
    }
}
