package org.stagecraft.demo.recorded;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.eclipse.jdt.annotation.Nullable;

/**
 * Command-line options of the recorded peers: {@code --name value} and {@code -p value} pairs, the
 * rest positional. Environment variables fill in what the command line leaves out, because a Robot
 * Session gives Player its environment but a fixed command line ({@code PROGRAM -p PORT cfg}).
 */
final class Options {
    static final String RECORDING_VARIABLE = "STAGECRAFT_RECORDING";
    static final String SPEED_VARIABLE = "STAGECRAFT_REPLAY_SPEED";

    private final Map<String, String> named = new LinkedHashMap<>();
    private final List<String> positional = new ArrayList<>();
    private final Map<String, String> env;

    Options(String[] args, List<String> names, Map<String, String> env) {
        this.env = env;
        for (int i = 0; i < args.length; i++) {
            if (names.contains(args[i])) {
                if (i + 1 == args.length) {
                    throw new IllegalArgumentException(args[i] + " needs a value");
                }
                named.put(args[i], args[++i]);
            } else if (args[i].startsWith("-")) {
                throw new IllegalArgumentException("unknown option " + args[i]);
            } else {
                positional.add(args[i]);
            }
        }
    }

    String get(String name, String fallback) {
        return named.getOrDefault(name, fallback);
    }

    int integer(String name, int fallback) {
        @Nullable String v = named.get(name);
        try {
            return v == null ? fallback : Integer.parseInt(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(name + " needs a whole number, not '" + v + "'");
        }
    }

    List<String> positional() {
        return positional;
    }

    Path recording() {
        @Nullable String v = named.getOrDefault("--recording", env.get(RECORDING_VARIABLE));
        if (v == null || v.isBlank()) {
            throw new IllegalArgumentException("no recording given (--recording FILE or " + RECORDING_VARIABLE + ")");
        }
        return Path.of(v);
    }

    double speed() {
        String v = named.getOrDefault("--speed", env.getOrDefault(SPEED_VARIABLE, "1"));
        try {
            double s = Double.parseDouble(v);
            if (s > 0 && !Double.isInfinite(s)) {
                return s;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException("the replay speed must be a positive number, not '" + v + "'");
    }
}
