package org.stagecraft.views.internal;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.Collection;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Bumper;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Sonar;
import org.stagecraft.scene.Payloads;
import org.stagecraft.streams.StreamMessage;

/**
 * The robot data breakpoints the Robot View offers for what its robots sense now, in the field language of the
 * Plot view and the inspector: a range sensor's nearest return ({@code laser:0 min(ranges) < 0.78}), a bumper
 * pressed ({@code bumper:0 any(bumpers)}), a base stalled ({@code position2d:0 stall == 1}). The numbers are
 * the sensors' values now; the breakpoint's dialog lets the user change them.
 */
public final class SensorConditions {
    private static final int DATA = 1;

    private SensorConditions() {
    }

    /** One offer per sensor among the newest messages, sorted. */
    public static List<String> offers(Collection<StreamMessage> latest) {
        TreeSet<String> out = new TreeSet<>();
        for (StreamMessage m : latest) {
            if (m.key().messageType() != DATA) {
                continue;
            }
            String offer = offer(m.key().index(), Payloads.body(m));
            if (offer != null) {
                out.add(offer);
            }
        }
        return List.copyOf(out);
    }

    static @Nullable String offer(int index, @Nullable MessageBody body) {
        return switch (body) {
            case Laser.Scan s -> nearest("laser:" + index, "ranges", s.ranges().toArray());
            case Sonar.Ranges s -> nearest("sonar:" + index, "ranges", s.ranges().toArray());
            case Ranger.Values v when v.name().equals("ranges") -> nearest("ranger:" + index, "ranges", v.values().toArray());
            case Bumper.State b when b.bumpersCount() > 0 -> "bumper:" + index + " any(bumpers)";
            case Position2d.State p -> "position2d:" + index + " stall == 1";
            case null, default -> null;
        };
    }

    private static @Nullable String nearest(String device, String field, float[] values) {
        double min = Double.POSITIVE_INFINITY;
        for (float v : values) {
            min = Math.min(min, v);
        }
        return values.length == 0 || !Double.isFinite(min) ? null : device + " min(" + field + ") < " + number(min);
    }

    private static @Nullable String nearest(String device, String field, double[] values) {
        float[] f = new float[values.length];
        for (int i = 0; i < values.length; i++) {
            f[i] = (float) values[i];
        }
        return nearest(device, field, f);
    }

    /** Centimetres are plenty for a threshold the user will adjust: "0.78", "1.5", "5". */
    static String number(double v) {
        return BigDecimal.valueOf(v).setScale(2, RoundingMode.HALF_UP).stripTrailingZeros().toPlainString()
                .toLowerCase(Locale.ROOT);
    }
}
