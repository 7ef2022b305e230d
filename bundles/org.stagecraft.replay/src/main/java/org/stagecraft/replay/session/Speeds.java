package org.stagecraft.replay.session;

/** The replay speeds offered to the user, within the Replayer's 0.1x..16x, and stepping between them. */
public final class Speeds {
    private static final double[] OFFERED = { 0.1, 0.25, 0.5, 1, 2, 4, 8, 16 };

    private Speeds() {
    }

    /** The speeds offered, slowest first. */
    public static double[] offered() {
        return OFFERED.clone();
    }

    /** The offered speed just above {@code speed}, or the fastest. */
    public static double faster(double speed) {
        for (double s : OFFERED) {
            if (s > speed + 1e-9) {
                return s;
            }
        }
        return OFFERED[OFFERED.length - 1];
    }

    /** The offered speed just below {@code speed}, or the slowest. */
    public static double slower(double speed) {
        for (int i = OFFERED.length - 1; i >= 0; i--) {
            if (OFFERED[i] < speed - 1e-9) {
                return OFFERED[i];
            }
        }
        return OFFERED[0];
    }

    /** "0.25x", "2x". */
    public static String text(double s) {
        return (s == Math.rint(s) ? Integer.toString((int) s) : Double.toString(s)) + "x";
    }
}
