package org.stagecraft.scene;

import java.util.ArrayList;
import java.util.List;

import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/**
 * Keeps a {@link WorldModel} up to date from a bus: poses latest-value (a skipped pose only makes the
 * trail coarser), geometry and configuration replies lossless (they come once per connection and
 * must not be lost).
 */
public final class SceneFeed implements AutoCloseable {
    /** position2d DATA STATE of every robot. */
    public static final StreamPattern POSES = StreamPattern.any().messageType(WorldModel.DATA).deviceType(4)
            .subtype(WorldModel.POSITION_STATE);
    /** Every RESP_ACK: the model keeps the GET_GEOM and ranger GET_CONFIG replies among them. */
    public static final StreamPattern REPLIES = StreamPattern.any().messageType(WorldModel.RESP_ACK);

    private final List<Subscription> subscriptions = new ArrayList<>();

    public SceneFeed(StreamBus bus, WorldModel world, Runnable onChange) {
        subscriptions.add(bus.subscribe(POSES, DeliveryPolicy.latestValue(), m -> {
            if (world.accept(m)) {
                onChange.run();
            }
        }));
        for (StreamPattern p : new StreamPattern[] { REPLIES,
                StreamPattern.any().messageType(WorldModel.DATA).deviceType(4).subtype(WorldModel.POSITION_DATA_GEOM),
                StreamPattern.any().messageType(WorldModel.DATA).deviceType(5).subtype(WorldModel.SONAR_DATA_GEOM),
                StreamPattern.any().messageType(WorldModel.DATA).deviceType(62).subtype(WorldModel.RANGER_DATA_GEOM) }) {
            subscriptions.add(bus.subscribe(p, DeliveryPolicy.lossless(1024), m -> {
                if (world.accept(m)) {
                    onChange.run();
                }
            }));
        }
    }

    @Override
    public void close() {
        subscriptions.forEach(Subscription::close);
    }
}
