package org.stagecraft.scene;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.trace.TraceFraming;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;

/**
 * The bus messages a recorded session produces, keyed as the Network Spy keys them (server messages from
 * the Player address to the client, the rest the other way) with the decoded message as payload. For
 * rendering recorded data without sockets: the pixel tests, the benchmark, screenshots.
 */
public final class TraceMessages {
    private static final PlayerDecoder DECODER = new PlayerDecoder(CodecRegistry.standard());

    private TraceMessages() {
    }

    /**
     * @param playerAddress e.g. "127.0.0.1:6665"; the client is "127.0.0.1:(40000 + connection id)"
     */
    public static List<StreamMessage> read(Path trace, String playerAddress) throws IOException {
        List<StreamMessage> out = new ArrayList<>();
        TraceFraming.frame(trace, e -> {
            if (e.event() instanceof WireEvent.Frame f) {
                MessageHeader h = f.header();
                String client = "127.0.0.1:" + (40000 + e.stream().conn());
                boolean fromServer = e.stream().dir() == Direction.SERVER_TO_CLIENT;
                StreamKey k = new StreamKey(fromServer ? playerAddress : client, fromServer ? client : playerAddress,
                        h.type(), h.interf(), h.index(), h.subtype());
                out.add(new StreamMessage(k, (long) (e.t() * 1e9), DECODER.decode(f)));
            }
        });
        return out;
    }

    /** The same messages as if they came from another robot (another Player address). */
    public static StreamMessage moved(StreamMessage m, String fromAddress, String toAddress) {
        StreamKey k = m.key();
        return new StreamMessage(new StreamKey(k.source().equals(fromAddress) ? toAddress : k.source(),
                k.destination().equals(fromAddress) ? toAddress : k.destination(), k.messageType(), k.deviceType(),
                k.index(), k.subtype()), m.timeNanos(), m.payload());
    }
}
