package org.stagecraft.replay.analysis;

import java.io.IOException;
import java.io.UncheckedIOException;

import org.stagecraft.recording.trace.TraceCorpus;

/** The shared single-robot recording as a list log, read once for all tests. */
final class AnalysisTestTraces {
    private static ListLog pioneer;

    private AnalysisTestTraces() {
    }

    static synchronized ListLog pioneer() {
        if (pioneer == null) {
            try {
                pioneer = ListLog.ofTrace(TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl"));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return pioneer;
    }
}
