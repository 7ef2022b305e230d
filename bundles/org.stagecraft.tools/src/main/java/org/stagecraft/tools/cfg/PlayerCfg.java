package org.stagecraft.tools.cfg;

import java.io.IOException;
import java.nio.charset.MalformedInputException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.cfg.CfgToken.Kind;

/**
 * A Player configuration file as far as the Tool Manager needs it: every device address a driver
 * {@code provides} or {@code requires}, every value that is a file path, and the files it
 * {@code include}s (read too, recursively). The text of each file is kept so that a rewrite changes
 * only the tokens it must.
 */
public final class PlayerCfg {

    /** Whether a driver serves the address or uses it. */
    public enum Role {
        PROVIDES, REQUIRES
    }

    /**
     * One {@code key value} or {@code key [ values ]} pair inside a section (or at the top level:
     * section null, sectionId 0). Entries of one section share its sectionId.
     */
    public record Entry(@Nullable String section, int sectionId, String key, CfgToken keyToken, List<CfgToken> values) {
    }

    /** A device address and where it is written. */
    public record AddressUse(Path file, CfgToken token, Role role, DeviceAddress address, String driver) {
        public String where() {
            return file + ":" + token.line();
        }
    }

    /** One file of the configuration: the main file or an included one. */
    public record Source(Path file, String text, List<Entry> entries, List<CfgToken> includes) {
    }

    private final Path file;
    private final List<Source> sources;
    private final List<AddressUse> addresses;

    private PlayerCfg(Path file, List<Source> sources, List<AddressUse> addresses) {
        this.file = file;
        this.sources = List.copyOf(sources);
        this.addresses = List.copyOf(addresses);
    }

    /** Reads {@code file} and everything it includes. */
    public static PlayerCfg read(Path file) throws CfgException {
        Path main = file.toAbsolutePath().normalize();
        List<Source> sources = new ArrayList<>();
        List<AddressUse> addresses = new ArrayList<>();
        readInto(main, sources, addresses, new ArrayDeque<>(), null, 0);
        return new PlayerCfg(main, sources, addresses);
    }

