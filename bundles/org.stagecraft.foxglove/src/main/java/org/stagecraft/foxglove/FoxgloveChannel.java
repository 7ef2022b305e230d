package org.stagecraft.foxglove;

import java.nio.charset.StandardCharsets;

/**
 * One channel as Foxglove sees it, the same in an MCAP file and on the Foxglove WebSocket: a topic,
 * the name of its schema (one of Foxglove's well-known schemas, spelled exactly, for the panels to
 * recognise it), the schema itself and how messages are encoded.
 *
 * @param topic           e.g. {@code /robot6665/laser0/scan}
 * @param schemaName      e.g. {@code foxglove.LaserScan}
 * @param schemaEncoding  {@code jsonschema}
 * @param schema          the JSON Schema text
 * @param messageEncoding {@code json}
 */
public record FoxgloveChannel(String topic, String schemaName, String schemaEncoding, String schema,
        String messageEncoding) {

    /** A JSON-encoded channel whose schema is a JSON Schema. */
    public static FoxgloveChannel json(String topic, String schemaName, String jsonSchema) {
        return new FoxgloveChannel(topic, schemaName, "jsonschema", jsonSchema, "json");
    }

    public byte[] schemaBytes() {
        return schema.getBytes(StandardCharsets.UTF_8);
    }
}
