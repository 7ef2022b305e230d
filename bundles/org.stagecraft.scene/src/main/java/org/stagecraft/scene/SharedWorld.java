package org.stagecraft.scene;

import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import org.stagecraft.streams.StreamBus;

/**
 * The world model of a bus, shared by every view of it and fed from the moment it is created. Geometry
 * replies come once per connection, usually before anyone opens a view: a view opened later must still
 * know where the sensors are, so the model lives with the bus, not with a view.
 */
public final class SharedWorld {
    private static final Map<StreamBus, SharedWorld> WORLDS = new IdentityHashMap<>();

    private final WorldModel world = new WorldModel();
    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();
    private final SceneFeed feed;
    private final StreamBus.Registration releases;

    private SharedWorld(StreamBus bus) {
        feed = new SceneFeed(bus, world, () -> listeners.forEach(Runnable::run));
        LastMessages last = LastMessages.of(bus); // the layers of a view opened later start from the newest data, not from nothing
        releases = bus.onRelease((address, keys) -> {
            world.released(keys);
            listeners.forEach(Runnable::run);
        });
        // a view opened in a later session must not start from an earlier session's robots
        listeners.add(new Runnable() {
            private long seen;

            @Override
            public void run() {
                long now = world.forgetting();
                if (now != seen) {
                    seen = now;
                    last.forget(k -> world.forgotten(RobotId.of(k)));
                }
            }
        });
    }

    /** The bus's shared world, created (and subscribed) on first use. */
    public static synchronized SharedWorld of(StreamBus bus) {
        WORLDS.entrySet().removeIf(e -> e.getKey().isClosed() && closeFeed(e.getValue()));
        return WORLDS.computeIfAbsent(bus, SharedWorld::new);
    }

    private static boolean closeFeed(SharedWorld w) {
        w.feed.close();
        w.releases.close();
        return true;
    }

    public WorldModel world() {
        return world;
    }

    /** Tells {@code onChange} (on bus threads) about every change; close the result to stop. */
    public AutoCloseable listen(Runnable onChange) {
        listeners.add(onChange);
        return () -> listeners.remove(onChange);
    }
}
