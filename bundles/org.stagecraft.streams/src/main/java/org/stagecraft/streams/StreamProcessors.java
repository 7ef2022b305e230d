package org.stagecraft.streams;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * Starts and stops {@link StreamProcessor}s on one bus (plain Java; in Eclipse
 * {@code org.stagecraft.core.streams.StreamProcessorExtensionRegistry} feeds it from the extension
 * point). Each processor gets a context that tracks its subscriptions, so stopping it closes them.
 */
public final class StreamProcessors {
    private final StreamBus bus;
    private final Map<String, Running> running = new LinkedHashMap<>();

    public StreamProcessors(StreamBus bus) {
        this.bus = Objects.requireNonNull(bus, "bus");
    }

    /**
     * Starts {@code p} under {@code id}. If its {@code start} throws, the subscriptions it made are closed
     * and the exception propagates; the processor is then not running.
     *
     * @throws IllegalArgumentException if a processor with this id is running
     */
    public void start(String id, StreamProcessor p) {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(p, "processor");
        if (id.isBlank()) {
            throw new IllegalArgumentException("processor id is blank");
        }
        Context ctx;
        synchronized (running) {
            if (running.containsKey(id)) {
                throw new IllegalArgumentException("a stream processor with id '" + id + "' is already running");
            }
            ctx = new Context(id);
            running.put(id, new Running(p, ctx));
        }
        try {
            p.start(ctx);
        } catch (RuntimeException | LinkageError e) {
            synchronized (running) {
                running.remove(id);
            }
            ctx.closeAll();
            throw e;
        }
    }

    /** Stops the processor {@code id}; false if none runs under it. */
    public boolean stop(String id) {
        Running r;
        synchronized (running) {
            r = running.remove(id);
        }
        if (r == null) {
            return false;
        }
        r.stop();
        return true;
    }

    /** Stops every processor, newest first; a processor whose stop throws is still stopped. */
    public void stopAll() {
        List<Running> all;
        synchronized (running) {
            all = new ArrayList<>(running.values());
            running.clear();
        }
        for (int i = all.size() - 1; i >= 0; i--) {
            all.get(i).stop();
        }
    }

    /** Ids of the running processors, in start order. */
    public Set<String> ids() {
        synchronized (running) {
            return Collections.unmodifiableSet(new LinkedHashSet<>(running.keySet()));
        }
    }

    public StreamBus bus() {
        return bus;
    }

    /**
     * The processors listed in {@code META-INF/services/org.stagecraft.streams.StreamProcessor} on the
     * class path (new instances on every call). A provider that cannot be loaded is skipped.
     */
    public static List<StreamProcessor> serviceLoaded() {
        List<StreamProcessor> found = new ArrayList<>();
        ServiceLoader<StreamProcessor> loader = ServiceLoader.load(StreamProcessor.class,
                StreamProcessor.class.getClassLoader());
        var it = loader.iterator();
        while (true) {
            try {
                if (!it.hasNext()) {
                    break;
                }
                found.add(it.next());
            } catch (ServiceConfigurationError e) {
                // a broken provider: skip it, keep the others
            }
        }
        return found;
    }

    private record Running(StreamProcessor processor, Context ctx) {
        void stop() {
            try {
                processor.stop();
            } catch (RuntimeException | LinkageError e) {
                // stopped anyway: its subscriptions are closed below
            } finally {
                ctx.closeAll();
            }
        }
    }

    private final class Context implements ProcessorContext {
        private final String id;
        private final List<Subscription> subscriptions = new CopyOnWriteArrayList<>();
        private volatile boolean stopped;

        Context(String id) {
            this.id = id;
        }

        @Override
        public StreamBus bus() {
            return bus;
        }

        @Override
        public Subscription subscribe(StreamPattern p, DeliveryPolicy d, StreamConsumer c) {
            if (stopped) {
                throw new IllegalStateException("stream processor '" + id + "' is stopped");
            }
            Subscription s = bus.subscribe(p, d, c);
            subscriptions.add(s);
            if (stopped) { // stopped concurrently
                s.close();
            }
            return s;
        }

        @Override
        public void publish(StreamMessage derived) {
            int type = derived.key().messageType();
            if (type < StreamTypes.USER_MIN) {
                throw new IllegalArgumentException("stream processor '" + id + "' may only publish user-defined"
                        + " message types " + StreamTypes.USER_MIN + ".." + StreamTypes.USER_MAX + ", not " + type);
            }
            if (!stopped) {
                bus.publish(derived);
            }
        }

        @Override
        public String processorId() {
            return id;
        }

        void closeAll() {
            stopped = true;
            for (Subscription s : subscriptions) {
                s.close();
            }
            subscriptions.clear();
        }
    }
}
