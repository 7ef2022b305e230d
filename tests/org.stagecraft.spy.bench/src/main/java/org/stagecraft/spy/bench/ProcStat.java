package org.stagecraft.spy.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/** CPU time and peak resident memory of processes, from Linux's /proc. */
final class ProcStat {
    /** USER_HZ: the unit of /proc/PID/stat's times; 100 on every Linux this runs on. */
    private static final double TICKS_PER_SECOND = 100.0;

    private ProcStat() {
    }

    /**
     * CPU seconds (user + system) the processes used, including their children that ended and were
     * waited for (socat forks a child per connection).
     */
    static double cpuSeconds(List<Long> pids) {
        double sum = 0;
        for (long pid : pids) {
            try {
                String stat = Files.readString(Path.of("/proc/" + pid + "/stat"));
                String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
                // after "pid (comm) ": state=0 ... utime=11 stime=12 cutime=13 cstime=14
                for (int i = 11; i <= 14; i++) {
                    sum += Long.parseLong(f[i]) / TICKS_PER_SECOND;
                }
            } catch (IOException | RuntimeException e) {
                // the process is gone: nothing more to count
            }
        }
        return sum;
    }

    /**
     * CPU seconds (user + system) of each kind of thread of the processes, by thread name with its
     * numbers taken out ("stagecraft-spy-", "C2 CompilerThread", "GC Thread#"), so that a
     * benchmark can say where a relay's time goes.
     */
    static Map<String, Double> cpuSecondsByThread(List<Long> pids) {
        Map<String, Double> byName = new TreeMap<>();
        for (long pid : pids) {
            try (var tasks = Files.list(Path.of("/proc/" + pid + "/task"))) {
                for (Path task : (Iterable<Path>) tasks::iterator) {
                    try {
                        String stat = Files.readString(task.resolve("stat"));
                        String name = stat.substring(stat.indexOf('(') + 1, stat.lastIndexOf(')')).replaceAll("[0-9]+", "#");
                        String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
                        byName.merge(name, (Long.parseLong(f[11]) + Long.parseLong(f[12])) / TICKS_PER_SECOND, Double::sum);
                    } catch (IOException | RuntimeException e) {
                        // the thread ended meanwhile
                    }
                }
            } catch (IOException | RuntimeException e) {
                // the process is gone
            }
        }
        return byName;
    }

    /**
     * The CPU time per message of each thread kind ({@code spent}: seconds per kind over the phase),
     * largest first; what threads that ended during the phase used (a connection's forwarding threads)
     * is the process's {@code total} less the rest.
     */
    static String cpuSpent(Map<String, Double> spent, double total, long messages) {
        Map<String, Double> all = new TreeMap<>(spent);
        double listed = spent.values().stream().mapToDouble(Double::doubleValue).sum();
        all.put("(threads that ended)", total - listed);
        StringBuilder sb = new StringBuilder();
        all.entrySet().stream().filter(e -> e.getValue() > 0).sorted(Map.Entry.<String, Double>comparingByValue().reversed()).limit(8)
                .forEach(e -> sb.append(String.format("%s%s %.2f µs", sb.isEmpty() ? "" : ", ", e.getKey(),
                        e.getValue() * 1e6 / messages)));
        return sb.toString();
    }

    /** Peak resident set (VmHWM) in MB, summed over the processes; NaN if unknown. */
    static double peakRssMb(List<Long> pids) {
        double sum = 0;
        boolean any = false;
        for (long pid : pids) {
            try {
                for (String line : Files.readAllLines(Path.of("/proc/" + pid + "/status"))) {
                    if (line.startsWith("VmHWM:")) {
                        sum += Long.parseLong(line.replaceAll("\\D", "")) / 1024.0;
                        any = true;
                    }
                }
            } catch (IOException | RuntimeException e) {
                // gone
            }
        }
        return any ? sum : Double.NaN;
    }
}
