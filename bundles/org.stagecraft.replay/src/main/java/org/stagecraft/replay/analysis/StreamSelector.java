package org.stagecraft.replay.analysis;

import java.util.Locale;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.streams.StreamPattern;

/**
 * Reads what a user types to pick streams: the bus's pattern syntax ({@code "type=1 dev=6 index=*"})
 * or, shorter, a device by Player's interface name, optionally with an index and a message type:
 * {@code "laser"}, {@code "ranger:1"}, {@code "position2d:0 CMD"}. A bare name means its DATA
 * messages, which is what one plots or watches.
 */
public final class StreamSelector {
    private StreamSelector() {
    }

    /** @throws IllegalArgumentException saying what was not understood */
    public static StreamPattern parse(String text, CodecRegistry registry) {
        String t = text == null ? "" : text.strip();
        if (t.isEmpty()) {
            return StreamPattern.any();
        }
        if (t.contains("=")) {
            return StreamPattern.parse(t);
        }
        String[] words = t.split("\\s+");
        if (words.length > 2) {
            throw new IllegalArgumentException("'" + t + "' is neither a stream pattern (field=value ...) nor a device "
                    + "such as 'laser', 'ranger:1' or 'position2d:0 CMD'");
        }
        String device = words[0];
        int colon = device.indexOf(':');
        String name = colon < 0 ? device : device.substring(0, colon);
        int code = registry.interfaceCode(name.toLowerCase(Locale.ROOT));
        if (code < 0) {
            throw new IllegalArgumentException("no Player interface is called '" + name + "' (e.g. position2d, laser, ranger)");
        }
        StreamPattern p = StreamPattern.any().deviceType(code);
        if (colon >= 0) {
            String index = device.substring(colon + 1);
            try {
                p = index.equals("*") ? p : p.index(Integer.parseInt(index));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + index + "' after '" + name + ":' is not a device index");
            }
        }
        int type = 1;
        if (words.length == 2) {
            if (words[1].equals("*")) {
                return p;
            }
            type = typeCode(words[1]);
        }
        return p.messageType(type);
    }

    private static int typeCode(String word) {
        for (org.stagecraft.player.wire.MessageType m : org.stagecraft.player.wire.MessageType.values()) {
            if (m.name().equalsIgnoreCase(word)) {
                return m.code();
            }
        }
        throw new IllegalArgumentException("'" + word + "' is not a message type (DATA, CMD, REQ, RESP_ACK, SYNCH, RESP_NACK or *)");
    }
}
