package org.stagecraft.scene;

import java.util.List;

import org.stagecraft.streams.StreamPattern;

/**
 * The layers a new Robot View starts with, and the ids of the built-in renderers (contributed by
 * org.stagecraft.views through its renderers extension point).
 */
public final class DefaultLayers {
    public static final String MAP = "org.stagecraft.views.map", POSITION2D = "org.stagecraft.views.position2d",
            LASER = "org.stagecraft.views.laser", SONAR = "org.stagecraft.views.sonar",
            RANGER = "org.stagecraft.views.ranger", BUMPER = "org.stagecraft.views.bumper",
            FIDUCIAL = "org.stagecraft.views.fiducial", BLOBFINDER = "org.stagecraft.views.blobfinder";

    private DefaultLayers() {
    }

    /** Map at the bottom, then sonar, laser and the robots on top; the generic ranger layer starts hidden. */
    public static List<LayerSpec> create() {
        return List.of(
                new LayerSpec("map", MAP, "Map", StreamPattern.parse("type=4 dev=42"), true, 0x303030, 1.0, 0),
                new LayerSpec("sonar", SONAR, "Sonar", StreamPattern.parse("type=1 dev=62 subtype=1"), true, 0x19E633, 0.3, 10),
                new LayerSpec("sonar5", SONAR, "Sonar (sonar interface)", StreamPattern.parse("type=1 dev=5 subtype=1"), true, 0x19E633, 0.3, 11),
                new LayerSpec("ranger", RANGER, "Rangers", StreamPattern.parse("type=1 dev=62 subtype=1"), false, 0xE6A019, 0.6, 15),
                new LayerSpec("laser", LASER, "Laser", StreamPattern.parse("type=1 dev=6 subtype=1"), true, 0x1A4DFF, 0.35, 20),
                new LayerSpec("fiducial", FIDUCIAL, "Fiducials", StreamPattern.parse("type=1 dev=10 subtype=1"), true, 0xC000C0, 0.9, 30),
                new LayerSpec("bumper", BUMPER, "Bumpers", StreamPattern.parse("type=1 dev=14 subtype=1"), true, 0xFF8000, 0.9, 40),
                new LayerSpec("position2d", POSITION2D, "Robots", StreamPattern.parse("type=1 dev=4 subtype=1"), true, 0xE61A1A, 0.9, 50),
                new LayerSpec("blobfinder", BLOBFINDER, "Blobfinder", StreamPattern.parse("type=1 dev=7 subtype=1"), true, 0xFFFFFF, 0.8, 60));
    }
}
