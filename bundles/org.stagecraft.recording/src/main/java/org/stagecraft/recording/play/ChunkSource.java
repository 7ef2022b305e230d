package org.stagecraft.recording.play;

import java.io.IOException;
import java.util.Iterator;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;

/**
 * One side of a recorded connection, chunk by chunk in recorded order, read as it is played: a
 * source over a large log holds only what it is reading, never the whole side.
 */
public interface ChunkSource extends AutoCloseable {

    /** The next chunk, or null after the last. */
    @Nullable TimedChunk next() throws IOException;

    @Override
    void close() throws IOException;

    /** A source over chunks already in memory (a small shipped recording). */
    static ChunkSource of(List<TimedChunk> chunks) {
        Iterator<TimedChunk> it = chunks.iterator();
        return new ChunkSource() {
            @Override
            public @Nullable TimedChunk next() {
                return it.hasNext() ? it.next() : null;
            }

            @Override
            public void close() {
                // nothing to release
            }
        };
    }
}
