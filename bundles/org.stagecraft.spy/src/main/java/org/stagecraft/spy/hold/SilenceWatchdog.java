package org.stagecraft.spy.hold;

/**
 * The thread behind {@link RobotHold#setWatchdog}: a few times per timeout it asks every connection
 * whether its program has gone silent while moving. It only reads two volatile fields per connection,
 * so it costs nothing on the wire.
 */
final class SilenceWatchdog implements AutoCloseable {
    private final Thread thread;
    private volatile boolean stopped;

    SilenceWatchdog(RobotHold holds, long timeoutNanos) {
        // a quarter of the timeout: a silent program is caught at most 25 % late
        long periodMillis = Math.max(1, timeoutNanos / 4 / 1_000_000L);
        thread = Thread.ofPlatform().daemon().name("stagecraft-hold-watchdog").start(() -> {
            while (!stopped) {
                try {
                    Thread.sleep(periodMillis);
                } catch (InterruptedException e) {
                    return;
                }
                if (!stopped) {
                    holds.watchdogCheck(holds.nanoTime());
                }
            }
        });
    }

    @Override
    public void close() {
        stopped = true;
        thread.interrupt();
    }
}
