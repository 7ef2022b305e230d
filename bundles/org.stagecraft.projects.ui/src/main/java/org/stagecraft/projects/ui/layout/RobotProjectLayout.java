package org.stagecraft.projects.ui.layout;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * What a new Robot Project holds, as files relative to the project folder, without any Eclipse API:
 *
 * <pre>
 * src/PROGRAM.py                            the robot program (PyDev source folder)
 * worlds/pioneer-laser-sonar.world          a Pioneer 2DX with sonar ring and SICK laser in a cave
 * worlds/pioneer-laser-sonar.cfg            its Player cfg, Stage with a window (usegui 1)
 * worlds/pioneer-laser-sonar-headless.cfg   the same without a window (usegui 0)
 * worlds/pioneer.inc, sick.inc, map.inc     Stage's model definitions the world includes
 * worlds/bitmaps/cave.png                   the floor plan
 * </pre>
 *
 * The world and cfg files are those of the recorded corpus ({@code tests/traces/worlds}) unchanged,
 * so a new project runs the world Stagecraft's own tests and demo run; the program is an example
 * of the Python client unchanged, or a generated skeleton.
 */
public final class RobotProjectLayout {
    public static final String SOURCE_FOLDER = "src";
    public static final String WORLDS_FOLDER = "worlds";
    public static final String WORLD = WORLDS_FOLDER + "/pioneer-laser-sonar.world";
    /** Player cfg with Stage's window: for watching the robot (needs a display). */
    public static final String WINDOWED_CFG = WORLDS_FOLDER + "/pioneer-laser-sonar.cfg";
    /** Player cfg without a window: runs anywhere, faster than real time. */
    public static final String HEADLESS_CFG = WORLDS_FOLDER + "/pioneer-laser-sonar-headless.cfg";
    /** Every world file, relative to the project (and, the same path, to the templates folder). */
    public static final List<String> WORLD_FILES = List.of(WORLD, WINDOWED_CFG, HEADLESS_CFG,
            WORLDS_FOLDER + "/pioneer.inc", WORLDS_FOLDER + "/sick.inc", WORLDS_FOLDER + "/map.inc",
            WORLDS_FOLDER + "/bitmaps/cave.png");

    /** One file of the project: its path relative to the project folder, and its bytes. */
    public record ProjectFile(String path, byte[] content) {
        public ProjectFile {
            Objects.requireNonNull(path);
            Objects.requireNonNull(content);
        }

        public String text() {
            return new String(content, StandardCharsets.UTF_8);
        }
    }

    private RobotProjectLayout() {
    }

    /** The program's path in the project ({@code src/laser_sentinel.py}). */
    public static String programPath(ProgramTemplate program) {
        return SOURCE_FOLDER + "/" + program.fileName();
    }

    /** The project's files: the world files first, then the program. */
    public static List<ProjectFile> files(String projectName, ProgramTemplate program, TemplateSource templates)
            throws IOException {
        List<ProjectFile> out = new ArrayList<>();
        for (String path : WORLD_FILES) {
            out.add(new ProjectFile(path, read(templates, path)));
        }
        String template = program.templatePath();
        byte[] text = template != null ? read(templates, template)
                : emptyProgram(projectName).getBytes(StandardCharsets.UTF_8);
        out.add(new ProjectFile(programPath(program), text));
        return out;
    }

    private static byte[] read(TemplateSource templates, String path) throws IOException {
        try (InputStream in = templates.open(path)) {
            return in.readAllBytes();
        }
    }

    /**
     * The {@link ProgramTemplate#EMPTY} program: connects to the world's robot, subscribes its base
     * and laser, and reads rounds of data, doing nothing with them yet.
     */
    public static String emptyProgram(String projectName) {
        return """
                #!/usr/bin/env python3
                \"""%s: a robot program for Player/Stage.

                Run As > Robot Session on worlds/%s (Stage with a window) or
                worlds/%s (headless) starts Player with the world, the Network Spy and this
                program, which connects to port 6665 as if Player were there.
                \"""

                from stagecraft_player import Client


                def main() -> None:
                    with Client("localhost", 6665) as client:
                        robot = client.position2d(0)  # the Pioneer's base
                        laser = client.laser(0)  # its SICK laser (Stage's ranger:1 as a laser)
                        robot.enable_motors(True)
                        while True:
                            client.read()  # one round of data: robot and laser now hold it
                            # your robot's behaviour here, e.g. robot.set_speed(0.2, 0)


                if __name__ == "__main__":
                    main()
                """.formatted(projectName.replace("\"", "'"), fileName(WINDOWED_CFG), fileName(HEADLESS_CFG));
    }

    private static String fileName(String path) {
        return path.substring(path.lastIndexOf('/') + 1);
    }
}
