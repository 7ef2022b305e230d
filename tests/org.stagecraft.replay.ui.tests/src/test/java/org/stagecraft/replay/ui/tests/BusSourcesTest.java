package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.stagecraft.core.streams.BusSources;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.streams.StreamBus;

class BusSourcesTest {
    @Test
    void liveAlwaysFirstOthersComeAndGoWithNotice() throws Exception {
        assertEquals(BusSources.LIVE, BusSources.all().get(0).id());
        assertSame(WorkbenchBus.get(), BusSources.find(BusSources.LIVE).orElseThrow().bus());
        AtomicInteger changes = new AtomicInteger();
        try (AutoCloseable l = BusSources.listen(changes::incrementAndGet); StreamBus bus = new StreamBus()) {
            AutoCloseable reg = BusSources.add(new BusSources.Source("test:a", "A", bus));
            assertEquals(1, changes.get());
            assertSame(bus, BusSources.find("test:a").orElseThrow().bus());
            assertTrue(BusSources.all().stream().anyMatch(s -> s.id().equals("test:a")));
            assertThrows(IllegalArgumentException.class, () -> BusSources.add(new BusSources.Source("test:a", "again", bus)));
            assertThrows(IllegalArgumentException.class, () -> BusSources.add(new BusSources.Source(BusSources.LIVE, "x", bus)));
            reg.close();
            reg.close(); // twice is harmless
            assertEquals(2, changes.get());
            assertTrue(BusSources.find("test:a").isEmpty());
        }
    }
}
