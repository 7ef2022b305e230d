package org.stagecraft.spy.hold;

/**
 * Told when a spy's robot hold changes (enabled, held, reasons). Called on the thread that made the
 * change, after the spy has acted on it; must return quickly (a UI posts to its own thread).
 */
@FunctionalInterface
public interface HoldListener {
    void holdChanged(HoldState state);
}
