package org.stagecraft.spy.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

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
