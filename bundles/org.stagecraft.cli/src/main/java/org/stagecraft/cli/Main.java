package org.stagecraft.cli;

import java.io.PrintStream;
import java.util.Arrays;

/** The {@code stagecraft} command line: headless tools that need no desktop. */
public final class Main {
    private static final String USAGE = """
            usage: stagecraft <command> [arguments]
              decode FILE   print every banner and Player message of a trace as one JSON object per line
              stats FILE    count messages per direction, interface, type and subtype
              spy --listen [HOST:]PORT --to HOST:PORT [...] [--bind ADDR] [--log FILE] [--upstream-grace SECONDS]
                  [--foxglove [ADDR:]PORT [--foxglove-queue MESSAGES]]
                            relay robot programs to Player, decode and log everything (Ctrl-C stops);
                            a program that comes before Player waits for it up to --upstream-grace (5 s);
                            --foxglove serves the live streams to Foxglove/Lichtblick (ws://, loopback unless
                            ADDR or --bind says otherwise; at most --foxglove-queue (1024) wait per viewer)
              export FILE --format csv|writelog|mcap [--from S] [--until S] [--stream PATTERN] [--grep TEXT] [--out FILE]
                            a log (spy log, trace or writelog file), or part of it, in another format
              replay FILE --to [PORT=]HOST:PORT [...] [--speed X] [--loop]
                            serve a recorded session to robot programs as the recorded Player did
            exit codes: 0 everything asked for was done; 1 nothing usable was done (the input could not be
              read at all, the output not written); 2 the command line is wrong; 3 done with losses: part of
              the input could not be read (said on stderr, with counts)
            """;

    private Main() {
    }

    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    public static int run(String[] args, PrintStream out, PrintStream err) {
        if (args.length == 0 || args[0].equals("-h") || args[0].equals("--help") || args[0].equals("help")) {
            (args.length == 0 ? err : out).print(USAGE);
            return args.length == 0 ? ExitCode.USAGE : ExitCode.DONE;
        }
        String[] rest = Arrays.copyOfRange(args, 1, args.length);
        return switch (args[0]) {
            case "decode" -> new DecodeCommand().run(rest, out, err);
            case "stats" -> new StatsCommand().run(rest, out, err);
            case "spy" -> new SpyCommand().run(rest, out, err);
            case "export" -> new ExportCommand().run(rest, out, err);
            case "replay" -> new ReplayCommand().run(rest, out, err);
            default -> {
                err.println("stagecraft: unknown command '" + args[0] + "'");
                err.print(USAGE);
                yield ExitCode.USAGE;
            }
        };
    }
}
