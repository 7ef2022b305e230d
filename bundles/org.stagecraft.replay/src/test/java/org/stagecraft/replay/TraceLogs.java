package org.stagecraft.replay;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;

/** The shared traces as session logs, for the export tests. */
public final class TraceLogs {
    private TraceLogs() {
    }

    public static SessionLog open(Path trace) throws IOException {
        return SessionLogs.open(trace);
    }

    /** Every message of a log, from a cursor. */
    public static List<LogMessage> all(SessionLog log) throws IOException {
        List<LogMessage> out = new ArrayList<>();
        try (LogCursor c = log.cursor(Long.MIN_VALUE)) {
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                out.add(m);
            }
        }
        return out;
    }
}
