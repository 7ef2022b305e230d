package org.stagecraft.tools.session;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.RobotHold;
import org.stagecraft.spy.proxy.NetworkSpy;
import org.stagecraft.tools.process.Recorder;
import org.stagecraft.tools.process.RestartPolicy;

/** The session's spy options reach the spy before it accepts the first robot program. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SessionSpyOptionsTest {
    private static final Duration WAIT = Duration.ofSeconds(30);

    @TempDir
    Path tmp;

    private SessionConfig config(int port, SpyOptions spy) {
        SessionConfig c = SessionConfig.of(Worlds.file("pioneer-laser-sonar.cfg")).withDefaultPort(port)
                .withPlayer(List.of("python3", Worlds.standIn().toString()),
                        Map.of("STANDIN_TRACE", Worlds.traces().resolve("pioneer-laser-sonar.gt.trace.jsonl").toString()))
                .withPlayerRestart(RestartPolicy.NEVER, WAIT).withScratchRoot(tmp.resolve("scratch"));
        return spy == null ? c : c.withSpyOptions(spy);
    }

    /** Polls state another thread changes (the spy's accept thread); there is no event to wait on. */
    private static void await(String what, java.util.function.BooleanSupplier condition) {
        long deadline = System.nanoTime() + WAIT.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out waiting until " + what);
            }
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(10));
        }
    }

    @Test
    void defaultsHoldWhenSuspendedWithoutWatchdogAndTheSpysGrace() {
        SessionConfig c = config(6665, null);
        assertEquals(SpyOptions.DEFAULT, c.spy());
        assertTrue(c.spy().holdWhenSuspended());
        assertNull(c.spy().watchdog());
        assertEquals(NetworkSpy.DEFAULT_UPSTREAM_GRACE, c.spy().upstreamGrace());
        assertNull(SpyOptions.DEFAULT.withWatchdog(Duration.ZERO).watchdog(), "zero is off, spelled as null");
        assertFalse(SpyOptions.DEFAULT.withHoldWhenSuspended(false).holdsEnabled());
        assertTrue(SpyOptions.DEFAULT.withHoldWhenSuspended(false).withWatchdog(Duration.ofSeconds(1)).holdsEnabled(),
                "the watchdog alone enables holds (and so the emergency stop)");
        assertThrows(IllegalArgumentException.class, () -> SpyOptions.DEFAULT.withUpstreamGrace(Duration.ofSeconds(-1)));
        assertEquals(c.withLog(tmp).spy(), c.spy(), "the other with-methods keep the options");
    }

    @Test
    void holdsAreEnabledBeforeTheFirstProgramConnectsAndTheWatchdogAndGraceAreSet() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        SpyOptions options = new SpyOptions(Duration.ofSeconds(2), true, Duration.ofMillis(750), false);
        try (RobotSession session = RobotSession.start(config(port, options), new Recorder());
                Socket program = new Socket(InetAddress.getLoopbackAddress(), port)) {
            RobotHold holds = session.holds();
            assertTrue(holds.isEnabled());
            assertEquals(Duration.ofMillis(750), holds.watchdog());
            assertEquals(Duration.ofSeconds(2), session.spy().upstreamGrace());
            await("the program's connection is holdable", () -> holds.forwarders().size() == 1);
            holds.hold(HoldReason.SUSPENDED);
            assertTrue(holds.isHeld());
            assertTrue(holds.release(HoldReason.SUSPENDED));
            assertFalse(holds.isHeld());
        }
    }

    @Test
    void withoutHoldsOrWatchdogTheSpyStaysThePlainByteCopy() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        SpyOptions options = SpyOptions.DEFAULT.withHoldWhenSuspended(false);
        try (RobotSession session = RobotSession.start(config(port, options), new Recorder());
                Socket program = new Socket(InetAddress.getLoopbackAddress(), port)) {
            assertFalse(session.holds().isEnabled());
            await("the spy accepted the program", () -> session.spy().totalConnections() == 1);
            assertEquals(List.of(), session.holds().forwarders(), "a connection accepted with holds off cannot be held");
            session.holds().hold(HoldReason.EMERGENCY_STOP);
            assertFalse(session.holds().isHeld(), "holds off: nothing is held, whatever is asked");
        }
    }
}
