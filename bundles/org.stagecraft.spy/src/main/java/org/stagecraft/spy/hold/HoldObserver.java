package org.stagecraft.spy.hold;

/**
 * Where a {@link RobotHold} reports what it does, for the log and the bus. Called on the thread that
 * acted (a relay thread or the one that called hold/release); implementations only enqueue.
 */
public interface HoldObserver {
    void action(HoldAction action);

    void state(HoldState state);

    HoldObserver NONE = new HoldObserver() {
        @Override
        public void action(HoldAction action) {
        }

        @Override
        public void state(HoldState state) {
        }
    };
}
