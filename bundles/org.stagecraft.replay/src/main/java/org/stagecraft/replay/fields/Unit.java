package org.stagecraft.replay.fields;

import java.util.Locale;

import org.eclipse.jdt.annotation.Nullable;

/** A unit a condition's number may be written in; values are converted to Player's SI units. */
public enum Unit {
    METRE("m", Dimension.LENGTH, 1), CENTIMETRE("cm", Dimension.LENGTH, 0.01), MILLIMETRE("mm", Dimension.LENGTH, 0.001),
    RADIAN("rad", Dimension.ANGLE, 1), DEGREE("deg", Dimension.ANGLE, Math.PI / 180),
    METRE_PER_SECOND("m/s", Dimension.SPEED, 1), CENTIMETRE_PER_SECOND("cm/s", Dimension.SPEED, 0.01),
    MILLIMETRE_PER_SECOND("mm/s", Dimension.SPEED, 0.001),
    RADIAN_PER_SECOND("rad/s", Dimension.ANGULAR_SPEED, 1), DEGREE_PER_SECOND("deg/s", Dimension.ANGULAR_SPEED, Math.PI / 180),
    SECOND("s", Dimension.TIME, 1), MILLISECOND("ms", Dimension.TIME, 0.001);

    private final String symbol;
    private final Dimension dimension;
    private final double toBase;

    Unit(String symbol, Dimension dimension, double toBase) {
        this.symbol = symbol;
        this.dimension = dimension;
        this.toBase = toBase;
    }

    public String symbol() {
        return symbol;
    }

    public Dimension dimension() {
        return dimension;
    }

    /** {@code value} in this unit, in the dimension's base (SI) unit. */
    public double toBase(double value) {
        return value * toBase;
    }

    /** The unit written {@code text} ("cm", "deg", "°", "m/s", ...), or null. */
    public static @Nullable Unit of(String text) {
        String t = text.toLowerCase(Locale.ROOT).replace("°", "deg").replace("degrees", "deg").replace("degree", "deg");
        for (Unit u : values()) {
            if (u.symbol.equals(t)) {
                return u;
            }
        }
        return null;
    }

    /** Every unit's symbol, for messages. */
    public static String symbols() {
        StringBuilder b = new StringBuilder();
        for (Unit u : values()) {
            b.append(b.isEmpty() ? "" : ", ").append(u.symbol);
        }
        return b.toString();
    }
}
