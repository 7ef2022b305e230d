package org.stagecraft.scene;

import java.util.Arrays;
import java.util.EnumMap;
import java.util.stream.Collectors;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.hold.HoldAction;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.spy.hold.HoldStreams;
import org.stagecraft.spy.hold.WorldChange;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/**
 * Whether the robots of a bus are held by their spy, for a view to say so on top of the robots: follows
 * the {@link HoldStreams#STATE} stream, starting from the last state the bus carried (a view opened while
 * the program is suspended shows "HELD" at once), whether the session froze its simulated world
 * ({@link HoldStreams#WORLD}), and the robot data breakpoint that stopped it, with the values it read
 * ({@link HoldStreams#breaks()}) and the reading itself, decoded, for the view to mark ({@link #breakReading()}).
 *
 * <p>One state per bus: every session's spy publishes on the same key, so with two sessions on the
 * workbench bus the newest change wins.
 */
public final class HoldStatus implements AutoCloseable {
    private static final StreamPattern STATE = StreamPattern.exactly(HoldStreams.STATE);
    private static final StreamPattern WORLD = StreamPattern.exactly(HoldStreams.WORLD);
    private static final String BREAK_PREFIX = "robot data breakpoint: ";

    private final Runnable onChange;
    private volatile @Nullable HoldState state;
    private volatile boolean worldFrozen;
    private volatile @Nullable String lastBreak;
    private volatile @Nullable BreakReading lastReading;
    private final PlayerDecoder decoder = new PlayerDecoder(CodecRegistry.standard());
    private final Subscription subscription;
    private final Subscription world;
    private final Subscription breaks;

    /** @param onChange told (on a bus thread) after each change, e.g. to request a redraw */
    public HoldStatus(StreamBus bus, Runnable onChange) {
        this.onChange = onChange;
        LastMessages.find(bus).ifPresent(store -> {
            store.matching(STATE).forEach(m -> state = stateOf(m));
            store.matching(WORLD).forEach(this::acceptWorld);
            store.matching(HoldStreams.breaks()).forEach(this::acceptBreak);
        });
        subscription = bus.subscribe(STATE, DeliveryPolicy.latestValue(), this::accept);
        world = bus.subscribe(WORLD, DeliveryPolicy.latestValue(), m -> {
            acceptWorld(m);
            onChange.run();
        });
        breaks = bus.subscribe(HoldStreams.breaks(), DeliveryPolicy.latestValue(), m -> {
            acceptBreak(m);
            onChange.run();
        });
    }

    private void acceptWorld(StreamMessage m) {
        if (m.payload() instanceof WorldChange c) {
            worldFrozen = c.frozen();
        }
    }

    private void acceptBreak(StreamMessage m) {
        if (m.payload() instanceof HoldAction a) {
            lastBreak = a.text();
            lastReading = readingOf(a);
        }
    }

    private void accept(StreamMessage m) {
        HoldState s = stateOf(m);
        if (s != null) {
            state = s;
            onChange.run();
        }
    }

    private static @Nullable HoldState stateOf(StreamMessage m) {
        return m.payload() instanceof HoldState s ? s : null;
    }

    private @Nullable BreakReading readingOf(HoldAction a) {
        byte[] bytes = a.bytes();
        if (bytes.length < MessageHeader.SIZE) {
            return null;
        }
        DecodedMessage d = decoder.decode(a.header(), Arrays.copyOfRange(bytes, MessageHeader.SIZE, bytes.length));
        return d.hasProblem() ? null
                : new BreakReading(DeviceAddress.of(HoldStreams.actionKey(a)), d.body(), a.decidingFields());
    }

    /**
     * The reading the robot data breakpoint stopped on, while the robots are held for it; null otherwise
     * (nothing held, held for another reason only, or a message that did not decode).
     */
    public @Nullable BreakReading breakReading() {
        HoldState s = state;
        return s != null && s.held() && s.reasons().containsKey(HoldReason.DATA_BREAKPOINT) ? lastReading : null;
    }

    /** The newest state seen, or null if none. */
    public @Nullable HoldState state() {
        return state;
    }

    /** What a view draws over the robots: "HELD (suspended in the debugger)", or null when nothing is held. */
    public @Nullable String overlayText() {
        String held = overlayText(state);
        if (held == null) {
            return null;
        }
        HoldState s = state;
        String b = lastBreak;
        // "; " between the parts: the view's bitmap font has no dash; the reasons already say "robot data breakpoint"
        return held + (worldFrozen ? "; world frozen" : "")
                + (b != null && s != null && s.reasons().containsKey(HoldReason.DATA_BREAKPOINT)
                        ? "; " + (b.startsWith(BREAK_PREFIX) ? b.substring(BREAK_PREFIX.length()) : b) : "");
    }

    public static @Nullable String overlayText(@Nullable HoldState s) {
        if (s == null || !s.held()) {
            return null;
        }
        return "HELD (" + new EnumMap<HoldReason, Integer>(s.reasons()).keySet().stream().map(HoldReason::text)
                .collect(Collectors.joining(", ")) + ")";
    }

    @Override
    public void close() {
        subscription.close();
        world.close();
        breaks.close();
    }
}
