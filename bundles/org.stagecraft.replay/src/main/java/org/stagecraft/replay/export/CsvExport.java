package org.stagecraft.replay.export;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.replay.fields.FlatFields;
import org.stagecraft.replay.log.HeaderNames;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;

/**
 * Player messages as one CSV table (RFC 4180), one row per message: {@code time} (log time in
 * seconds, every nanosecond digit), {@code conn}, {@code dir}, {@code iface}, {@code index},
 * {@code type}, {@code subtype} (names), {@code size} (payload bytes), {@code timestamp} (the Player
 * header's), then one column per field path ({@code pos.px}, {@code ranges[3]}). When several kinds of
 * message are exported together the field columns are the union of theirs, in the order first met,
 * and a row leaves the columns of other kinds empty: one file that a spreadsheet or pandas reads
 * whole, filtered by the {@code iface}/{@code type}/{@code subtype} columns. The log is read twice:
 * once for the columns, once for the rows.
 */
public final class CsvExport {
    static final List<String> FIXED = List.of("time", "conn", "dir", "iface", "index", "type", "subtype", "size",
            "timestamp");

    private CsvExport() {
    }

    /** @return the number of rows written */
    public static long write(SessionLog log, ExportFilter filter, CodecRegistry registry, Writer out) throws IOException {
        Set<String> fields = new LinkedHashSet<>();
        forEach(log, filter, registry, m -> fields.addAll(FlatFields.flatten(m.decoded().body()).keySet()));
        List<String> header = new ArrayList<>(FIXED);
        header.addAll(fields);
        row(out, header);
        long[] rows = { 0 };
        List<String> cells = new ArrayList<>(header.size());
        HeaderNames names = new HeaderNames(registry);
        forEach(log, filter, registry, m -> {
            MessageHeader h = m.decoded().header();
            cells.clear();
            cells.add(CellText.seconds(m.timeNanos()));
            cells.add(Integer.toString(m.connection().id()));
            cells.add(m.dir().label());
            cells.add(names.iface(h.interf()));
            cells.add(Integer.toString(h.index()));
            cells.add(HeaderNames.type(h.type()));
            cells.add(names.subtype(h));
            cells.add(Long.toString(h.sizeUnsigned()));
            cells.add(Double.toString(h.timestamp()));
            Map<String, Object> values = FlatFields.flatten(m.decoded().body());
            for (String f : fields) {
                cells.add(values.containsKey(f) ? CellText.of(values.get(f)) : "");
            }
            row(out, cells);
            rows[0]++;
        });
        out.flush();
        return rows[0];
    }

    /** Calls {@code action} for every Player message the filter takes, in log order. */
    static void forEach(SessionLog log, ExportFilter filter, CodecRegistry registry, ExportFilter.MessageAction action)
            throws IOException {
        filter.forEachInRange(log, m -> {
            if (filter.takes(m, registry)) {
                action.accept(m);
            }
        });
    }

    private static void row(Writer out, List<String> cells) throws IOException {
        for (int i = 0; i < cells.size(); i++) {
            if (i > 0) {
                out.write(',');
            }
            out.write(quote(cells.get(i)));
        }
        out.write("\r\n");
    }

    static String quote(String s) {
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0 && s.indexOf('\n') < 0 && s.indexOf('\r') < 0) {
            return s;
        }
        return '"' + s.replace("\"", "\"\"") + '"';
    }
}