    private static void readInto(Path file, List<Source> sources, List<AddressUse> addresses, Deque<Path> including,
            @Nullable Path includedFrom, int includeLine) throws CfgException {
        if (including.contains(file)) {
            throw new CfgException(includedFrom, includeLine, "include cycle: " + file + " includes itself (through "
                    + including + ")");
        }
        for (Source s : sources) {
            if (s.file().equals(file)) {
                return; // included twice: one copy serves both includes
            }
        }
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            if (includedFrom != null) {
                throw new CfgException(includedFrom, includeLine, "included file " + file + " does not exist");
            }
            throw new CfgException(file, 0, "no such file");
        } catch (MalformedInputException e) {
            throw new CfgException(file, 0, "not UTF-8 text");
        } catch (IOException e) {
            throw new CfgException(file, 0, "cannot read: " + e.getMessage(), e);
        }
        List<CfgToken> tokens = CfgLexer.tokens(file, text);
        List<Entry> entries = new ArrayList<>();
        List<CfgToken> includes = new ArrayList<>();
        new Parser(file, tokens, entries, includes).parse();
        Source source = new Source(file, text, entries, includes);
        sources.add(source);
        for (Entry e : entries) {
            Role role = switch (e.key()) {
                case "provides" -> Role.PROVIDES;
                case "requires" -> Role.REQUIRES;
                default -> null;
            };
            if (role == null) {
                continue;
            }
            String driver = driverName(entries, e.sectionId());
            for (CfgToken v : e.values()) {
                try {
                    addresses.add(new AddressUse(file, v, role, DeviceAddress.parse(v.text()), driver));
                } catch (IllegalArgumentException ex) {
                    throw new CfgException(file, v.line(), e.key() + ": " + ex.getMessage());
                }
            }
        }
        including.push(file);
        for (CfgToken inc : includes) {
            readInto(resolve(file, inc.text()), sources, addresses, including, file, inc.line());
        }
        including.pop();
    }

    private static String driverName(List<Entry> entries, int sectionId) {
        for (Entry e : entries) {
            if (sectionId != 0 && e.sectionId() == sectionId && e.key().equals("name") && !e.values().isEmpty()) {
                return e.values().get(0).text();
            }
        }
        return "?";
    }

    /** A path as Player reads it: relative to the directory of the file it is written in. */
    static Path resolve(Path file, String path) {
        return file.getParent().resolve(path).normalize();
    }

    public Path file() {
        return file;
    }

    /** The main file first, then included files in the order they are first included. */
    public List<Source> sources() {
        return sources;
    }

    public List<AddressUse> addresses() {
        return addresses;
    }

    /**
     * The ports Player will listen on when started with {@code -p defaultPort}: the port of every
     * {@code provides} address, the default one for addresses that name none. Player opens a port
     * only for the devices it serves, so the default port is among them only if some address uses it.
     * Each port maps to its first declaration (for messages that say where a port comes from).
     */
    public Map<Integer, AddressUse> listenPorts(int defaultPort) {
        Map<Integer, AddressUse> ports = new LinkedHashMap<>();
        for (AddressUse a : addresses) {
            if (a.role() == Role.PROVIDES) {
                ports.putIfAbsent(a.address().portOr(defaultPort), a);
            }
        }
        return ports;
    }

    /** Whether any provided address leaves its port to {@code -p}. */
    public boolean usesDefaultPort() {
        return addresses.stream().anyMatch(a -> a.role() == Role.PROVIDES && a.address().port() < 0);
    }

    /**
     * Recursive-descent reader of the section structure:
     * {@code file := item*; item := "include" STRING | WORD value | WORD "(" item* ")";
     * value := STRING | WORD | "[" (STRING | WORD)* "]"}.
     */
    private static final class Parser {
        private static final Set<Kind> SCALARS = Set.of(Kind.STRING, Kind.WORD);
        private final Path file;
        private final List<CfgToken> tokens;
        private final List<Entry> entries;
        private final List<CfgToken> includes;
        private int pos;
        private int sections;

        Parser(Path file, List<CfgToken> tokens, List<Entry> entries, List<CfgToken> includes) {
            this.file = file;
            this.tokens = tokens;
            this.entries = entries;
            this.includes = includes;
        }

        void parse() throws CfgException {
            items(null, 0, 0);
            if (pos < tokens.size()) {
                throw error(tokens.get(pos), "unexpected '" + tokens.get(pos).text() + "' (no section is open)");
            }
        }

        /** Reads items until the end of the file or a closing parenthesis (left for the caller). */
        private void items(@Nullable String section, int sectionId, int depth) throws CfgException {
            while (pos < tokens.size() && !tokens.get(pos).is(Kind.CLOSE_PAREN)) {
                CfgToken key = tokens.get(pos++);
                if (!key.is(Kind.WORD)) {
                    throw error(key, "expected a name, found '" + shown(key) + "'");
                }
                if (pos >= tokens.size()) {
                    throw error(key, "'" + key.text() + "' has no value");
                }
                CfgToken next = tokens.get(pos);
                if (key.text().equals("include") && depth == 0) {
                    if (!next.is(Kind.STRING)) {
                        throw error(next, "include needs a quoted file name");
                    }
                    includes.add(next);
                    pos++;
                } else if (next.is(Kind.OPEN_PAREN)) {
                    pos++;
                    items(key.text(), ++sections, depth + 1);
                    if (pos >= tokens.size()) {
                        throw error(next, "section '" + key.text() + "' opened here is never closed with ')'");
                    }
                    pos++;
                } else if (next.is(Kind.OPEN_BRACKET)) {
                    pos++;
                    List<CfgToken> values = new ArrayList<>();
                    while (pos < tokens.size() && SCALARS.contains(tokens.get(pos).kind())) {
                        values.add(tokens.get(pos++));
                    }
                    if (pos >= tokens.size() || !tokens.get(pos).is(Kind.CLOSE_BRACKET)) {
                        throw error(next, "list '" + key.text() + " [' is not closed with ']'"
                                + (pos < tokens.size() ? " (found '" + shown(tokens.get(pos)) + "' on line "
                                        + tokens.get(pos).line() + ")" : ""));
                    }
                    pos++;
                    entries.add(new Entry(section, sectionId, key.text(), key, values));
                } else if (SCALARS.contains(next.kind())) {
                    pos++;
                    entries.add(new Entry(section, sectionId, key.text(), key, List.of(next)));
                } else {
                    throw error(next, "'" + key.text() + "' has no value (found '" + shown(next) + "')");
                }
            }
            if (depth == 0 && pos < tokens.size()) {
                throw error(tokens.get(pos), "')' without a section to close");
            }
        }

        private static String shown(CfgToken t) {
            return t.is(Kind.STRING) ? "\"" + t.text() + "\"" : t.text();
        }

        private CfgException error(CfgToken at, String problem) {
            return new CfgException(file, at.line(), problem);
        }
    }
}
