package org.stagecraft.replay.writelog;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.msg.Fiducial;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Sonar;
import org.stagecraft.replay.log.LogProblem;

/**
 * Files in Player's own formatting (fixed widths, signs, zero padding, trailing spaces, as Player 3's
 * writelog prints them), and lines that cannot be read.
 */
class WritelogReaderTest {

    private static final String PLAYER_FILE = """
            ## Player version 3.0.2\s
            ## File version 0.3.0\s
            ## Format:\s
            ## - Messages are newline-separated
            1234567890.100 16777343 6665 position2d 00 004 001 +00.100 -00.200 +0.000 +00.300 +00.400
            1234567890.200 16777343 6665 position2d 00 001 001 +01.000 +02.000 +0.500 +00.100 +00.000 +00.050 1
            1234567890.300 16777343 6665 laser 00 001 001 0007 -1.5708 +1.5708 +0.01745329 +8.0000 0003 1.000  0 2.000  1 3.000  0\s
            1234567890.310 16777343 6665 sonar 00 001 001 3 0.500 0.600 0.700\s
            1234567890.320 16777343 6665 ranger 01 001 001 0002 1.250 2.500\s
            1234567890.330 16777343 6665 fiducial 00 004 001  +0.100  +0.000  +0.000  +0.000  +0.000+0.000  +0.200  +0.100  +0.050  +0.300  +0.200
            garbage line
            1234567890.400 16777343 6665 laser 00 001 001 0007 -1.5708 +1.5708 +0.01745329 +8.0000 0003 1.000  0 2.000\s
            1234567890.500 16777343 6665 camera 00 001 001 1 1 8 1 0 0\s
            1234567890.600 16777343 6665 nosuchthing 00 001 001 1
            1234567890.700 16777343 6665 sonar 00 001 001 2 0.5 0.6 0.7
            1234567890.800 16777343 6665 sonar 00 001 001 2 0.5 x
            1234567890.900 16777343 6666 sonar 00 004 001 2 +0.100 -0.200 +1.5708 +0.300 +0.400 -1.5708\s
            """;

    private static List<WritelogRecord> readAll(String text, List<LogProblem> problems) throws IOException {
        List<WritelogRecord> out = new ArrayList<>();
        try (WritelogReader r = new WritelogReader("test.log", new BufferedReader(new StringReader(text)))) {
            for (WritelogRecord rec = r.next(); rec != null; rec = r.next()) {
                out.add(rec);
            }
            problems.addAll(r.problems());
        }
        return out;
    }

    @Test
    void readsPlayersOwnFormattingIntoTheCodecsMessages() throws IOException {
        List<LogProblem> problems = new ArrayList<>();
        List<WritelogRecord> r = readAll(PLAYER_FILE, problems);
        assertEquals(7, r.size());

        DeviceGeom geom = assertInstanceOf(DeviceGeom.class, r.get(0).body());
        assertEquals(0.1, geom.pose().px());
        assertEquals(-0.2, geom.pose().py());
        assertEquals(0.3, geom.size().sl());
        assertEquals(0.4, geom.size().sw());
        assertEquals(1234567890.1, r.get(0).time());
        assertEquals(16777343L, r.get(0).host());
        assertEquals(6665L, r.get(0).robot());
        assertEquals(4, r.get(0).type());

        Position2d.State s = assertInstanceOf(Position2d.State.class, r.get(1).body());
        assertEquals(1.0, s.pos().px());
        assertEquals(0.5, s.pos().pa());
        assertEquals(0.05, s.vel().pa());
        assertEquals(1, s.stall());

        Laser.Scan scan = assertInstanceOf(Laser.Scan.class, r.get(2).body());
        assertEquals(7, scan.id());
        assertEquals(3, scan.rangesCount());
        assertEquals(3, scan.intensityCount(), "readlog's reading: one intensity per range");
        assertEquals(2.0f, scan.ranges().get(1));
        assertEquals(1, scan.intensity().unsigned(1));
        assertEquals((float) 0.01745329, scan.resolution());

        Sonar.Ranges sonar = assertInstanceOf(Sonar.Ranges.class, r.get(3).body());
        assertEquals(0.7f, sonar.ranges().get(2));

        Ranger.Values ranger = assertInstanceOf(Ranger.Values.class, r.get(4).body());
        assertEquals("ranges", ranger.name());
        assertEquals(1, r.get(4).index());
        assertEquals(2.5, ranger.values().get(1));

        Fiducial.Geom fg = assertInstanceOf(Fiducial.Geom.class, r.get(5).body(), "two values Player printed without a space");
        assertEquals(0.0, fg.pose().pyaw());
        assertEquals(0.2, fg.size().sl());
        assertEquals(0.1, fg.size().sw());
        assertEquals(0.3, fg.fiducialSize().sl());

        Sonar.Geom sg = assertInstanceOf(Sonar.Geom.class, r.get(6).body());
        assertEquals(6666L, r.get(6).robot());
        assertEquals(-1.5708, sg.poses().get(1).pyaw());
        assertEquals(0.0, sg.poses().get(1).pz());
    }

