package org.stagecraft.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;

/** {@code stagecraft decode FILE}: every banner and message of a recording as JSON lines. */
final class DecodeCommand {

    int run(String[] args, PrintStream out, PrintStream err) {
        if (args.length != 1) {
            err.println("usage: stagecraft decode FILE");
            return ExitCode.USAGE;
        }
        Path file = InputFile.readable("decode", args[0], err);
        if (file == null) {
            return ExitCode.FAILED;
        }
        EventJson json = new EventJson(new PlayerDecoder(CodecRegistry.standard()));
        BufferedWriter w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
        try {
            LogRecovery recovery = Recordings.frame(file, e -> {
                try {
                    w.write(json.toJson(e));
                    w.write('\n');
                } catch (IOException ex) {
                    throw new UncheckedIOException(ex);
                }
            });
            w.flush();
            return recovery.report("decode", file, err);
        } catch (IOException | UncheckedIOException e) {
            flushQuietly(w);
            err.println("stagecraft decode: " + e.getMessage());
            return ExitCode.FAILED;
        } catch (RuntimeException | OutOfMemoryError e) {
            flushQuietly(w);
            err.println("stagecraft decode: " + CommandFailure.describe(file, e));
            return ExitCode.FAILED;
        }
    }

    private static void flushQuietly(BufferedWriter w) {
        try {
            w.flush();
        } catch (IOException ignored) {
            // the error being reported matters more than a failed flush
        }
    }
}
