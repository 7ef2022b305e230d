package org.stagecraft.tools.process;

import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.stream.Collectors;

/**
 * Stands in for the IDE in {@link OrphanReaperTest}: a JVM of its own that starts one tool through
 * {@link SupervisedTool} (on a terminal or on pipes, as {@code -Dstagecraft.tools.pty} says), prints
 * the pids of the tool's whole tree and of the reaper, and then waits to be killed.
 * <p>
 * Argument: the tool's shell script; it must print {@code READY} once its children are started.
 */
public final class DyingIde {
    private DyingIde() {
    }

    public static void main(String[] args) throws Exception {
        SupervisedTool tool = new SupervisedTool(ToolSpec.of("doomed", List.of("sh", "-c", args[0]))
                .withReadiness(Readiness.line("READY"), ToolSpec.DEFAULT_READY_WITHIN), ToolListener.NONE);
        tool.start();
        ProcessHandle root = tool.process();
        List<ProcessHandle> children = root.descendants().toList();
        System.out.println("TREE " + root.pid() + " "
                + children.stream().map(h -> String.valueOf(h.pid())).collect(Collectors.joining(" ")));
        ProcessHandle reaper = OrphanReaper.shared().process();
        System.out.println("REAPER " + (reaper != null ? reaper.pid() : "none"));
        System.out.flush();
        // until the test kills this JVM
        new CountDownLatch(1).await();
    }
}
