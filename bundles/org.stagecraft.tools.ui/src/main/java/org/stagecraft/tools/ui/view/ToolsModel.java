package org.stagecraft.tools.ui.view;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.process.ToolState;

/**
 * What the Tools view shows: every part of every Robot Session of this workbench, with its state.
 * Updated from the Tool Manager's threads; listeners are told after each change (and must hand any
 * UI work to the display themselves).
 */
public final class ToolsModel {
    /** One row: a part of a session. */
    public record Row(String session, String part, ToolState state, long pid, int restarts, @Nullable Integer lastExit,
            String detail) {
    }

    private static final ToolsModel INSTANCE = new ToolsModel();
    private final Map<String, Row> rows = new LinkedHashMap<>();
    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();

    public static ToolsModel get() {
        return INSTANCE;
    }

    public void update(Row row) {
        synchronized (rows) {
            rows.put(row.session() + "\u0000" + row.part(), row);
        }
        listeners.forEach(Runnable::run);
    }

    /** Forgets the rows of a session that has ended (its last states stay until the next session starts). */
    public void removeSession(String session) {
        synchronized (rows) {
            rows.values().removeIf(r -> r.session().equals(session));
        }
        listeners.forEach(Runnable::run);
    }

    public List<Row> rows() {
        synchronized (rows) {
            return new ArrayList<>(rows.values());
        }
    }

    public @Nullable Row find(String session, String part) {
        synchronized (rows) {
            return rows.get(session + "\u0000" + part);
        }
    }

    public void addListener(Runnable l) {
        listeners.add(l);
    }

    public void removeListener(Runnable l) {
        listeners.remove(l);
    }
}
