package org.stagecraft.spy;

import java.util.ArrayList;
import java.util.List;

/**
 * What a test opened, closed after it in the reverse order (the spy before its pipeline before its bus).
 * A test holds one in a field marked {@code @AutoClose}, so JUnit closes it after each test.
 */
public final class Cleanup implements AutoCloseable {
    private final List<AutoCloseable> opened = new ArrayList<>();

    /** Closes {@code c} after the test; returns it. */
    public <T extends AutoCloseable> T add(T c) {
        opened.add(c);
        return c;
    }

    @Override
    public void close() throws Exception {
        for (AutoCloseable c : opened.reversed()) {
            c.close();
        }
        opened.clear();
    }
}
