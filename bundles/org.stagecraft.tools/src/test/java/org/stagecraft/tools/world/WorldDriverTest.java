package org.stagecraft.tools.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.tools.cfg.PlayerCfg;

/**
 * Stagecraft's world driver without Player: its source ships with the bundle, its cfg section is one Player reads
 * as the driver on its own port, the answers it gives are read strictly, and a machine that cannot build it is told
 * what is missing. (Built and run against the real Player and Stage: tests/org.stagecraft.player.it, RealWorldFreezeTest.)
 */
class WorldDriverTest {
    @TempDir
    Path tmp;

    @Test
    void theSourceShipsBesideTheClasses() {
        String source = WorldDriver.source();
        assertTrue(source.contains("player_driver_init"), "a Player plugin's entry point");
        assertTrue(source.contains("\"" + WorldDriver.NAME + "\""), "registers the driver under the name the cfg uses");
    }

    @Test
    void theCfgSectionIsTheDriverOnItsOwnPort() throws Exception {
        Path cfg = tmp.resolve("copy.cfg");
        Files.writeString(cfg, "driver\n(\n  name \"stage\"\n  provides [ \"simulation:0\" ]\n  plugin \"stageplugin\"\n)\n"
                + WorldDriver.cfgSection(tmp.resolve("lib dir/libstagecraft_world.so"), 40123));
        PlayerCfg read = PlayerCfg.read(cfg);
        Map<Integer, PlayerCfg.AddressUse> ports = read.listenPorts(6665);
        assertEquals(List.of(6665, 40123), List.copyOf(ports.keySet()), "Player listens for it on its own port only");
        PlayerCfg.AddressUse world = ports.get(40123);
        assertEquals(WorldDriver.NAME, world.driver());
        assertEquals("simulation", world.address().iface());
        assertTrue(read.sources().get(0).entries().stream().anyMatch(e -> e.key().equals("plugin")
                && e.values().get(0).text().equals(tmp.resolve("lib dir/libstagecraft_world.so").toString())),
                "the plugin by its absolute path, spaces and all");
        assertTrue(read.sources().get(0).entries().stream().anyMatch(e -> e.key().equals("alwayson")
                && e.values().get(0).text().equals("1")), "updated on every pass of Player's main loop");
    }

    @Test
    void answersAreReadStrictly() throws Exception {
        assertEquals(new WorldState(true, 12_300_000, true), WorldState.parse("1 12300000 gui"));
        assertEquals(new WorldState(false, 0, false), WorldState.parse("0 0 headless\n"));
        assertEquals("12.300 s", WorldState.parse("1 12300000 gui").simTime());
        for (String bad : List.of("", "1 12300000", "2 5 gui", "1 five gui", "1 5 window", "1 5 gui extra")) {
            WorldException e = assertThrows(WorldException.class, () -> WorldState.parse(bad), bad);
            assertTrue(e.getMessage().contains("world driver answered"), e.getMessage());
        }
    }

    @Test
    void withoutACompilerTheErrorSaysSo() {
        WorldException e = assertThrows(WorldException.class,
                () -> WorldDriver.build("player", Map.of("PATH", tmp.toString()), tmp.resolve("cache")));
        assertTrue(e.getMessage().contains("no C++ compiler") && e.getMessage().contains("g++"), e.getMessage());
    }

    @Test
    void withoutStagesDevelopmentFilesTheErrorNamesThem() throws Exception {
        Path bin = Files.createDirectories(tmp.resolve("bin"));
        for (String tool : List.of("c++", "pkg-config")) {
            Path t = bin.resolve(tool);
            // a pkg-config that knows no package, as on a machine without Stage installed
            Files.writeString(t, "#!/bin/sh\necho \"Package stage was not found in the pkg-config search path\" >&2\nexit 1\n");
            assertTrue(t.toFile().setExecutable(true));
        }
        WorldException e = assertThrows(WorldException.class,
                () -> WorldDriver.build("player", Map.of("PATH", bin + ":/bin:/usr/bin"), tmp.resolve("cache")));
        assertTrue(e.getMessage().contains("stage.pc") && e.getMessage().contains("Package stage was not found"), e.getMessage());
        assertFalse(Files.exists(tmp.resolve("cache")), "nothing half-built is cached");
    }

    @Test
    void aPlayerInAStagecraftPrefixBringsItsPkgConfigFiles() throws Exception {
        Path prefix = tmp.resolve("player-stage");
        Files.createDirectories(prefix.resolve("bin"));
        Files.createDirectories(prefix.resolve("lib/pkgconfig"));
        Path player = Files.writeString(prefix.resolve("bin/player"), "#!/bin/sh\n");
        assertTrue(player.toFile().setExecutable(true));
        assertEquals(java.util.Optional.empty(), WorldDriver.prefixOf(player.toString(), Map.of()), "no stage.pc yet");
        Files.writeString(prefix.resolve("lib/pkgconfig/stage.pc"), "Name: stage\n");
        assertEquals(prefix.toRealPath(), WorldDriver.prefixOf(player.toString(), Map.of()).orElseThrow());
        assertEquals(prefix.toRealPath(), WorldDriver.prefixOf("player", Map.of("PATH", prefix.resolve("bin").toString())).orElseThrow(),
                "found on PATH as Player is run");
    }
}
