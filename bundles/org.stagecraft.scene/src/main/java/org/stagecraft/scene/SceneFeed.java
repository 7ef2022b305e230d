package org.stagecraft.scene;

import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Sonar;
import org.stagecraft.player.wire.MessageType;
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
    public static final StreamPattern POSES = data(Position2d.CODE, Position2d.DATA_STATE);
    /** Every RESP_ACK: the model keeps the GET_GEOM and ranger GET_CONFIG replies among them. */
    public static final StreamPattern REPLIES = StreamPattern.any().messageType(MessageType.RESP_ACK.code());

    private final List<Subscription> subscriptions = new ArrayList<>();

    public SceneFeed(StreamBus bus, WorldModel world, Runnable onChange) {
        subscriptions.add(bus.subscribe(POSES, DeliveryPolicy.latestValue(), m -> {
            if (world.accept(m)) {
                onChange.run();
            }
        }));
        for (StreamPattern p : new StreamPattern[] { REPLIES,
                data(Position2d.CODE, Position2d.DATA_GEOM), data(Sonar.CODE, Sonar.DATA_GEOM),
                data(Ranger.CODE, Ranger.DATA_GEOM) }) {
            subscriptions.add(bus.subscribe(p, DeliveryPolicy.lossless(1024), m -> {
                if (world.accept(m)) {
                    onChange.run();
                }
            }));
        }
    }

    private static StreamPattern data(int interf, int subtype) {
        return StreamPattern.any().messageType(MessageType.DATA.code()).deviceType(interf).subtype(subtype);
    }

    @Override
    public void close() {
        subscriptions.forEach(Subscription::close);
    }
}
