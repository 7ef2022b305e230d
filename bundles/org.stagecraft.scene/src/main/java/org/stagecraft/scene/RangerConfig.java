package org.stagecraft.scene;

/** The scan geometry of a ranger (its GET_CONFIG reply), or the defaults used until one is seen. */
public record RangerConfig(double minAngle, double maxAngle, double angularRes, double minRange, double maxRange,
        boolean seen) {

    /** Bearing of beam i of {@code count} in the device frame. */
    public double bearing(int i, int count) {
        if (seen && angularRes > 0) {
            return minAngle + i * angularRes;
        }
        return count <= 1 ? 0.5 * (minAngle + maxAngle) : minAngle + i * (maxAngle - minAngle) / (count - 1);
    }

    /** Until a config is seen: a 180 degree fan (a SICK LMS200, as Stage's sicklaser) with an 8 m range. */
    public static final RangerConfig DEFAULT_FAN = new RangerConfig(-Math.PI / 2, Math.PI / 2, 0, 0, 8, false);
}
