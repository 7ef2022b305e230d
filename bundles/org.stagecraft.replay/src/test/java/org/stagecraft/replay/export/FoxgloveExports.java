package org.stagecraft.replay.export;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/** An MCAP export of a corpus trace, read back: its Foxglove messages in file order. */
record FoxgloveExports(Path trace, Path mcap, McapExport.Summary summary, List<Msg> messages, McapMessages all) {

    /** One message of a channel with a Foxglove schema. */
    record Msg(String topic, String schemaName, String embeddedSchema, long logTime, String json) {
        JsonObject object() {
            return JsonParser.parseString(json).getAsJsonObject();
        }
    }

    static List<Path> traces() {
        return TraceCorpus.all();
    }

    static FoxgloveExports of(Path trace) throws IOException {
        String name = trace.getFileName().toString().replace(".trace.jsonl", "");
        Path out = Files.createDirectories(Path.of("target", "test-logs")).resolve("foxglove-" + name + ".mcap");
        Files.deleteIfExists(out);
        McapExport.Summary s;
        try (SessionLog log = SessionLogs.open(trace)) {
            s = McapExport.write(log, ExportFilter.all(), CodecRegistry.standard(), out);
        }
        McapMessages mcap = McapMessages.read(out);
        List<Msg> msgs = new ArrayList<>();
        for (McapMessages.Message m : mcap.messages) {
            McapMessages.Channel c = mcap.channels.get(m.channel());
            McapMessages.Schema schema = mcap.schemas.get(c.schemaId());
            if (schema != null && schema.name().startsWith("foxglove.")) {
                msgs.add(new Msg(c.topic(), schema.name(), new String(schema.data(), StandardCharsets.UTF_8), m.logTime(),
                        new String(m.data(), StandardCharsets.UTF_8)));
            }
        }
        return new FoxgloveExports(trace, out, s, msgs, mcap);
    }
}
