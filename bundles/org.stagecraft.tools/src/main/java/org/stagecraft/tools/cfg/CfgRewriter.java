package org.stagecraft.tools.cfg;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.eclipse.jdt.annotation.Nullable;

/**
 * Writes the copy of a Player configuration that Player really runs on: every local port moved as
 * the port map says, and nothing else changed but what moving the file requires.
 * <p>
 * The copy lives in a scratch directory, not beside the original (which may be read-only, or in a
 * project whose builders would react to a new file). So that it still means what the original meant:
 * <ul>
 * <li>every {@code include} names a copy in the same directory (included files may provide ports too);
 * <li>a relative path is made absolute against the directory of the file it is written in, which is
 * how Player resolves it: always for the keys that name files ({@link #PATH_KEYS}); for any other
 * string value when such a file exists there (driver-specific options, e.g. a plugin given as
 * {@code "./libmine.so"}); never for names such as {@code name}, {@code model} or an address.
 * </ul>
 * Player also starts in the original file's directory, for drivers that open files relative to
 * the working directory.
 */
public final class CfgRewriter {
    /** Keys whose string values are file names (Player's own and Stage's). */
    public static final Set<String> PATH_KEYS = Set.of("worldfile", "filename", "mapfile", "file", "logfile", "include");
    private static final Set<String> NEVER_PATHS = Set.of("name", "provides", "requires", "model", "driver", "key");

    /** One token changed in one file. */
    public record Change(Path file, int line, String before, String after) {
    }

    /** The written copy: the file to give Player, every file written, and what changed. */
    public record Rewritten(Path main, List<Path> files, List<Change> changes) {
    }

    private record Replacement(CfgToken token, String text) {
    }

    private CfgRewriter() {
    }

    /**
     * Writes the rewritten copy of {@code cfg} (and of every file it includes) into {@code dir}.
     *
     * @param portMap original port to the port Player should use instead; addresses naming a port
     *                not in the map, or another host, are left as they are
     */
    public static Rewritten write(PlayerCfg cfg, Map<Integer, Integer> portMap, Path dir) throws CfgException, IOException {
        Map<Path, Path> copies = new LinkedHashMap<>();
        int k = 0;
        for (PlayerCfg.Source s : cfg.sources()) {
            String name = s.file().getFileName().toString();
            copies.put(s.file(), dir.resolve(k == 0 ? name : "include" + k + "-" + name));
            k++;
        }
        List<Change> changes = new ArrayList<>();
        List<Path> written = new ArrayList<>();
        for (PlayerCfg.Source s : cfg.sources()) {
            List<Replacement> reps = new ArrayList<>();
            for (PlayerCfg.AddressUse a : cfg.addresses()) {
                if (!a.file().equals(s.file()) || !a.address().isLocal() || a.address().port() < 0) {
                    continue;
                }
                @Nullable Integer moved = portMap.get(a.address().port());
                if (moved != null) {
                    reps.add(new Replacement(a.token(), a.address().withPort(moved)));
                }
            }
            for (CfgToken inc : s.includes()) {
                reps.add(new Replacement(inc, copies.get(PlayerCfg.resolve(s.file(), inc.text())).toString()));
            }
            for (PlayerCfg.Entry e : s.entries()) {
                if (NEVER_PATHS.contains(e.key())) {
                    continue;
                }
                for (CfgToken v : e.values()) {
                    if (!v.is(CfgToken.Kind.STRING) || v.text().isEmpty() || v.text().contains(":")) {
                        continue;
                    }
                    Path p = Path.of(v.text());
                    if (p.isAbsolute()) {
                        continue;
                    }
                    Path resolved = PlayerCfg.resolve(s.file(), v.text());
                    if (PATH_KEYS.contains(e.key()) || Files.exists(resolved)) {
                        reps.add(new Replacement(v, resolved.toString()));
                    }
                }
            }
            reps.sort(Comparator.comparingInt((Replacement r) -> r.token().start()).reversed());
            StringBuilder text = new StringBuilder(s.text());
            for (Replacement r : reps) {
                if (r.text().contains("\"") || r.text().contains("\n")) {
                    throw new CfgException(s.file(), r.token().line(), "cannot write " + r.text()
                            + " as a Player string (it contains a quote or a line break)");
                }
                text.replace(r.token().start(), r.token().end(), "\"" + r.text() + "\"");
                changes.add(new Change(s.file(), r.token().line(), r.token().text(), r.text()));
            }
            Path out = copies.get(s.file());
            Files.writeString(out, text, StandardCharsets.UTF_8);
            written.add(out);
        }
        changes.sort(Comparator.comparing((Change c) -> c.file().toString()).thenComparingInt(Change::line));
        return new Rewritten(copies.get(cfg.file()), List.copyOf(written), List.copyOf(changes));
    }
}
