package org.stagecraft.core.streams;

import org.stagecraft.streams.StreamBus;

/**
 * The stream bus of the running workbench: whatever observes a robot (the Network Spy of a Robot Session,
 * a log replay) publishes here, and the views subscribe here. One per workbench, created on first use;
 * consumers run on virtual threads, so a view hops to its UI thread itself.
 */
public final class WorkbenchBus {
    private static StreamBus bus;

    private WorkbenchBus() {
    }

    public static synchronized StreamBus get() {
        if (bus == null || bus.isClosed()) {
            bus = new StreamBus();
        }
        return bus;
    }
}
