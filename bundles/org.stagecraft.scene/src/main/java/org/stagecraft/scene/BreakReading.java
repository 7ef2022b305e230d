package org.stagecraft.scene;

import java.util.List;
import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.stagecraft.player.codec.MessageBody;

/**
 * The sensor reading a robot data breakpoint stopped on, for a view to mark: the device that sent it,
 * the message decoded, and the fields of it that decided the breakpoint.
 *
 * @param device         the sensor, e.g. laser:0 of the robot on port 6665
 * @param body           the triggering message, decoded
 * @param decidingFields the concrete fields that decided it ({@code ranges[147]}, {@code bumpers[1]}, or a
 *                       whole list {@code ranges}); empty when not known (a break replayed from a log), which
 *                       marks the whole reading
 */
public record BreakReading(DeviceAddress device, MessageBody body, List<String> decidingFields) {
    private static final Pattern ELEMENT = Pattern.compile("([A-Za-z_][A-Za-z0-9_]*)\\[(\\d+)\\]");

    public BreakReading {
        decidingFields = List.copyOf(decidingFields);
    }

    /**
     * The elements of the list {@code list} (e.g. "ranges") that decided it, in order; every element
     * (empty result, {@code whole} true) when the list as a whole decided or nothing is known.
     */
    public Elements elements(String list) {
        if (decidingFields.isEmpty() || decidingFields.contains(list)) {
            return Elements.WHOLE;
        }
        List<Integer> out = decidingFields.stream().map(f -> index(f, list)).filter(OptionalInt::isPresent)
                .map(OptionalInt::getAsInt).toList();
        return new Elements(false, out);
    }

    private static OptionalInt index(String field, String list) {
        Matcher m = ELEMENT.matcher(field);
        return m.matches() && m.group(1).equals(list) ? OptionalInt.of(Integer.parseInt(m.group(2))) : OptionalInt.empty();
    }

    /** Which elements of a list to mark: all of them, or those listed. */
    public record Elements(boolean whole, List<Integer> indexes) {
        static final Elements WHOLE = new Elements(true, List.of());

        public Elements {
            indexes = List.copyOf(indexes);
        }

        public boolean marks(int i) {
            return whole || indexes.contains(i);
        }
    }
}
