package org.stagecraft.replay.export;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.HashMap;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.foxglove.FoxgloveChannel;
import org.stagecraft.foxglove.FoxgloveSink;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * Foxglove's channels as added channels of an MCAP spy log. The only place the export's Foxglove
 * part meets the file writing. A write failure is thrown as {@link UncheckedIOException} (the sink
 * interface has no checked exceptions); {@link McapExport} unwraps it.
 */
final class SpyLogFoxgloveSink implements FoxgloveSink {
    private final SpyLogWriter out;
    private final Map<FoxgloveChannel, Integer> ids = new HashMap<>();

    SpyLogFoxgloveSink(SpyLogWriter out) {
        this.out = out;
    }

    @Override
    public void advertise(FoxgloveChannel c) {
        try {
            ids.put(c, out.addChannel(c.topic(), c.messageEncoding(), c.schemaName(), c.schemaEncoding(),
                    c.schemaBytes(), Map.of("source", "stagecraft-foxglove")));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void publish(FoxgloveChannel c, long logTimeNanos, long publishTimeNanos, byte[] json) {
        @Nullable Integer id = ids.get(c);
        if (id == null) {
            throw new IllegalStateException("channel " + c.topic() + " was published before it was advertised");
        }
        try {
            out.message(id, logTimeNanos, json);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** How many Foxglove channels were added. */
    int channels() {
        return ids.size();
    }
}
