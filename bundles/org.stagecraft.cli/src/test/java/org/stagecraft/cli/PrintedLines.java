package org.stagecraft.cli;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** What a command prints (its stderr), for a test to wait for a line of it. */
final class PrintedLines extends ByteArrayOutputStream {
    synchronized String text() {
        return toString(StandardCharsets.UTF_8);
    }

    /** Waits for {@code p} to match; returns its first group. */
    String await(Pattern p, long timeoutMs) throws InterruptedException {
        return awaitMatch(p, timeoutMs).group(1);
    }

    /** Waits for {@code p} to match; fails naming it and what was printed. */
    Matcher awaitMatch(Pattern p, long timeoutMs) throws InterruptedException {
        long deadline = System.currentTimeMillis() + timeoutMs;
        while (System.currentTimeMillis() < deadline) {
            Matcher m = p.matcher(text());
            if (m.find()) {
                return m;
            }
            synchronized (this) {
                wait(50); // woken by write(); the timeout only bounds a missed notify
            }
        }
        throw new AssertionError("no line matching " + p + " in:\n" + text());
    }

    @Override
    public synchronized void write(byte[] b, int off, int len) {
        super.write(b, off, len);
        notifyAll();
    }
}
