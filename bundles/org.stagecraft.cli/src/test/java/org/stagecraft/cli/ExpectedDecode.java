package org.stagecraft.cli;

import org.stagecraft.recording.fuzz.FramingCheck;

/**
 * What {@code stagecraft decode} must do with a fuzzed variant, from what reading it independently
 * gave ({@link FramingCheck.Outcome}): exit 0 and nothing on stderr for a file read whole; for one the
 * reader refused, exit 1 with the reader's message when nothing came before the bad line, else exit 3
 * with the message and that nothing after the line was read.
 */
record ExpectedDecode(int code, String err) {

    static ExpectedDecode of(FramingCheck.Outcome o) {
        String refusal = o.refusal();
        if (refusal == null) {
            return new ExpectedDecode(ExitCode.DONE, "");
        }
        if (o.events() == 0) {
            return new ExpectedDecode(ExitCode.FAILED, "stagecraft decode: " + refusal + System.lineSeparator());
        }
        return new ExpectedDecode(ExitCode.LOSSES,
                "stagecraft decode: " + refusal + "; nothing after that line was read" + System.lineSeparator());
    }
}
