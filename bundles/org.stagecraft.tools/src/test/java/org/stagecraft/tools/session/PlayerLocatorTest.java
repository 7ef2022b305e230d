package org.stagecraft.tools.session;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.tools.session.PlayerLocator.Located;
import org.stagecraft.tools.session.PlayerLocator.Source;

/** Which Player a session runs: launch configuration, preference, the install prefix, the PATH. */
class PlayerLocatorTest {
    @TempDir
    Path tmp;

    /** A prefix as {@code ./stagecraft player-stage install} leaves it, with a fake bin/player. */
    private Path installed(Path prefix) throws Exception {
        Files.createDirectories(prefix.resolve("bin"));
        Files.createDirectories(prefix.resolve("lib"));
        Path player = prefix.resolve("bin/player");
        Files.writeString(player, "#!/bin/sh\nexit 0\n");
        Files.setPosixFilePermissions(player, PosixFilePermissions.fromString("rwxr-xr-x"));
        return prefix;
    }

    @Test
    void theInstallPrefixDefaultsToXdgDataHomeThenHomeAndTheVariableOverridesBoth() {
        assertEquals(Path.of("/d/stagecraft/player-stage"),
                new PlayerLocator(Map.of("HOME", "/h", "XDG_DATA_HOME", "/d")).installPrefix());
        assertEquals(Path.of("/h/.local/share/stagecraft/player-stage"), new PlayerLocator(Map.of("HOME", "/h")).installPrefix());
        assertEquals(Path.of("/h/.local/share/stagecraft/player-stage"),
                new PlayerLocator(Map.of("HOME", "/h", "XDG_DATA_HOME", "")).installPrefix(), "empty counts as unset");
        assertEquals(Path.of("/opt/ps"), new PlayerLocator(Map.of("HOME", "/h", "XDG_DATA_HOME", "/d",
                PlayerLocator.PREFIX_VARIABLE, "/opt/ps")).installPrefix());
        assertNull(new PlayerLocator(Map.of()).installPrefix());
    }

    @Test
    void aPlayerFromThePrefixGetsItsLibrariesPluginsAndStageFiles() throws Exception {
        Path prefix = installed(tmp.resolve("ps"));
        PlayerLocator locator = new PlayerLocator(Map.of(PlayerLocator.PREFIX_VARIABLE, prefix.toString(),
                "LD_LIBRARY_PATH", "/usr/local/lib", "PATH", tmp.toString()));

        Located p = locator.locate("", null, Map.of("EXTRA", "1"));

        assertEquals(Source.INSTALL_PREFIX, p.source());
        assertEquals(prefix.resolve("bin/player").toString(), p.program());
        assertEquals(prefix, p.prefix());
        assertEquals(prefix + "/lib:/usr/local/lib", p.environment().get("LD_LIBRARY_PATH"), "prepended to the IDE's");
        assertEquals(prefix + "/lib", p.environment().get("PLAYERPATH"));
        assertEquals(prefix + "/share/stage:" + prefix + "/lib/Stage-4.3", p.environment().get("STAGEPATH"));
        assertEquals("1", p.environment().get("EXTRA"), "the launch's own Player variables are kept");
    }

    @Test
    void theLaunchsOwnVariablesWinButTheLibraryDirectoryStaysFirst() throws Exception {
        Path prefix = installed(tmp.resolve("ps"));
        PlayerLocator locator = new PlayerLocator(Map.of(PlayerLocator.PREFIX_VARIABLE, prefix.toString()));

        Located p = locator.locate(null, null, Map.of("LD_LIBRARY_PATH", "/mine", "PLAYERPATH", "/my/plugins"));

        assertEquals(prefix + "/lib:/mine", p.environment().get("LD_LIBRARY_PATH"));
        assertEquals("/my/plugins", p.environment().get("PLAYERPATH"));
        assertEquals(prefix + "/lib", locator.locate(null, null, Map.of()).environment().get("LD_LIBRARY_PATH"),
                "no existing value: just the prefix's lib");
    }

