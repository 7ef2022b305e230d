package org.stagecraft.tools.session;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.tools.cfg.PlayerCfg;

/** When a session adds Stagecraft's world driver: Player itself, running a cfg with Stage in it. */
class SessionWorldTest {
    @TempDir
    Path tmp;

    @Test
    void onlyPlayerItselfRunsAWorld() {
        assertTrue(RobotSession.isPlayer("player"));
        assertTrue(RobotSession.isPlayer("/home/me/.local/share/stagecraft/player-stage/bin/player"));
        assertFalse(RobotSession.isPlayer("/usr/bin/java"), "the recorded Player of the demo reads the cfg but runs no world");
        assertFalse(RobotSession.isPlayer("/tmp/recorded-player"));
    }

    @Test
    void aCfgRunsStageWhenADriverIsStages() throws Exception {
        Path stage = Files.writeString(tmp.resolve("stage.cfg"), "driver\n(\n  name \"stage\"\n  provides [ \"simulation:0\" ]\n"
                + "  plugin \"stageplugin\"\n)\n");
        Path other = Files.writeString(tmp.resolve("other.cfg"), "driver\n(\n  name \"p2os\"\n  provides [ \"position2d:0\" ]\n"
                + "  port \"/dev/ttyS0\"\n)\n# name \"stage\" in a comment is no driver\n");
        assertTrue(RobotSession.runsStage(PlayerCfg.read(stage)));
        assertFalse(RobotSession.runsStage(PlayerCfg.read(other)), "a real robot's cfg has no world to freeze");
    }

    @Test
    void newLaunchesFreezeTheWorldAndTheOptionIsKeptByEveryChange() {
        assertTrue(SpyOptions.DEFAULT.freezeWorld());
        SpyOptions off = SpyOptions.DEFAULT.withFreezeWorld(false);
        assertFalse(off.withHoldWhenSuspended(true).withWatchdog(java.time.Duration.ofSeconds(1))
                .withUpstreamGrace(java.time.Duration.ofSeconds(3)).freezeWorld());
    }
}
