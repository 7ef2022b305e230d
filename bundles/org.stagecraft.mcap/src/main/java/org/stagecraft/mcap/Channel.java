package org.stagecraft.mcap;

import java.util.Map;

/** A Channel record; {@code schemaId} 0 means no schema. */
public record Channel(int id, int schemaId, String topic, String messageEncoding, Map<String, String> metadata) {
    public Channel {
        metadata = metadata == null ? Map.of() : Map.copyOf(metadata);
    }
}
