package org.stagecraft.tools.process;

import java.io.IOException;
import java.io.OutputStream;
import java.lang.ProcessBuilder.Redirect;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.jdt.annotation.Nullable;

/**
 * Kills the tools this JVM started when the JVM dies, however it dies (SIGKILL, a crash, a lost
 * display), without a shutdown hook.
 * <p>
 * How: a tiny {@code /bin/sh} script, started once per JVM in a session of its own (so a Ctrl-C or
 * a closed terminal that takes the IDE down does not take it down too), reads lines from a pipe on
 * its standard input: {@code +PID} when a tool starts, {@code -PID} when it has ended. The JVM holds
 * the only write end of that pipe, and the kernel closes it when the JVM ends for any reason; the
 * script then reads end-of-file and kills what is still registered: each process, the process
 * group it leads (a tool on a pseudo-terminal leads its own), and every descendant (found through
 * {@code /proc}, since once a tool's parent is gone its children are re-parented), SIGTERM first,
 * SIGKILL after a grace.
 * <p>
 * Why not the alternatives: shutdown hooks do not run on SIGKILL or a crash; the SIGHUP a tool on a
 * terminal gets when its terminal closes is ignored by some tools and does not exist on the pipes
 * fallback; {@code PR_SET_PDEATHSIG} fires when the <em>thread</em> that forked ends, and Java starts
 * processes from arbitrary pool threads.
 * <p>
 * After a normal exit every tool has been unregistered, so the script just ends.
 */
public final class OrphanReaper {
    /** Seconds between SIGTERM and SIGKILL, in tenths (the script counts 0.1 s sleeps). */
    private static final int GRACE_TENTHS = 30;

    /**
     * The reaper's script. {@code $roots} holds the registered pids, space-separated. {@code tree}
     * prints them, the members of the process groups they lead and all their descendants.
     */
    static final String SCRIPT = """
            trap '' HUP INT PIPE
            roots=' '
            while IFS= read -r line; do
              case $line in
                +[0-9]*) roots="$roots${line#+} " ;;
                -[0-9]*) p=${line#-}; rest=' '
                         for q in $roots; do [ "$q" = "$p" ] || rest="$rest$q "; done
                         roots=$rest ;;
              esac
            done
            [ -n "$(echo $roots)" ] || exit 0
            tree() {
              found=$roots
              changed=1
              while [ $changed = 1 ]; do
                changed=0
                for s in /proc/[0-9]*/stat; do
                  pid=${s#/proc/}; pid=${pid%/stat}
                  case $found in *" $pid "*) continue ;; esac
                  { IFS= read -r l < "$s"; } 2>/dev/null || continue
                  set -- ${l##*) }
                  case $found in *" $2 "*) found="$found$pid "; changed=1; continue ;; esac
                  case $roots in *" $3 "*) found="$found$pid "; changed=1 ;; esac
                done
              done
              echo $found
            }
            victims=$(tree)
            for p in $roots; do kill -TERM -$p 2>/dev/null; done
            kill -TERM $victims 2>/dev/null
            i=0
            while [ $i -lt GRACE ]; do
              alive=
              for p in $victims; do
                { IFS= read -r l < /proc/$p/stat; } 2>/dev/null || continue
                set -- ${l##*) }
                [ "$1" = Z ] || alive=1
              done
              [ -z "$alive" ] && break
              sleep 0.1
              i=$((i + 1))
            done
            victims="$victims $(tree)"
            for p in $roots; do kill -KILL -$p 2>/dev/null; done
            kill -KILL $victims 2>/dev/null
            exit 0
            """.replace("GRACE", String.valueOf(GRACE_TENTHS));

    private static final OrphanReaper SHARED = new OrphanReaper();

    private final Set<Long> registered = new LinkedHashSet<>();
    private @Nullable Process script;
    private @Nullable OutputStream toScript;
    /** Why the script cannot run, once it has failed to start; then registering is a no-op. */
    private @Nullable String unavailable;

    OrphanReaper() {
    }

    /** The one reaper of this JVM. */
    public static OrphanReaper shared() {
        return SHARED;
    }

    /**
     * Registers a started tool: if this JVM dies while it runs, it and its descendants are killed.
     *
     * @return null, or why the tool is not protected (for the tool's console)
     */
    public synchronized @Nullable String register(long pid) {
        registered.add(pid);
        return send("+" + pid);
    }

    /** The tool has ended (its pid may be reused by an unrelated process from now on). */
    public synchronized void unregister(long pid) {
        if (registered.remove(pid)) {
            send("-" + pid);
        }
    }

    /** The reaper's own process, once started (for tests). */
    synchronized @Nullable ProcessHandle process() {
        return script != null ? script.toHandle() : null;
    }

    /** Called with the lock held. */
    private @Nullable String send(String line) {
        if (unavailable != null) {
            return unavailable;
        }
        for (int attempt = 0; attempt < 2; attempt++) {
            try {
                if (script == null || !script.isAlive()) {
                    // first use, or someone killed the script: a new one gets every live registration
                    start();
                    line = replay();
                }
                toScript.write((line + "\n").getBytes(StandardCharsets.US_ASCII));
                toScript.flush();
                return null;
            } catch (IOException e) {
                script = null;
                if (attempt == 1) {
                    unavailable = "cannot watch for the IDE's death (" + e.getMessage()
                            + "): if the IDE is killed, this tool may keep running";
                }
            }
        }
        return unavailable;
    }

    private String replay() {
        List<String> lines = new ArrayList<>();
        for (long pid : registered) {
            lines.add("+" + pid);
        }
        return String.join("\n", lines);
    }

    private void start() throws IOException {
        List<String> command = new ArrayList<>();
        // its own session: signals for the IDE's terminal or process group do not reach it
        for (String dir : List.of("/usr/bin", "/bin")) {
            if (Files.isExecutable(Path.of(dir, "setsid"))) {
                command.add(dir + "/setsid");
                break;
            }
        }
        command.addAll(List.of("/bin/sh", "-c", SCRIPT));
        ProcessBuilder pb = new ProcessBuilder(command).redirectOutput(Redirect.DISCARD).redirectError(Redirect.DISCARD);
        script = pb.start();
        toScript = script.getOutputStream();
    }
}
