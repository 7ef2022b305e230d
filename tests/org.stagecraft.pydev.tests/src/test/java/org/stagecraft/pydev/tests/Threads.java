package org.stagecraft.pydev.tests;

import java.util.Map;

/** A dump of every thread's stack, for the message of a wait that timed out. */
final class Threads {
    private Threads() {
    }

    static String dump() {
        StringBuilder b = new StringBuilder("\nthreads:\n");
        for (Map.Entry<Thread, StackTraceElement[]> e : Thread.getAllStackTraces().entrySet()) {
            b.append('"').append(e.getKey().getName()).append("\" ").append(e.getKey().getState()).append('\n');
            for (StackTraceElement s : e.getValue()) {
                b.append("    at ").append(s).append('\n');
            }
        }
        return b.toString();
    }
}
