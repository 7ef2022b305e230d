package org.stagecraft.spy.bench;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.List;

/** What stands between the robot programs and Player in one benchmark configuration. */
interface Relay extends AutoCloseable {
    String name();

    /** Starts relaying to each upstream address; returns where clients connect, in the same order. */
    List<InetSocketAddress> start(List<InetSocketAddress> upstreams) throws IOException;

    /** The processes doing the relaying (for CPU time and memory), empty when none of its own. */
    default java.util.List<Long> pids() {
        return java.util.List.of();
    }

    /** Forwarded bytes the relay did not observe in the last run (after close), or -1 when it observes nothing. */
    default long unobservedBytes() {
        return -1;
    }

    /** Anything the relay wants to report after a run (losses, log size). */
    default String report() {
        return "";
    }

    @Override
    void close() throws IOException;
}
