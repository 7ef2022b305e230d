package org.stagecraft.projects.ui.layout;

import org.eclipse.jdt.annotation.Nullable;

/** The robot program a new Robot Project starts with. */
public enum ProgramTemplate {
    /** The example that turns to face the nearest object (laser:0); never drives. */
    LASER_SENTINEL("Laser Sentinel", "laser_sentinel.py", "examples/laser_sentinel.py",
            "turns on the spot to face the nearest object its laser sees; never drives"),
    /** The example that wanders about, avoiding obstacles with its sonar ring (ranger:0). */
    SUNDAY_STROLL("Sunday Stroll", "sunday_stroll.py", "examples/sunday_stroll.py",
            "wanders about at random and turns away from obstacles its sonars see"),
    /** A program that connects and reads the robot's data, and does nothing else yet. */
    EMPTY("Empty program", "robot.py", null,
            "connects to the robot and reads its data: the behaviour is yours to write");

    private final String label;
    private final String fileName;
    private final @Nullable String templatePath;
    private final String description;

    ProgramTemplate(String label, String fileName, @Nullable String templatePath, String description) {
        this.label = label;
        this.fileName = fileName;
        this.templatePath = templatePath;
        this.description = description;
    }

    public String label() {
        return label;
    }

    /** The program's file name in the project's source folder. */
    public String fileName() {
        return fileName;
    }

    /** Where its text is among the templates ({@link TemplateSource}); null for a generated program. */
    public @Nullable String templatePath() {
        return templatePath;
    }

    public String description() {
        return description;
    }
}
