package org.stagecraft.replay.export;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.writelog.WritelogWriter;

/**
 * A log (or the part a filter takes) as a Player writelog file, for Player's readlog. The Player
 * version in the file's metadata is the recorded server's, from its banner.
 *
 * <p>The geometry and configuration replies come first, before any data, wherever the client asked
 * for them in the session: readlog stores replies only while it reads the file's leading reply
 * lines (its {@code reading_configs} phase ends at the first line that is not a reply) and answers
 * a client's GET_GEOM / GET_CONFIG from what it stored, so a reply further down would be missing
 * when the client asks at its start. Player's own writelog writes them there too (its
 * {@code WriteGeometries} at setup).
 */
public final class WritelogExport {
    private WritelogExport() {
    }

    public static WritelogWriter.Summary write(SessionLog log, ExportFilter filter, CodecRegistry registry, Writer out)
            throws IOException {
        WritelogWriter w = new WritelogWriter(out, registry, playerVersion(log), log.path().getFileName().toString());
        CsvExport.forEach(log, filter, registry, m -> {
            if (WritelogWriter.isReply(m)) {
                w.write(m);
            }
        });
        CsvExport.forEach(log, filter, registry, m -> {
            if (!WritelogWriter.isReply(m)) {
                w.write(m);
            }
        });
        w.flush();
        return w.summary();
    }

    /** "3.1.1-dev" from the first banner "Player v.3.1.1-dev", or null. */
    static @Nullable String playerVersion(SessionLog log) throws IOException {
        try (LogCursor c = log.cursor(Long.MIN_VALUE)) {
            int looked = 0;
            for (LogMessage m = c.next(); m != null && looked < 1000; m = c.next(), looked++) {
                if (m.kind() == LogMessage.Kind.BANNER) {
                    String text = new String(m.bytes(), StandardCharsets.ISO_8859_1).replace("\0", "").trim();
                    int v = text.indexOf("v.");
                    return v >= 0 ? text.substring(v + 2).trim() : null;
                }
            }
        }
        return null;
    }
}
