package org.stagecraft.core.streams;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;

import org.stagecraft.streams.StreamBus;

/**
 * The buses a view can follow: the workbench bus ("Live", always there) and one per open log replay
 * (each Session Log editor replays into a bus of its own). Views list them in a "Source" menu,
 * remember a choice by its id and listen for changes: a source that goes away (its editor closed)
 * sends its followers back to Live. Thread-safe; listeners are called on the thread that changed
 * the list.
 */
public final class BusSources {
    /** The id of the workbench bus's entry. */
    public static final String LIVE = "live";

    /**
     * One source.
     *
     * @param id    stable across restarts (for a log: derived from its file), so a view can remember it
     * @param label what the menu shows
     * @param bus   the bus
     */
    public record Source(String id, String label, StreamBus bus) {
        public Source {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(label, "label");
            Objects.requireNonNull(bus, "bus");
        }
    }

    private static final List<Source> ADDED = new CopyOnWriteArrayList<>();
    private static final List<Runnable> LISTENERS = new CopyOnWriteArrayList<>();

    private BusSources() {
    }

    /** The workbench bus's entry. */
    public static Source live() {
        return new Source(LIVE, "Live", WorkbenchBus.get());
    }

    /** Live first, then the others in the order they were added. */
    public static List<Source> all() {
        List<Source> all = new ArrayList<>();
        all.add(live());
        all.addAll(ADDED);
        return all;
    }

    public static Optional<Source> find(String id) {
        if (id == null || LIVE.equals(id)) {
            return Optional.of(live());
        }
        return ADDED.stream().filter(s -> s.id().equals(id)).findFirst();
    }

    /**
     * Adds a source; close the result to remove it (e.g. when its editor closes).
     *
     * @throws IllegalArgumentException when the id is Live's or already taken
     */
    public static AutoCloseable add(Source source) {
        synchronized (ADDED) {
            if (find(source.id()).isPresent()) {
                throw new IllegalArgumentException("a bus source with id '" + source.id() + "' is already registered");
            }
            ADDED.add(source);
        }
        changed();
        return () -> {
            if (ADDED.remove(source)) {
                changed();
            }
        };
    }

    /** Tells {@code onChange} about every addition and removal; close the result to stop. */
    public static AutoCloseable listen(Runnable onChange) {
        LISTENERS.add(onChange);
        return () -> LISTENERS.remove(onChange);
    }

    private static void changed() {
        LISTENERS.forEach(Runnable::run);
    }
}
