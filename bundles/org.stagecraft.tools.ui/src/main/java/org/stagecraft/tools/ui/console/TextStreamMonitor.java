package org.stagecraft.tools.ui.console;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.eclipse.debug.core.IStreamListener;
import org.eclipse.debug.core.model.IFlushableStreamMonitor;
import org.eclipse.jdt.annotation.NonNullByDefault;

/**
 * One output stream of a session part as the debug console reads it: text appended by the Tool
 * Manager's threads, kept until a console takes it over (then unbuffered). The console reads
 * {@link #getContents()} and adds its listener while holding this monitor's lock, so no text is lost
 * or shown twice in between.
 */
public final class TextStreamMonitor implements IFlushableStreamMonitor {
    private final List<IStreamListener> listeners = new CopyOnWriteArrayList<>();
    private final StringBuilder contents = new StringBuilder();
    private boolean buffered = true;

    public synchronized void append(String text) {
        if (buffered) {
            contents.append(text);
        }
        for (IStreamListener l : listeners) {
            l.streamAppended(text, this);
        }
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public synchronized void addListener(IStreamListener listener) {
        listeners.add(listener);
    }

    @Override
    public synchronized String getContents() {
        return contents.toString();
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public synchronized void removeListener(IStreamListener listener) {
        listeners.remove(listener);
    }

    @Override
    public synchronized void flushContents() {
        contents.setLength(0);
    }

    @Override
    public synchronized void setBuffered(boolean buffer) {
        buffered = buffer;
    }

    @Override
    public synchronized boolean isBuffered() {
        return buffered;
    }
}
