package org.stagecraft.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

/**
 * Issue 17 item 4 from a view's side: when the connection of a robot program closes and the bus
 * releases its streams, a layer showing them keeps its last data (the robot's last scan stays drawn),
 * and a view opened afterwards still starts from the last messages the workbench kept.
 */
class ReleasedStreamsTest {
    private static final String CLIENT = "127.0.0.1:40000";
    private static final StreamKey LASER = new StreamKey("127.0.0.1:6665", CLIENT, 1, 6, 0, 1);

    @Test
    void aLayerKeepsTheLastScanOfAConnectionThatClosed() {
        try (StreamBus bus = new StreamBus(Runnable::run)) {
            LastMessages.of(bus);
            LayerFeed layer = new LayerFeed(() -> {
            }).subscribe(bus, StreamPattern.any().deviceType(6));
            bus.publish(new StreamMessage(LASER, 1, "scan 1"));
            bus.publish(new StreamMessage(LASER, 2, "last scan"));

            assertEquals(1, bus.release(CLIENT)); // the robot program disconnected
            assertTrue(bus.streams().isEmpty(), "the bus forgot the stream");

            assertEquals(List.of(new StreamMessage(LASER, 2, "last scan")), layer.snapshot(), "the view still shows it");
            LayerFeed opened = new LayerFeed(() -> {
            }).subscribe(bus, StreamPattern.any().deviceType(6));
            assertEquals(List.of(new StreamMessage(LASER, 2, "last scan")), opened.snapshot(),
                    "a view opened after the close starts from the last scan too");
            layer.close();
            opened.close();
        }
    }
}
