package org.stagecraft.replay.fields;

import java.util.Locale;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;

/**
 * A robot data breakpoint to start from, for a field a user points at in the inspector: the message's device,
 * its message type when not DATA, and a test of the field against the value it has there — {@code laser:0
 * min(ranges) < 0.287} for a list of numbers, {@code position2d:0 stall == 0} for an integer, {@code
 * position2d:0 pos.px < 1.25} for a real number. The user edits it before it is set; it always reads
 * ({@link StreamCondition#parse}).
 */
public final class BreakpointText {
    private BreakpointText() {
    }

    /**
     * @param interfaceName Player's name of the message's interface, e.g. "laser"
     * @param path          the field's path in the body, e.g. {@code pos.px} or {@code ranges}
     * @return the text, or null for a field that holds no number (text, bytes, a struct)
     */
    public static @Nullable String of(String interfaceName, MessageHeader header, String path, Field field) {
        String device = interfaceName.toLowerCase(Locale.ROOT) + ":" + header.index();
        MessageType type = header.messageType();
        if (type != null && type != MessageType.DATA) {
            device += " " + type.name();
        }
        if (field.kind() == Field.Kind.LIST) {
            double min = Double.POSITIVE_INFINITY;
            for (Field c : field.children()) {
                if (!c.kind().numeric()) {
                    return null;
                }
                min = Math.min(min, c.number());
            }
            return field.children().isEmpty() ? null : device + " min(" + path + ") < " + Condition.format(min);
        }
        if (!field.kind().numeric()) {
            return null;
        }
        return device + " " + path + (field.kind() == Field.Kind.INTEGER ? " == " : " < ") + Condition.format(field.number());
    }
}
