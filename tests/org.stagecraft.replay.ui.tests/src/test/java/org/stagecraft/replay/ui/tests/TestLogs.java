package org.stagecraft.replay.ui.tests;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.stagecraft.player.session.SessionFramer;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * The logs the tests open, in a workspace project: a shared recording as it is, the same recording
 * written as a spy log by the spy's own writer (as a Robot Session would have logged it), and a spy
 * log cut off in the middle.
 */
final class TestLogs {
    static final String TRACE = "pioneer-laser-sonar.gt.trace.jsonl";
    static final String PORT_LISTEN = "127.0.0.1:6665";

    private TestLogs() {
    }

    static IProject project() throws CoreException {
        IProject p = ResourcesPlugin.getWorkspace().getRoot().getProject("replay-ui-tests");
        if (!p.exists()) {
            p.create(null);
        }
        if (!p.isOpen()) {
            p.open(null);
        }
        return p;
    }

    /** The shared recording copied into the project. */
    static IFile trace() throws Exception {
        IFile f = project().getFile(TRACE);
        if (!f.exists()) {
            Files.copy(TraceCorpus.file(TRACE), f.getLocation().toPath());
            f.refreshLocal(IResource.DEPTH_ZERO, null);
        }
        return f;
    }

    /** The recording written by {@link SpyLogWriter} into {@code name}, with chunks of {@code chunkSize} bytes. */
    static IFile spyLog(String name, int chunkSize) throws Exception {
        IFile f = project().getFile(name);
        Path out = f.getLocation().toPath();
        Files.deleteIfExists(out);
        try (FileChannel ch = FileChannel.open(out, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                SpyLogWriter w = SpyLogWriter.create(ch, Map.of("scenario", "replay-ui test"), chunkSize)) {
            write(TraceCorpus.file(TRACE), w);
        }
        f.refreshLocal(IResource.DEPTH_ZERO, null);
        return f;
    }

    /** A copy of {@code log} keeping only its first {@code fraction} of bytes (a crash mid-write). */
    static Path truncated(IFile log, double fraction) throws IOException {
        Path src = log.getLocation().toPath();
        byte[] all = Files.readAllBytes(src);
        Path cut = Files.createTempFile("truncated-", ".mcap");
        Files.write(cut, java.util.Arrays.copyOf(all, (int) (all.length * fraction)));
        return cut;
    }

    private static long nanos(double t) {
        return Math.round(t * 1e9);
    }

    /** Frames the trace's byte streams and logs every event the way the spy does. */
    private static void write(Path trace, SpyLogWriter log) throws IOException {
        try (Feeder f = new Feeder(trace, log)) {
            f.writeUntil(Double.MAX_VALUE);
        }
    }

    /**
     * Writes a trace into a spy log step by step, as a running spy would: {@link #writeUntil} logs the
     * recording up to a time, so a test can open the log while it grows.
     */
    static final class Feeder implements AutoCloseable {
        private final TraceReader reader;
        private final SpyLogWriter log;
        private final SessionFramer framer;
        private TraceRecord pending;
        private double last;

        Feeder(Path trace, SpyLogWriter log) throws IOException {
            this.reader = new TraceReader(trace);
            this.log = log;
            this.framer = new SessionFramer(e -> {
                try {
                    log.wire(nanos(e.t()), e.stream().conn(), e.stream().port(), e.stream().dir(), e.event());
                } catch (IOException ex) {
                    throw new UncheckedIOException(ex);
                }
            });
        }

        /** Logs every record up to {@code seconds} (trace time); false when the trace is used up. */
        boolean writeUntil(double seconds) throws IOException {
            for (TraceRecord r = pending != null ? pending : reader.next(); r != null; r = reader.next()) {
                pending = null;
                switch (r) {
                    case TraceRecord.Header h -> {
                    }
                    case TraceRecord.Chunk c -> {
                        if (c.t() > seconds) {
                            pending = r;
                            return true;
                        }
                        last = c.t();
                        framer.chunk(c.t(), c.stream(), c.data());
                    }
                    case TraceRecord.Lifecycle l -> {
                        if (l.t() > seconds) {
                            pending = r;
                            return true;
                        }
                        last = l.t();
                        if (l.isClose()) {
                            framer.close(l.t(), l.conn());
                            log.connectionClosed(nanos(l.t()), l.conn(), "closed");
                        } else {
                            log.connectionOpened(nanos(l.t()), l.conn(), "127.0.0.1:" + (40000 + l.conn()), PORT_LISTEN,
                                    "127.0.0.1:7665");
                        }
                    }
                }
            }
            return false;
        }

        @Override
        public void close() throws IOException {
            framer.endAll(last);
            reader.close();
        }
    }
}
