package org.stagecraft.replay.fields;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.stagecraft.player.codec.CodecRegistry;

/** The robot data breakpoint's condition language: reading, errors with positions, units, tests. */
class ConditionTest {

    /** A laser-like body: ranges, a pose with a velocity, a stall flag, bumpers. */
    private static Field body(double[] ranges, double px, double vpa, int stall, int... bumpers) {
        List<Field> r = new ArrayList<>();
        for (double d : ranges) {
            r.add(new Field(null, Field.Kind.FLOAT32, (float) d, List.of()));
        }
        List<Field> b = new ArrayList<>();
        for (int x : bumpers) {
            b.add(new Field(null, Field.Kind.INTEGER, (long) x, List.of()));
        }
        Field pos = new Field("pos", Field.Kind.STRUCT, null, List.of(new Field("px", Field.Kind.FLOAT64, px, List.of()),
                new Field("py", Field.Kind.FLOAT64, 0.0, List.of()), new Field("pa", Field.Kind.FLOAT64, 0.0, List.of())));
        Field vel = new Field("vel", Field.Kind.STRUCT, null, List.of(new Field("px", Field.Kind.FLOAT64, 0.0, List.of()),
                new Field("pa", Field.Kind.FLOAT64, vpa, List.of())));
        return new Field(FieldTree.ROOT, Field.Kind.STRUCT, null, List.of(new Field("ranges", Field.Kind.LIST, null, r), pos, vel,
                new Field("stall", Field.Kind.INTEGER, (long) stall, List.of()), new Field("bumpers", Field.Kind.LIST, null, b)));
    }

