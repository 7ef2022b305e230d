package org.stagecraft.tools.world;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.process.ExecutableLookup;

/**
 * Stagecraft's world driver for Player ({@code stagecraft_world.cc} beside this class): its source, the
 * shared library built from it against the Player and Stage a session runs, and the {@code .cfg} section that
 * loads it. It is built on first use with the system's C++ compiler and {@code pkg-config} (Stage's
 * {@code stage.pc} and Player's {@code playercore.pc}, which {@code ./stagecraft player-stage install} puts in
 * its prefix), and kept in a cache keyed by the source and the flags, so a rebuilt Stage gets a rebuilt driver.
 */
public final class WorldDriver {
    /** The driver's name in a {@code .cfg}. */
    public static final String NAME = "stagecraft_world";
    private static final String SOURCE = "stagecraft_world.cc";
    private static final String LIBRARY = "libstagecraft_world.so";
    private static final long BUILD_SECONDS = 180;

    private WorldDriver() {
    }

    /** The driver's C++ source, as shipped in this bundle. */
    public static String source() {
        try (InputStream in = WorldDriver.class.getResourceAsStream(SOURCE)) {
            if (in == null) {
                throw new IllegalStateException(SOURCE + " is missing from " + WorldDriver.class.getPackageName());
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read " + SOURCE + ": " + e.getMessage(), e);
        }
    }

    /** Where built drivers are kept: {@code $XDG_CACHE_HOME/stagecraft/world-driver} (default {@code ~/.cache}). */
    public static Path defaultCache() {
        String xdg = System.getenv("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() ? Path.of(xdg) : Path.of(System.getProperty("user.home"), ".cache");
        return base.resolve("stagecraft").resolve("world-driver");
    }

    /**
     * The driver built against the Player that {@code playerProgram} runs (built now if the cache has no
     * copy for these flags).
     *
     * @param playerProgram the session's Player program, as a path or a name on {@code environment}'s PATH
     * @param environment   Player's environment (PATH, PKG_CONFIG_PATH as the session sets them)
     * @throws WorldException saying what is missing (compiler, pkg-config, Stage's development files) or
     *                        the compiler's last lines
     */
    public static Path build(String playerProgram, Map<String, String> environment, Path cache) throws WorldException {
        Map<String, String> env = new LinkedHashMap<>(System.getenv());
        env.putAll(environment);
        prefixOf(playerProgram, env).ifPresent(prefix -> {
            String own = prefix.resolve("lib").resolve("pkgconfig").toString();
            String before = env.get("PKG_CONFIG_PATH");
            env.put("PKG_CONFIG_PATH", before == null || before.isBlank() ? own : own + ":" + before);
        });
        String compiler = tool(env, "c++", "g++").orElseThrow(() -> new WorldException(
                "no C++ compiler (c++ or g++) on PATH to build Stagecraft's world driver; install g++"));
        String pkgConfig = tool(env, "pkg-config").orElseThrow(() -> new WorldException(
                "no pkg-config on PATH to find Stage's and Player's development files; install pkg-config"));
        Result flags = run(List.of(pkgConfig, "--cflags", "--libs", "stage", "playercore"), env, null);
        if (flags.exit != 0) {
            throw new WorldException("pkg-config does not find Stage and Player (stage.pc, playercore.pc; PKG_CONFIG_PATH="
                    + env.getOrDefault("PKG_CONFIG_PATH", "") + "): " + flags.lastLines());
        }
        List<String> flagList = new ArrayList<>();
        for (String f : flags.output.trim().split("\\s+")) {
            if (f.isEmpty()) {
                continue;
            }
            flagList.add(f);
            if (f.startsWith("-L")) {
                flagList.add("-Wl,-rpath," + f.substring(2)); // the libraries Player itself was linked with
            }
        }
        String source = source();
        Path dir = cache.resolve(key(source, compiler, flagList));
        Path library = dir.resolve(LIBRARY);
        if (Files.isRegularFile(library)) {
            return library;
        }
        try {
            Files.createDirectories(dir);
            Path src = dir.resolve(SOURCE);
            Files.writeString(src, source, StandardCharsets.UTF_8);
            Path partial = Files.createTempFile(dir, "build-", ".so");
            List<String> command = new ArrayList<>(List.of(compiler, "-shared", "-fPIC", "-O2", "-o", partial.toString(),
                    src.toString()));
            command.addAll(flagList);
            Result built = run(command, env, dir);
            if (built.exit != 0) {
                Files.deleteIfExists(partial);
                throw new WorldException("Stagecraft's world driver did not compile against this Stage (" + String.join(" ", command)
                        + "): " + built.lastLines());
            }
            try {
                Files.move(partial, library, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(partial, library, StandardCopyOption.REPLACE_EXISTING);
            }
            return library;
        } catch (IOException e) {
            throw new WorldException("cannot build Stagecraft's world driver in " + dir + ": " + e.getMessage(), e);
        }
    }

    /**
     * The {@code .cfg} section that loads the driver: one simulation device on a port of its own (so robot
     * programs do not see it in their device lists), updated on every pass of Player's main loop.
     */
    public static String cfgSection(Path library, int port) {
        return "\n# Added by Stagecraft: its world driver, which freezes the simulated world while the session's robots are\n"
                + "# held (docs/debugging-robots.md). Not in your file; only in this copy.\n"
                + "driver\n(\n  name \"" + NAME + "\"\n  plugin \"" + library + "\"\n  provides [ \"" + port
                + ":simulation:0\" ]\n  alwayson 1\n)\n";
    }

    /** The install prefix of a Player program in PREFIX/bin, when that prefix has Stage's pkg-config file. */
    static Optional<Path> prefixOf(String playerProgram, Map<String, String> env) {
        Optional<Path> exe = playerProgram.contains("/") ? Optional.of(Path.of(playerProgram))
                : ExecutableLookup.in(playerProgram, env.get("PATH"));
        return exe.map(p -> {
            try {
                return p.toRealPath();
            } catch (IOException e) {
                return p.toAbsolutePath();
            }
        }).map(Path::getParent).map(Path::getParent)
                .filter(prefix -> Files.isRegularFile(prefix.resolve("lib").resolve("pkgconfig").resolve("stage.pc")));
    }

    private static Optional<String> tool(Map<String, String> env, String... names) {
        for (String n : names) {
            Optional<Path> p = ExecutableLookup.in(n, env.get("PATH"));
            if (p.isPresent()) {
                return Optional.of(p.get().toString());
            }
        }
        return Optional.empty();
    }

    private static String key(String source, String compiler, List<String> flags) {
        try {
            MessageDigest d = MessageDigest.getInstance("SHA-256");
            d.update(source.getBytes(StandardCharsets.UTF_8));
            d.update(compiler.getBytes(StandardCharsets.UTF_8));
            d.update(String.join(" ", flags).getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(d.digest(), 0, 8);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    private record Result(int exit, String output) {
        String lastLines() {
            String[] lines = output.strip().split("\n");
            int from = Math.max(0, lines.length - 12);
            return String.join("\n", java.util.Arrays.copyOfRange(lines, from, lines.length));
        }
    }

    private static Result run(List<String> command, Map<String, String> env, @Nullable Path dir) throws WorldException {
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().clear();
        pb.environment().putAll(env);
        if (dir != null) {
            pb.directory(dir.toFile());
        }
        try {
            Process p = pb.start();
            p.getOutputStream().close();
            byte[] out = p.getInputStream().readAllBytes(); // ends when the process closes its output
            if (!p.waitFor(BUILD_SECONDS, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new WorldException(command.get(0) + " did not finish within " + BUILD_SECONDS + " s");
            }
            return new Result(p.exitValue(), new String(out, StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new WorldException("cannot run " + command.get(0) + ": " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new WorldException("interrupted while building Stagecraft's world driver", e);
        }
    }
}
