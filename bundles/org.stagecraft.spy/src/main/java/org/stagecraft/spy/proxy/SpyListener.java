package org.stagecraft.spy.proxy;

/**
 * Hears the spy's {@link SpyNotice}s. Called on a relay thread: implementations hand the notice on
 * (print it, post it to a UI thread) and return; an exception is counted and ignored, like an
 * observer's.
 */
@FunctionalInterface
public interface SpyListener {
    void notice(SpyNotice notice);
}
