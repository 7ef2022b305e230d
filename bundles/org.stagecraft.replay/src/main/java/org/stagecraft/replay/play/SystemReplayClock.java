package org.stagecraft.replay.play;

import java.util.concurrent.locks.LockSupport;

/** {@link ReplayClock} on {@link System#nanoTime()}. */
final class SystemReplayClock implements ReplayClock {
    static final SystemReplayClock INSTANCE = new SystemReplayClock();

    @Override
    public long nanoTime() {
        return System.nanoTime();
    }

    @Override
    public void sleepUntil(long deadlineNanos) throws InterruptedException {
        long left;
        while ((left = deadlineNanos - System.nanoTime()) > 0) {
            LockSupport.parkNanos(left);
            if (Thread.interrupted()) {
                throw new InterruptedException();
            }
        }
    }
}
