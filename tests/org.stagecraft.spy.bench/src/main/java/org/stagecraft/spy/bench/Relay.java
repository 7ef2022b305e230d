package org.stagecraft.spy.bench;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.List;

/** What stands between the robot programs and Player in one benchmark configuration. */
interface Relay extends AutoCloseable {
    String name();

    /** Starts relaying to each upstream address; returns where clients connect, in the same order. */
    List<InetSocketAddress> start(List<InetSocketAddress> upstreams) throws IOException;

    /** Anything the relay wants to report after a run (losses, log size). */
    default String report() {
        return "";
    }

    @Override
    void close() throws IOException;
}
