package org.stagecraft.core.streams;

import java.util.Set;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamConsumer;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.StreamProcessors;
import org.stagecraft.streams.Subscription;

/**
 * The stream bus of the running workbench: whatever observes a robot (the Network Spy of a Robot Session,
 * a log replay) publishes here, and the views subscribe here. One per workbench, created on first use with
 * every contributed stream processor running on it ({@link Contributions#startProcessors}), so a derived
 * stream appears for a live robot as it does in a replay; consumers run on the bus's own threads, so a view hops
 * to its UI thread itself.
 */
public final class WorkbenchBus {
    private static @Nullable StreamBus bus;
    private static @Nullable StreamProcessors processors;

    private WorkbenchBus() {
    }

    /** How many messages of a forwarded bus may wait for the workbench bus before some are dropped (and counted). */
    public static final int FORWARD_CAPACITY = 1 << 16;

    /**
     * Republishes everything {@code source} carries (e.g. a Robot Session's own bus, fed by its spy) on the
     * workbench bus, in order and lossless up to {@value #FORWARD_CAPACITY} waiting messages, so that the
     * views and the processors see it. Streams {@code source} releases (closed connections) are released on the workbench bus
     * too, after their last forwarded message. Close the result to stop.
     */
    public static Subscription forward(StreamBus source) {
        StreamBus target = get();
        return source.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(FORWARD_CAPACITY), new StreamConsumer() {
            @Override
            public void accept(StreamMessage m) {
                target.publish(m);
            }

            @Override
            public void released(String address, Set<StreamKey> streams) {
                target.release(address);
            }
        });
    }

    /** The bus, with the contributed processors started on it; a new one (and new processors) if the last was closed. */
    public static synchronized StreamBus get() {
        StreamBus b = bus;
        if (b == null || b.isClosed()) {
            if (processors != null) {
                processors.stopAll(); // their bus is gone; stop() frees what else they hold
            }
            b = new StreamBus();
            bus = b;
            processors = Contributions.workbench().startProcessors(b);
        }
        return b;
    }

    /** The ids of the processors running on the workbench bus. */
    public static synchronized java.util.Set<String> processorIds() {
        get();
        return processors.ids();
    }
}
