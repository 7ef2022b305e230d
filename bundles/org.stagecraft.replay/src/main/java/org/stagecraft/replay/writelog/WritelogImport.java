package org.stagecraft.replay.writelog;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.spy.log.SpyLogWriter;

/** Placeholder until the writelog reader lands: recognises nothing. */
public final class WritelogImport {
    private WritelogImport() {
    }

    public static boolean looksLikeWritelog(byte[] head) {
        return false;
    }

    public static List<LogProblem> convert(Path writelog, SpyLogWriter out) throws IOException {
        throw new IOException(writelog + ": reading Player writelog files is not built yet");
    }
}
