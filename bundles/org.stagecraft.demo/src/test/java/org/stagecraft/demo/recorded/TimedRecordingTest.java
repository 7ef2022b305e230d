package org.stagecraft.demo.recorded;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.play.RecordingException;
import org.stagecraft.recording.play.TimedChunk;
import org.stagecraft.recording.play.TimedConnection;
import org.stagecraft.recording.play.TimedRecording;

class TimedRecordingTest {
    @TempDir
    Path tmp;

    @Test
    void theShippedRecordingIsOneConnectionOfThirtySecondsWithTheBannerFirst() throws Exception {
        TimedRecording r = TimedRecording.read(DemoFiles.recording());
        assertEquals(1, r.connections().size());
        TimedConnection c = r.connections().get(0);
        // open at 0.314788, close at 30.759267 in the trace
        assertEquals(30.759267 - 0.314788, c.length(), 1e-9);
        assertEquals(32, c.server().get(0).data().length, "Player's ident banner");
        assertEquals(0.332571 - 0.314788, c.server().get(0).offset(), 1e-9);
        assertNonDecreasing(c.server());
        assertNonDecreasing(c.client());
        RecordedConnection same = RecordedConnection.read(DemoFiles.recording()).get(0);
        assertArrayEquals(same.clientBytes(), c.clientBytes(), "the same bytes as the untimed reader");
        assertArrayEquals(same.serverBytes(), c.serverBytes());
    }

    private static void assertNonDecreasing(List<TimedChunk> chunks) {
        for (int i = 1; i < chunks.size(); i++) {
            assertTrue(chunks.get(i).offset() >= chunks.get(i - 1).offset(), "chunk " + i + " is in recorded order");
        }
    }

    @Test
    void aMissingRecordingIsNamed() {
        Path missing = tmp.resolve("nowhere.trace.jsonl");
        RecordingException e = assertThrows(RecordingException.class, () -> TimedRecording.read(missing));
        assertEquals("the recording " + missing + " does not exist", e.getMessage());
    }

    @Test
    void aRecordingCutOffMidLineIsRefusedWithItsFileAndLine() throws Exception {
        List<String> lines = Files.readAllLines(DemoFiles.recording(), StandardCharsets.UTF_8);
        String cut = String.join("\n", lines.subList(0, 99)) + "\n" + lines.get(99).substring(0, 40);
        Path file = Files.writeString(tmp.resolve("cut.trace.jsonl"), cut);
        RecordingException e = assertThrows(RecordingException.class, () -> TimedRecording.read(file));
        assertTrue(e.getMessage().startsWith("the recording is corrupt: " + file + ":100: not valid JSON"), e.getMessage());
    }

    @Test
    void aFileThatIsNoRecordingSaysWhatWasExpected() throws Exception {
        Path file = Files.writeString(tmp.resolve("notes.txt"), "{\"hello\":1}\n");
        RecordingException e = assertThrows(RecordingException.class, () -> TimedRecording.read(file));
        assertTrue(e.getMessage().contains(file + ":1: expected a header with \"format\":\"player-trace\""), e.getMessage());
    }

    @Test
    void aRecordingWithoutPlayerTrafficIsRefused() throws Exception {
        Path file = Files.writeString(tmp.resolve("empty.trace.jsonl"), Files.readAllLines(DemoFiles.recording()).get(0) + "\n");
        RecordingException e = assertThrows(RecordingException.class, () -> TimedRecording.read(file));
        assertEquals("the recording " + file + " holds no connection in which Player sent anything", e.getMessage());
    }
}
