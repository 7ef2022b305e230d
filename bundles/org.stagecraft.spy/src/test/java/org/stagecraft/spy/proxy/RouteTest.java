package org.stagecraft.spy.proxy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** A route must lead somewhere else than the spy itself. */
class RouteTest {
    @Test
    void aRouteToItsOwnListenAddressIsRefusedInEverySpelling() {
        for (String[] r : new String[][] {{"127.0.0.1", "127.0.0.1"}, {"127.0.0.1", "localhost"}, {"0.0.0.0", "127.0.0.1"},
                {"127.0.0.1", "0.0.0.0"}, {"0.0.0.0", "localhost"}}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> Route.of(r[0], 6665, r[1], 6665), r[0] + " -> " + r[1]);
            assertTrue(e.getMessage().contains("leads back to the spy itself"), e.getMessage());
            assertTrue(e.getMessage().contains(":6665 -> "), e.getMessage());
        }
    }

    @Test
    void otherPortsOrAnEphemeralListenPortAreFine() {
        assertEquals(7665, Route.of("127.0.0.1", 6665, "localhost", 7665).upstream().getPort());
        assertEquals(0, Route.loopback(0, "127.0.0.1", 6665).listen().getPort());
        // another loopback address is another socket: no loop
        assertEquals(6665, Route.of("127.0.0.1", 6665, "127.0.0.2", 6665).upstream().getPort());
    }
}
