package org.stagecraft.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.FloatArray;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.scene.shapes.FloatList;
import org.stagecraft.scene.shapes.ReadingMark;

/** Where the Robot View marks the reading a robot data breakpoint stopped on (issue 27), without GL. */
class ReadingMarkTest {
    private static final double EPS = 1e-6;
    private static final double MPP = 0.01;
    private static final int RING_VERTICES = 48; // 24 segments
    /** Five beams from -90 to +90 degrees; the nearest return is beam 3 (0.5 m, at +45 degrees). */
    private static final Laser.Scan SCAN = new Laser.Scan((float) (-Math.PI / 2), (float) (Math.PI / 2), (float) (Math.PI / 4), 8f,
            5, FloatArray.of(2f, 1.5f, 8f, 0.5f, 3f), 0, ByteArray.EMPTY, 1);
    private static final DeviceAddress LASER = new DeviceAddress(new RobotId("127.0.0.1:6665"), Laser.CODE, 0);

    @Test
    void theDecidingBeamRunsFromTheSensorToItsReturnInsideARing() {
        FloatList lines = new FloatList(), points = new FloatList();
        ReadingMark.build(new BreakReading(LASER, SCAN, List.of("ranges[3]")), new WorldModel(), MPP, lines, points);
        assertEquals(RING_VERTICES + 2, lines.vertices(), "the ring and one beam");
        // the ring: 12 px around the laser (at the origin of a robot never seen)
        assertEquals(ReadingMark.RING_PIXELS * MPP, Math.hypot(lines.get(0), lines.get(1)), EPS);
        // the beam: from the laser to 0.5 m at +45 degrees
        int b = 2 * RING_VERTICES;
        assertEquals(0, lines.get(b), EPS);
        assertEquals(0, lines.get(b + 1), EPS);
        assertEquals(0.5 * Math.cos(Math.PI / 4), lines.get(b + 2), EPS);
        assertEquals(0.5 * Math.sin(Math.PI / 4), lines.get(b + 3), EPS);
        assertEquals(1, points.vertices(), "a point at its return");
        assertEquals(lines.get(b + 2), points.get(0), EPS);
    }

    @Test
    void aWholeReadingGetsAPointAtEveryReturnAndNoBeams() {
        FloatList lines = new FloatList(), points = new FloatList();
        // nothing known (a break replayed from a log)
        ReadingMark.build(new BreakReading(LASER, SCAN, List.of()), new WorldModel(), MPP, lines, points);
        assertEquals(RING_VERTICES, lines.vertices(), "the ring only");
        assertEquals(5, points.vertices(), "every beam's end");
        // count(ranges) decided: the whole list
        FloatList l2 = new FloatList(), p2 = new FloatList();
        ReadingMark.build(new BreakReading(LASER, SCAN, List.of("ranges")), new WorldModel(), MPP, l2, p2);
        assertEquals(5, p2.vertices());
    }

    @Test
    void aConditionOnOtherFieldsMarksTheSensorOnly() {
        FloatList lines = new FloatList(), points = new FloatList();
        ReadingMark.build(new BreakReading(LASER, SCAN, List.of("id")), new WorldModel(), MPP, lines, points);
        assertEquals(RING_VERTICES, lines.vertices());
        assertEquals(0, points.vertices());
    }

    @Test
    void readsElementIndexesOfTheNamedListOnly() {
        BreakReading r = new BreakReading(LASER, SCAN, List.of("ranges[3]", "intensity[1]", "ranges[10]"));
        assertEquals(List.of(3, 10), r.elements("ranges").indexes());
        assertFalse(r.elements("ranges").whole());
        assertTrue(r.elements("ranges").marks(3));
        assertFalse(r.elements("ranges").marks(1));
        assertEquals(List.of(1), r.elements("intensity").indexes());
        assertTrue(new BreakReading(LASER, SCAN, List.of()).elements("ranges").whole());
    }
}
