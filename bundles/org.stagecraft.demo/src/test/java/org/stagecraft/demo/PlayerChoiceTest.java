package org.stagecraft.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PlayerChoiceTest {
    @TempDir
    Path tmp;

    private Path launcher() {
        return tmp.resolve("state/recorded-player");
    }

    private Path program(String dir, String name, String permissions) throws Exception {
        Path p = Files.createDirectories(tmp.resolve(dir)).resolve(name);
        Files.writeString(p, "#!/bin/sh\n");
        Files.setPosixFilePermissions(p, PosixFilePermissions.fromString(permissions));
        return p;
    }

    @Test
    void aRealPlayerOnThePathIsPreferred() throws Exception {
        program("a", "player", "rw-r--r--"); // not executable: not a program
        Path real = program("b", "player", "rwxr-xr-x");
        String path = tmp.resolve("a") + File.pathSeparator + File.pathSeparator + tmp.resolve("b");
        assertEquals(new PlayerChoice(real.toString(), false), PlayerChoice.choose(PlayerChoice.AUTO, launcher(), path));
    }

    @Test
    void withoutOneTheRecordedPlayerRuns() throws Exception {
        program("a", "not-player", "rwxr-xr-x");
        assertEquals(new PlayerChoice(launcher().toString(), true),
                PlayerChoice.choose(PlayerChoice.AUTO, launcher(), tmp.resolve("a").toString()));
        assertEquals(new PlayerChoice(launcher().toString(), true), PlayerChoice.choose(PlayerChoice.AUTO, launcher(), null));
    }

    @Test
    void recordedOrANamedProgramAreTakenAsSaid() throws Exception {
        Path real = program("b", "player", "rwxr-xr-x");
        assertEquals(new PlayerChoice(launcher().toString(), true),
                PlayerChoice.choose(PlayerChoice.RECORDED, launcher(), tmp.resolve("b").toString()));
        assertEquals(new PlayerChoice("/opt/player/bin/player", false),
                PlayerChoice.choose("/opt/player/bin/player", launcher(), real.getParent().toString()));
    }
}
