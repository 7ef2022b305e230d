package org.stagecraft.streams;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class StreamPatternTest {
    private static final StreamKey SONAR_DATA = new StreamKey("127.0.0.1:6665", "127.0.0.1:40312", 1, 5, 0, 1);
    private static final StreamKey LASER_CMD = new StreamKey("10.0.0.7:40999", "10.0.0.2:6666", 2, 6, 1, 3);

    @Test
    void anyMatchesEverything() {
        assertTrue(StreamPattern.any().matches(SONAR_DATA));
        assertTrue(StreamPattern.any().matches(LASER_CMD));
    }

    @Test
    void eachFieldFilters() {
        StreamPattern any = StreamPattern.any();
        assertTrue(any.messageType(1).matches(SONAR_DATA));
        assertFalse(any.messageType(1).matches(LASER_CMD));
        assertTrue(any.deviceType(6).matches(LASER_CMD));
        assertFalse(any.deviceType(6).matches(SONAR_DATA));
        assertTrue(any.index(1).matches(LASER_CMD));
        assertFalse(any.index(1).matches(SONAR_DATA));
        assertTrue(any.subtype(3).matches(LASER_CMD));
        assertFalse(any.subtype(3).matches(SONAR_DATA));
        assertTrue(any.deviceType(5).messageType(1).index(0).subtype(1).matches(SONAR_DATA));
        assertFalse(any.deviceType(5).messageType(1).index(0).subtype(2).matches(SONAR_DATA));
        assertTrue(StreamPattern.exactly(SONAR_DATA).matches(SONAR_DATA));
        assertFalse(StreamPattern.exactly(SONAR_DATA).matches(SONAR_DATA.withSubtype(2)));
    }

    @Test
    void addressGlobs() {
        assertTrue(StreamPattern.any().destination("*:40312").matches(SONAR_DATA));
        assertTrue(StreamPattern.any().source("*:6665").matches(SONAR_DATA));
        assertFalse(StreamPattern.any().source("*:666").matches(SONAR_DATA)); // the glob is anchored
        assertFalse(StreamPattern.any().source("*:66650").matches(SONAR_DATA));
        assertTrue(StreamPattern.any().source("127.0.0.1:*").matches(SONAR_DATA));
        assertFalse(StreamPattern.any().source("127.0.0.1:*").matches(LASER_CMD));
        assertTrue(StreamPattern.any().source("10.*.7:*9").matches(LASER_CMD));
        assertTrue(StreamPattern.any().source("*0*0*").matches(LASER_CMD));
        assertTrue(StreamPattern.any().source("10.0.0.7:40999").matches(LASER_CMD));
        assertFalse(StreamPattern.any().source("10.0.0.7:4099").matches(LASER_CMD));
        assertFalse(StreamPattern.any().destination("*:6665").matches(SONAR_DATA)); // that is its source
    }

    @Test
    void patternsAreImmutable() {
        StreamPattern base = StreamPattern.any().deviceType(5);
        StreamPattern narrower = base.subtype(2);
        assertTrue(base.matches(SONAR_DATA));
        assertFalse(narrower.matches(SONAR_DATA));
        assertEquals("src=* dst=* type=* dev=5 index=* subtype=*", base.toString());
    }

    @Test
    void textFormRoundTrips() {
        StreamPattern p = StreamPattern.any().destination("*:6665").messageType(1).deviceType(6).subtype(1);
        assertEquals("src=* dst=*:6665 type=1 dev=6 index=* subtype=1", p.toString());
        assertEquals(p, StreamPattern.parse(p.toString()));
        assertEquals(p.toString(), StreamPattern.parse("src=* dst=*:6665 type=1 dev=6 index=* subtype=1").toString());
        for (String text : new String[] {"src=* dst=* type=* dev=* index=* subtype=*",
                "src=127.0.0.1:* dst=*:6665 type=128 dev=65535 index=7 subtype=255"}) {
            assertEquals(text, StreamPattern.parse(text).toString());
        }
    }

    @Test
    void parseAcceptsAnyOrderAndMissingFields() {
        assertEquals(StreamPattern.any(), StreamPattern.parse(""));
        assertEquals(StreamPattern.any(), StreamPattern.parse("   "));
        assertEquals(StreamPattern.any().deviceType(5).messageType(1), StreamPattern.parse("  dev=5\ttype=1 "));
        assertTrue(StreamPattern.parse("dst=*:40312 dev=5").matches(SONAR_DATA));
    }

    @ParameterizedTest
    @ValueSource(strings = {"type=x", "dev=70000", "bogus=1", "src", "=5", "index=", "subtype=-1", "type=1.5"})
    void badTokensAreNamed(String bad) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> StreamPattern.parse("src=* " + bad + " dev=6"));
        assertTrue(e.getMessage().contains("'" + bad + "'"), e.getMessage());
    }

    @Test
    void repeatedFieldIsRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> StreamPattern.parse("dev=5 dev=6"));
        assertTrue(e.getMessage().contains("'dev=6'") && e.getMessage().contains("repeats"), e.getMessage());
    }

    @Test
    void builderChecksRanges() {
        assertThrows(IllegalArgumentException.class, () -> StreamPattern.any().messageType(256));
        assertThrows(IllegalArgumentException.class, () -> StreamPattern.any().index(-1));
        assertThrows(IllegalArgumentException.class, () -> StreamPattern.any().source("a b"));
        assertThrows(IllegalArgumentException.class, () -> StreamPattern.any().destination(""));
    }
}
