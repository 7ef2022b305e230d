package org.stagecraft.replay.fields;

import org.eclipse.jdt.annotation.Nullable;

/**
 * What a number measures, so a condition cannot compare a range with an angle by mistake. Player's
 * messages carry SI units (metres, radians, seconds), so each dimension has one base unit that values
 * are held in.
 */
public enum Dimension {
    LENGTH("m"), ANGLE("rad"), SPEED("m/s"), ANGULAR_SPEED("rad/s"), TIME("s");

    private final String baseUnit;

    Dimension(String baseUnit) {
        this.baseUnit = baseUnit;
    }

    /** The SI unit Player's fields of this dimension are in, e.g. "m". */
    public String baseUnit() {
        return baseUnit;
    }

    /** For people: "a length", "an angle", ... */
    public String described() {
        return switch (this) {
            case LENGTH -> "a length";
            case ANGLE -> "an angle";
            case SPEED -> "a speed";
            case ANGULAR_SPEED -> "an angular speed";
            case TIME -> "a time";
        };
    }

    /**
     * The dimension of a field reached by {@code path}, from Player's field names (its interface
     * definitions use the same names for the same quantities), or null when the name does not say.
     * A pose's {@code px}/{@code py}/{@code pa} under a {@code vel} member are speeds.
     */
    public static @Nullable Dimension ofField(FieldPath path) {
        if (path.aggregate() == FieldPath.Aggregate.COUNT) {
            return null;
        }
        String last = path.lastName();
        boolean velocity = path.names().contains("vel");
        return switch (last) {
            case "ranges", "range", "min_range", "max_range", "range_res", "px", "py", "pz", "sw", "sl", "sh",
                    "length", "radius", "width", "height", "x", "y", "z" -> velocity ? SPEED : LENGTH;
            case "pa", "proll", "ppitch", "pyaw", "min_angle", "max_angle", "angle", "bearing", "orientation",
                    "angular_res" -> velocity ? ANGULAR_SPEED : ANGLE;
            case "velocity", "speed" -> SPEED;
            case "timestamp", "time", "sim_time" -> TIME;
            default -> null;
        };
    }
}