    @Test
    void everyUnreadableLineIsAProblemNamingItAndReadingGoesOn() throws IOException {
        List<LogProblem> problems = new ArrayList<>();
        readAll(PLAYER_FILE, problems);
        List<String> where = problems.stream().map(LogProblem::where).toList();
        assertEquals(List.of("line 11", "line 12", "line 13", "line 14", "line 15", "line 16"), where);
        assertTrue(problems.get(0).text().contains("only 2 values"), problems.get(0).text());
        assertTrue(problems.get(1).text().contains("ranges_count 3 needs 6 more values but the line has 3"), problems.get(1).text());
        assertTrue(problems.get(2).text().contains("camera"), problems.get(2).text());
        assertTrue(problems.get(3).text().contains("unknown interface 'nosuchthing'"), problems.get(3).text());
        assertTrue(problems.get(4).text().contains("1 values left over"), problems.get(4).text());
        assertTrue(problems.get(5).text().contains("'x'"), problems.get(5).text());
        assertEquals(WritelogReader.nanos(1234567890.33), problems.get(0).timeNanos(), "time of the last readable line");
    }

    @Test
    void aPlayerOneFileStopsWithOneProblem() throws IOException {
        List<LogProblem> problems = new ArrayList<>();
        List<WritelogRecord> r = readAll("""
                ## Player version 1.6.5\s
                ## File version 0.1.0\s
                1100000000.000 host 6665 laser 00 1100000000.000 0000 -1.5708 +1.5708 +0.00872665 0361 1.000 0
                """, problems);
        assertEquals(List.of(), r);
        assertEquals(1, problems.size());
        assertEquals("line 2", problems.get(0).where());
        assertTrue(problems.get(0).text().contains("0.1.0"));
    }

    @Test
    void stampedRangerDataInBothPlayerLayouts() throws IOException {
        List<LogProblem> problems = new ArrayList<>();
        List<WritelogRecord> r = readAll("""
                1.0 0 6665 ranger 00 001 002 0002 1.0 2.0 0\s
                2.0 0 6665 ranger 00 001 002 0002 1.0 2.0 0 1 0.1 0.2 0.3 0.4 5.0 0.01 10.0\s
                3.0 0 6665 ranger 00 001 002 0002 1.0 2.0 0 0.1 0.2 0.3 0.4 5.0 0.01 10.0\s
                """, problems);
        assertEquals(List.of(), problems);
        Ranger.Stamped a = assertInstanceOf(Ranger.Stamped.class, r.get(0).body());
        assertEquals(0, a.haveConfig());
        Ranger.Stamped b = assertInstanceOf(Ranger.Stamped.class, r.get(1).body());
        assertEquals(1, b.haveConfig());
        assertEquals(10.0, b.config().frequency());
        assertEquals(b, r.get(2).body(), "writelog's layout (no have_config value) reads the same");
    }

    @Test
    void recognisesWritelogFilesByTheirStart() {
        assertTrue(WritelogImport.looksLikeWritelog(PLAYER_FILE.getBytes(StandardCharsets.ISO_8859_1)));
        assertTrue(WritelogImport.looksLikeWritelog(
                "# a comment\n\n0.5 0 6665 sonar 0 1 1 1 0.5\n".getBytes(StandardCharsets.ISO_8859_1)));
        assertFalse(WritelogImport.looksLikeWritelog(
                "{\"format\":\"player-trace\",\"version\":1}\n".getBytes(StandardCharsets.ISO_8859_1)));
        assertFalse(WritelogImport.looksLikeWritelog(new byte[] { (byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n' }));
        assertFalse(WritelogImport.looksLikeWritelog("hello world, this is text\n".getBytes(StandardCharsets.ISO_8859_1)));
        assertFalse(WritelogImport.looksLikeWritelog(new byte[0]));
    }

    @Test
    void noteLineAppliesToTheNextLineOnly() throws IOException {
        List<LogProblem> problems = new ArrayList<>();
        List<WritelogRecord> r = readAll("""
                # stagecraft-note no-intensities
                1.0 0 6665 laser 0 1 1 0 -1.0 1.0 0.5 8.0 2 1.0 0 2.0 0
                1.1 0 6665 laser 0 1 1 0 -1.0 1.0 0.5 8.0 2 1.0 0 2.0 0
                """, problems);
        assertEquals(0, ((Laser.Scan) r.get(0).body()).intensityCount());
        assertEquals(2, ((Laser.Scan) r.get(1).body()).intensityCount());
    }
}
