package org.stagecraft.spy.bench;

import java.net.InetSocketAddress;
import java.util.List;

/** No relay: clients connect to the upstream itself. The baseline every relay is compared with. */
final class DirectConnection implements Relay {
    @Override
    public String name() {
        return "direct";
    }

    @Override
    public List<InetSocketAddress> start(List<InetSocketAddress> upstreams) {
        return upstreams;
    }

    @Override
    public void close() {
    }
}
