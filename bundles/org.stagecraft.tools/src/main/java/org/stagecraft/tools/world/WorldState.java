package org.stagecraft.tools.world;

import java.util.Locale;

/**
 * What the world driver says about the Stage world.
 *
 * @param frozen        whether the driver holds it still
 * @param simTimeMicros its simulated time, in microseconds
 * @param gui           whether Stage runs it with a window (usegui 1)
 */
public record WorldState(boolean frozen, long simTimeMicros, boolean gui) {

    /** The driver's answer, "FROZEN SIMTIME gui|headless" (stagecraft_world.cc). */
    static WorldState parse(String text) throws WorldException {
        String[] f = text.trim().split(" ");
        if (f.length != 3 || !(f[0].equals("0") || f[0].equals("1")) || !(f[2].equals("gui") || f[2].equals("headless"))) {
            throw new WorldException("the world driver answered \"" + text + "\", not \"0|1 TIME gui|headless\"");
        }
        try {
            return new WorldState(f[0].equals("1"), Long.parseLong(f[1]), f[2].equals("gui"));
        } catch (NumberFormatException e) {
            throw new WorldException("the world driver answered \"" + text + "\": " + f[1] + " is not a time in microseconds");
        }
    }

    /** Simulated time for people, e.g. "12.300 s". */
    public String simTime() {
        return String.format(Locale.ROOT, "%.3f s", simTimeMicros / 1e6);
    }
}