    private static final Field NEAR = body(new double[] { 2.0, 0.287, 1.5 }, 1.25, 0.7, 0, 0, 1);
    private static final Field FAR = body(new double[] { 2.0, 3.0, 1.5 }, -0.5, 0.0, 1, 0, 0);

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
            "min(ranges) < 0.3; true; false",
            "min(ranges) < 30 cm; true; false",
            "min(ranges) < 280 mm; false; false",
            "ranges[1] <= 0.287; true; false",
            "ranges[1] == 0.287; true; false",
            "0.287 == ranges[1]; true; false",
            "max(ranges) >= 3 and stall == 1; false; true",
            "stall == 1 or min(ranges) < 0.3; true; true",
            "not (stall == 1); true; false",
            "!(stall = 1) && count(ranges) == 3; true; false",
            "any(bumpers); true; false",
            "all(bumpers); false; false",
            "abs(vel.pa) > 30 deg/s; true; false",
            "pos.px - 1 > 0; true; false",
            "pos.px * 2 > 2.4 m; true; false",
            "-pos.px > 0; false; true",
            "mean(ranges) > 1 and sum(ranges) < 10; true; true",
            "mean(ranges) > 2 and sum(ranges) < 10; false; true",
            "nosuch.field < 1; false; false",
            "nosuch.field != 1; false; false",
            "true; true; true" })
    void evaluates(String text, boolean onNear, boolean onFar) {
        Condition c = Condition.parse(text);
        assertEquals(onNear, c.test(NEAR).holds(), text + " on NEAR");
        assertEquals(onFar, c.test(FAR).holds(), text + " on FAR");
    }

    @Test
    void explainsWithValuesAndUnits() {
        assertEquals("min(ranges) = 0.287 m < 0.3", Condition.parse("min(ranges) < 0.3").test(NEAR).explanation());
        assertEquals("min(ranges) = 0.287 m < 30 cm", Condition.parse("min(ranges)<30 cm").test(NEAR).explanation());
        assertEquals("abs(vel.pa) = 0.7 rad/s > 30 deg/s", Condition.parse("abs(vel.pa) > 30 deg/s").test(NEAR).explanation());
        assertEquals("stall = 1 == 1", Condition.parse("stall == 1 or min(ranges) < 0.1").test(FAR).explanation());
        assertEquals("any(bumpers) (1 of 2 non-zero)", Condition.parse("any(bumpers)").test(NEAR).explanation());
        assertEquals("", Condition.parse("min(ranges) < 0.1").test(NEAR).explanation(), "nothing to explain when it does not hold");
    }

    /** What a view marks when a breakpoint stops: the concrete fields that decided the test, not the test's text. */
    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
            "min(ranges) < 0.3; NEAR; ranges[1]",
            "max(ranges) >= 3; FAR; ranges[1]",
            "ranges[2] > 1; NEAR; ranges[2]",
            "any(bumpers); NEAR; bumpers[1]",
            "all(bumpers) or stall == 1; FAR; stall",
            "stall == 1 or min(ranges) < 0.3; NEAR; ranges[1]",
            "min(ranges) < 0.3 and pos.px > 1; NEAR; ranges[1] pos.px",
            "abs(vel.pa - 0.1) > 0.5; NEAR; vel.pa",
            "count(ranges) == 3; NEAR; ranges",
            "not (stall == 1); NEAR; ''" })
    void namesTheFieldsThatDecidedIt(String text, String which, String fields) {
        Condition.Verdict v = Condition.parse(text).test(which.equals("NEAR") ? NEAR : FAR);
        assertTrue(v.holds(), text);
        assertEquals(fields.isEmpty() ? List.of() : List.of(fields.split(" ")), v.decidingFields(), text);
        assertEquals(List.of(), Condition.parse("min(ranges) < 0.1").test(NEAR).decidingFields(), "none when it does not hold");
    }

    /** A unit converts the number: 30 deg is 0.5236 rad, 0.3 m/s stays 0.3. */
    @Test
    void unitsConvertToPlayersSiUnits() {
        Field turning = body(new double[] { 1 }, 0, Math.toRadians(29.9), 0);
        assertFalse(Condition.parse("vel.pa > 30 deg/s").test(turning).holds());
        assertTrue(Condition.parse("vel.pa > 29.8 deg/s").test(turning).holds());
        assertTrue(Condition.parse("vel.pa > 29.8 °/s").test(turning).holds());
        assertTrue(Condition.parse("ranges[0] == 100 cm").test(turning).holds());
        assertTrue(Condition.parse("ranges[0] == 1000mm").test(turning).holds());
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
            // text; where (1-based character); what the reason says
            "min(ranges) < 30 deg; 15; an angle",
            "min(ranges) <; 14; ends too early",
            "min(ranges) 0.3; 13; unexpected '0.3'",
            "foo(ranges) < 1; 1; no function is called 'foo'",
            "stall; 1; is a number, not a test",
            "0.3 furlong < ranges[0]; 5; not a unit",
            "(stall == 1; 12; expected ')'",
            "stall < 1 < 2; 11; do not chain",
            "stall and min(ranges) < 1; 7; is a number",
            "min(ranges) < 0.3 $; 19; not part of a condition",
            "ranges[*] < 1; 1; wrap it in",
            "; 1; empty",
            "min(3) < 1; 5; takes a field",
            "pos.px + 15 deg > 0; 10; an angle",
            "stall == 1); 11; no '(' to close" })
    void refusesWithPositionAndReason(String text, int column, String reason) {
        String t = text == null ? "" : text;
        ConditionException e = assertThrows(ConditionException.class, () -> Condition.parse(t));
        assertEquals(column - 1, e.position(), e.getMessage());
        assertTrue(e.reason().contains(reason), e.getMessage());
        assertTrue(e.getMessage().startsWith("at character " + column + ": "), e.getMessage());
        assertEquals(t + "\n" + " ".repeat(column - 1) + "^", e.pointer());
    }

    @Test
    void streamConditionReadsDeviceTypeAndCondition() {
        CodecRegistry r = CodecRegistry.standard();
        StreamCondition c = StreamCondition.parse("laser:0 min(ranges) < 0.3", r);
        assertEquals("min(ranges) < 0.3", c.condition().text());
        assertEquals(org.stagecraft.replay.analysis.StreamSelector.parse("laser:0", r), c.streams());
        assertEquals(org.stagecraft.replay.analysis.StreamSelector.parse("position2d:1 CMD", r),
                StreamCondition.parse("  position2d:1 CMD vel.px > 0", r).streams());
        assertEquals(org.stagecraft.streams.StreamPattern.parse("type=1 dev=6 index=*"),
                StreamCondition.parse("type=1 dev=6 index=* | min(ranges) < 0.3", r).streams());
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
            "lidar:0 min(ranges) < 1; 1; no Player interface is called 'lidar'",
            "laser:0; 8; needs a condition",
            "laser:0 min(ranges) <; 22; ends too early",
            "laser:x min(ranges) < 1; 1; not a device index",
            "ranger:1 DATA ranges[3] < 5 deg; 27; an angle" })
    void streamConditionErrorsPointIntoTheWholeText(String text, int column, String reason) {
        ConditionException e = assertThrows(ConditionException.class, () -> StreamCondition.parse(text, CodecRegistry.standard()));
        assertEquals(column - 1, e.position(), e.getMessage());
        assertTrue(e.reason().contains(reason), e.getMessage());
        assertEquals(text, e.text());
    }
}
