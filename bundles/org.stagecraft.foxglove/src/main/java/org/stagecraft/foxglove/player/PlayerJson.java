package org.stagecraft.foxglove.player;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.json.JsonFieldWriter;
import org.stagecraft.player.json.JsonNumbers;
import org.stagecraft.player.wire.MessageHeader;

/**
 * A decoded message as one JSON object: {@code header} (Player's timestamp, seq, host and robot),
 * then the body's fields by Player's names, numbers exact (a float32 as the shortest text of that
 * float; NaN and infinities, which the JSON Schema's numbers cannot hold, as null), opaque bytes in
 * base64: {@link JsonFieldWriter} with {@link JsonNumbers#SCHEMA}. The MCAP export's Player channels.
 */
public final class PlayerJson {

    private PlayerJson() {
    }

    /** The message as JSON text. */
    public static String of(MessageHeader h, MessageBody body) {
        StringBuilder b = new StringBuilder(1024);
        b.append("{\"header\":{\"timestamp\":");
        JsonNumbers.SCHEMA.appendDouble(b, h.timestamp());
        b.append(",\"seq\":").append(h.seqUnsigned()).append(",\"host\":").append(h.hostUnsigned())
                .append(",\"robot\":").append(h.robotUnsigned()).append('}');
        body.describe(new JsonFieldWriter(b, JsonNumbers.SCHEMA, true));
        return b.append('}').toString();
    }
}
