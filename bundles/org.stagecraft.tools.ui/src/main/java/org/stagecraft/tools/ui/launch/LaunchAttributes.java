package org.stagecraft.tools.ui.launch;

/** Attributes of a Robot Session launch configuration. */
public final class LaunchAttributes {
    public static final String TYPE = "org.stagecraft.tools.robotSession";
    private static final String P = "org.stagecraft.tools.";
    /** The Player cfg: a workspace path ("/project/worlds/robot.cfg") or a file system path. */
    public static final String CFG = P + "cfg";
    /** The robot program (.py): a workspace path; empty for a session without one. */
    public static final String PROGRAM = P + "program";
    /** The Player program; empty for the preference (default: player on PATH). */
    public static final String PLAYER = P + "player";
    /** Extra environment of Player (map); the robot program's environment is the standard Environment tab. */
    public static final String PLAYER_ENVIRONMENT = P + "playerEnvironment";
    /** What {@code player -p} would be: the default port of addresses that name none (int, 6665). */
    public static final String DEFAULT_PORT = P + "defaultPort";
    /** Restart policy of Player ("never", "on-failure:N", "always:N"). */
    public static final String PLAYER_RESTART = P + "playerRestart";
    /** Seconds Player (or a restart of it) may take to open its ports (int, 30). */
    public static final String READY_SECONDS = P + "readySeconds";
    /** Folder for spy logs, relative to the cfg's project ("spy-logs"); empty: no log. */
    public static final String LOG_FOLDER = P + "logFolder";
    /** Names of the user tools to start (list); absent: every enabled tool. */
    public static final String TOOLS = P + "tools";

    /** Hold the robots while the robot program is suspended in the debugger (boolean, true). */
    public static final String HOLD_WHEN_SUSPENDED = P + "holdWhenSuspended";
    /** While the robots are held, freeze the simulated world too, when Player runs Stage (boolean, true). */
    public static final String FREEZE_WORLD = P + "freezeWorld";
    /** The silence watchdog is on (boolean, false). */
    public static final String WATCHDOG = P + "watchdog";
    /** The silence watchdog's timeout in milliseconds (int, {@value #DEFAULT_WATCHDOG_MILLIS}). */
    public static final String WATCHDOG_MILLIS = P + "watchdogMillis";
    /** How long a robot program's connection waits for Player to accept, in seconds (int, 5). */
    public static final String UPSTREAM_GRACE_SECONDS = P + "upstreamGraceSeconds";

    public static final String DEFAULT_LOG_FOLDER = "spy-logs";
    public static final int DEFAULT_WATCHDOG_MILLIS = 500;

    /** PyDev's ids, used by string only: PyDev is optional and not a build dependency. */
    public static final String PYDEV_RUN_TYPE = "org.python.pydev.debug.regularLaunchConfigurationType";
    public static final String PYDEV_PROJECT = "org.python.pydev.debug.ATTR_PROJECT";
    public static final String PYDEV_NATURE = "org.python.pydev.pythonNature";
    /** PyDev's bundles whose public API a Robot Session calls by reflection (PyDev's computed PYTHONPATH). */
    public static final String PYDEV_DEBUG_BUNDLE = "org.python.pydev.debug";
    public static final String PYDEV_AST_BUNDLE = "org.python.pydev.ast";
    public static final String EXTERNAL_TOOLS_LOCATION = "org.eclipse.ui.externaltools.ATTR_LOCATION";
    public static final String EXTERNAL_TOOLS_WORKING_DIRECTORY = "org.eclipse.ui.externaltools.ATTR_WORKING_DIRECTORY";

    private LaunchAttributes() {
    }
}
