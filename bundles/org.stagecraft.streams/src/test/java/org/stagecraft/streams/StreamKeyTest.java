package org.stagecraft.streams;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.stagecraft.streams.Streams.PLAYER;
import static org.stagecraft.streams.Streams.ROBOT;

import org.junit.jupiter.api.Test;

class StreamKeyTest {

    @Test
    void fieldsAreRangeChecked() {
        new StreamKey(PLAYER, ROBOT, 255, 65535, 65535, 255); // the maxima are valid
        new StreamKey(PLAYER, ROBOT, 0, 0, 0, 0);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new StreamKey(PLAYER, ROBOT, 256, 1, 0, 0))
                .getMessage().contains("messageType 256"));
        assertThrows(IllegalArgumentException.class, () -> new StreamKey(PLAYER, ROBOT, -1, 1, 0, 0));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new StreamKey(PLAYER, ROBOT, 1, 65536, 0, 0))
                .getMessage().contains("deviceType"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new StreamKey(PLAYER, ROBOT, 1, 1, -3, 0))
                .getMessage().contains("index"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new StreamKey(PLAYER, ROBOT, 1, 1, 0, 256))
                .getMessage().contains("subtype"));
        assertThrows(NullPointerException.class, () -> new StreamKey(null, ROBOT, 1, 1, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new StreamKey(PLAYER, " ", 1, 1, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new StreamKey("a b", ROBOT, 1, 1, 0, 0));
    }

    @Test
    void upperHalfOfMessageTypesIsUserDefined() {
        assertFalse(new StreamKey(PLAYER, ROBOT, 6, 5, 0, 1).isUserDefined());
        assertFalse(new StreamKey(PLAYER, ROBOT, 127, 5, 0, 1).isUserDefined());
        assertTrue(new StreamKey(PLAYER, ROBOT, StreamTypes.USER_MIN, 5, 0, 1).isUserDefined());
        assertTrue(new StreamKey(PLAYER, ROBOT, StreamTypes.USER_MAX, 5, 0, 1).isUserDefined());
        StreamKey derived = new StreamKey(PLAYER, ROBOT, 1, 5, 0, 1).withMessageType(128);
        assertEquals(new StreamKey(PLAYER, ROBOT, 128, 5, 0, 1), derived);
    }

    @Test
    void messageNeedsAKey() {
        assertThrows(NullPointerException.class, () -> new StreamMessage(null, 0, "x"));
        assertEquals(null, new StreamMessage(Streams.data(5, 0, 1), 0, null).payload());
    }

    @Test
    void deliveryPolicies() {
        assertFalse(DeliveryPolicy.latestValue().isLossless());
        assertEquals(16, DeliveryPolicy.lossless(16).capacity());
        assertEquals(DeliveryPolicy.lossless(16), DeliveryPolicy.lossless(16));
        assertEquals("lossless(16)", DeliveryPolicy.lossless(16).toString());
        assertThrows(IllegalArgumentException.class, () -> DeliveryPolicy.lossless(0));
    }
}