    @Test
    void theDefaultPreferenceDoesNotHideThePrefix() throws Exception {
        Path prefix = installed(tmp.resolve("ps"));
        PlayerLocator locator = new PlayerLocator(Map.of(PlayerLocator.PREFIX_VARIABLE, prefix.toString()));

        assertEquals(Source.INSTALL_PREFIX, locator.locate(" ", "player", Map.of()).source());
    }

    @Test
    void aPreferenceTheUserSetWinsOverThePrefixAndTheLaunchConfigurationOverBoth() throws Exception {
        Path prefix = installed(tmp.resolve("ps"));
        PlayerLocator locator = new PlayerLocator(Map.of(PlayerLocator.PREFIX_VARIABLE, prefix.toString(),
                "LD_LIBRARY_PATH", "/usr/local/lib"));

        Located fromPreference = locator.locate("", "/opt/player/bin/player", Map.of());
        assertEquals(Source.PREFERENCE, fromPreference.source());
        assertEquals("/opt/player/bin/player", fromPreference.program());
        assertEquals(Map.of(), fromPreference.environment(), "no prefix variables for a Player from elsewhere");

        Located fromLaunch = locator.locate("/srv/player", "/opt/player/bin/player", Map.of("A", "b"));
        assertEquals(Source.LAUNCH_CONFIGURATION, fromLaunch.source());
        assertEquals("/srv/player", fromLaunch.program());
        assertEquals(Map.of("A", "b"), fromLaunch.environment());
    }

    @Test
    void withoutAnInstallPlayerComesFromThePath() throws Exception {
        Path emptyPrefix = Files.createDirectories(tmp.resolve("nothing-installed"));
        Path notExecutable = tmp.resolve("half");
        Files.createDirectories(notExecutable.resolve("bin"));
        Files.writeString(notExecutable.resolve("bin/player"), "not a program");

        for (Path prefix : new Path[] {emptyPrefix, notExecutable}) {
            Located p = new PlayerLocator(Map.of(PlayerLocator.PREFIX_VARIABLE, prefix.toString())).locate(null, "", Map.of());
            assertEquals(Source.PATH, p.source(), prefix.toString());
            assertEquals("player", p.program());
            assertNull(p.prefix());
        }
        assertEquals(Source.PATH, new PlayerLocator(Map.of()).locate(null, null, Map.of()).source(), "no HOME, no prefix");
    }

    @Test
    void aNamedPlayerOfAnInstallGetsThePrefixVariablesAndOneFromElsewhereDoesNot() throws Exception {
        Path prefix = installed(tmp.resolve("elsewhere/ps"));
        Files.writeString(prefix.resolve("env.sh"), "# written by the install script\n");
        Path other = installed(tmp.resolve("no-env-sh")); // a bin/player without the install's env.sh
        PlayerLocator locator = new PlayerLocator(Map.of("LD_LIBRARY_PATH", "/usr/local/lib")); // no prefix variable

        for (Located p : List.of(locator.locate(prefix.resolve("bin/player").toString(), null, Map.of("A", "b")),
                locator.locate("", prefix.resolve("bin/player").toString(), Map.of("A", "b")))) {
            assertEquals(prefix.resolve("bin/player").toString(), p.program());
            assertEquals(prefix, p.prefix());
            assertEquals(prefix + "/lib:/usr/local/lib", p.environment().get("LD_LIBRARY_PATH"));
            assertEquals(prefix + "/lib", p.environment().get("PLAYERPATH"));
            assertEquals(prefix + "/share/stage:" + prefix + "/lib/Stage-4.3", p.environment().get("STAGEPATH"));
            assertEquals("b", p.environment().get("A"));
        }
        assertEquals(Source.LAUNCH_CONFIGURATION, locator.locate(prefix.resolve("bin/player").toString(), null, Map.of()).source());

        Located plain = locator.locate(other.resolve("bin/player").toString(), null, Map.of("A", "b"));
        assertNull(plain.prefix());
        assertEquals(Map.of("A", "b"), plain.environment());
        assertNull(locator.locate("player", null, Map.of()).prefix(), "a name on the PATH");
        assertNull(locator.locate(prefix.resolve("bin/missing").toString(), null, Map.of()).prefix(), "no such file");
    }
}
