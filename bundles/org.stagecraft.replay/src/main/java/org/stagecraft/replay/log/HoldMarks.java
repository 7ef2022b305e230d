package org.stagecraft.replay.log;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.log.HoldEntry;

/**
 * A log's robot holds, shaped for the Session Log editor: the spans during which robots were held and the
 * simulated world was frozen (for the timeline), the instants of injected and held-back messages, and which of the program's messages
 * were held back (for the inspector, which lists what the program sent).
 */
public final class HoldMarks {
    /** A time the robots were held, with the reasons the log gave. */
    public record Span(long startNanos, long endNanos, String text) {
    }

    private final List<Span> spans;
    private final List<Span> frozen;
    private final List<Long> injected = new ArrayList<>();
    private final List<Long> heldBack = new ArrayList<>();
    private final Set<Long> heldBackMessages = new HashSet<>();
    private final List<Long> breaks = new ArrayList<>();
    private final Set<Long> breakMessages = new HashSet<>();

    /** Pairs starts with ends into spans: a second start before an end is ignored, an open span runs to the log's end. */
    private static final class Spans {
        private final List<Span> done = new ArrayList<>();
        private long start = Long.MIN_VALUE;
        private String text = "";

        void start(HoldEntry e) {
            if (start == Long.MIN_VALUE) {
                start = e.timeNanos();
                text = e.text();
            }
        }

        void end(long t) {
            if (start != Long.MIN_VALUE) {
                done.add(new Span(start, Math.max(start, t), text));
                start = Long.MIN_VALUE;
            }
        }

        List<Span> finish(long endNanos) {
            end(endNanos); // the log ended while it was on
            return List.copyOf(done);
        }
    }

    /** @param endNanos where a hold still on at the end of the log is drawn to */
    public HoldMarks(List<HoldEntry> entries, long endNanos) {
        Spans held = new Spans();
        Spans frozenWorld = new Spans();
        for (HoldEntry e : entries) {
            switch (e.action()) {
                case WORLD_FROZEN -> frozenWorld.start(e);
                case WORLD_THAWED -> frozenWorld.end(e.timeNanos());
                case HOLD_ON -> held.start(e);
                case HOLD_OFF -> held.end(e.timeNanos());
                case INJECTED -> injected.add(e.timeNanos());
                case BREAK -> {
                    breaks.add(e.timeNanos());
                    breakMessages.add(key(e.conn(), e.programOffset()));
                }
                case PASSED_ON -> {
                    // the end of what a BREAK held back: the BREAK is the mark
                }
                case HELD_BACK -> {
                    heldBack.add(e.timeNanos());
                    heldBackMessages.add(key(e.conn(), e.programOffset()));
                }
            }
        }
        spans = held.finish(endNanos);
        frozen = frozenWorld.finish(endNanos);
    }

    public static HoldMarks none() {
        return new HoldMarks(List.of(), 0);
    }

    public List<Span> spans() {
        return spans;
    }

    /** The times the session's simulated world stood still (docs/debugging-robots.md, "The frozen world"). */
    public List<Span> frozenSpans() {
        return frozen;
    }

    public List<Long> injectedTimes() {
        return List.copyOf(injected);
    }

    public List<Long> heldBackTimes() {
        return List.copyOf(heldBack);
    }

    /** When robot data breakpoints held. */
    public List<Long> breakTimes() {
        return List.copyOf(breaks);
    }

    /** Whether this log message is a Player message on which a robot data breakpoint held. */
    public boolean triggeredBreak(LogMessage m) {
        return m.connection() != null && m.dir() == Direction.SERVER_TO_CLIENT
                && breakMessages.contains(key(m.connection().id(), m.streamOffset()));
    }

    /** Whether this log message is a program message the hold kept from Player. */
    public boolean heldBack(LogMessage m) {
        return m.connection() != null && m.dir() == Direction.CLIENT_TO_SERVER
                && heldBackMessages.contains(key(m.connection().id(), m.streamOffset()));
    }

    public boolean isEmpty() {
        return spans.isEmpty() && frozen.isEmpty() && injected.isEmpty() && heldBack.isEmpty() && breaks.isEmpty();
    }

    private static long key(int conn, long offset) {
        return ((long) conn << 48) ^ offset; // offsets stay far below 2^48 bytes
    }
}
