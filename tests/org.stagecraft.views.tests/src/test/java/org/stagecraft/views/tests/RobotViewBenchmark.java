package org.stagecraft.views.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.swt.widgets.Display;
import org.junit.jupiter.api.Test;
import org.stagecraft.player.msg.Geometry;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.scene.DefaultLayers;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.Payloads;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.views.RobotScene;
import org.stagecraft.views.renderers.LaserRenderer;
import org.stagecraft.views.renderers.Position2dRenderer;
import org.stagecraft.views.renderers.SonarRenderer;

/**
 * Benchmark, not a test (not in the test run; {@code ./stagecraft bench views} runs it): frame time, fps
 * and CPU per frame of an 800x600 Robot View canvas drawing N robots, each with a 180-beam laser, a
 * 16-sonar ring and its pose, from recorded data (the single-robot session copied to N Player ports and
 * spread on a grid). Every frame gets new data for every robot, so every frame rebuilds and uploads all
 * geometry: the worst case, as when all robots stream at once. Frames are swapped (swap interval 0).
 *
 * <p>CPU per frame is the process CPU time (all threads: Mesa's llvmpipe rasteriser threads included) over
 * the frames drawn; the UI thread's own share is printed separately. Figures go to stdout and to
 * target/robot-view-benchmark.txt. STAGECRAFT_BENCH_SECONDS sets the measured time per case (default 5).
 */
class RobotViewBenchmark {
    static final int W = 800, H = 600;

    @Test
    void frameTimes() throws Exception {
        double seconds = Double.parseDouble(System.getenv().getOrDefault("STAGECRAFT_BENCH_SECONDS", "5"));
        List<StreamMessage> recorded = RecordedScene.recorded("pioneer-laser-sonar.gt.trace.jsonl");
        StringBuilder report = new StringBuilder();
        report.append(String.format("Robot View benchmark: %d x %d, %s, %d CPUs, %.0f s per case%n", W, H,
                System.getProperty("java.vm.name") + " " + Runtime.version(), Runtime.getRuntime().availableProcessors(),
                seconds));
        try (GlHarness gl = new GlHarness(W, H)) {
            for (int robots : new int[] { 6, 60 }) {
                report.append(run(gl, recorded, robots, seconds)).append('\n');
            }
        }
        System.out.println(report);
        Path out = Path.of("target", "robot-view-benchmark.txt");
        Files.createDirectories(out.getParent());
        Files.writeString(out, report);
    }

    /** One case: N robots, data changing every frame. */
    private String run(GlHarness gl, List<StreamMessage> recorded, int robots, double seconds) throws IOException {
        RecordedScene rec = new RecordedScene(10);
        RobotScene scene = rec.scene;
        scene.addLayer(new LayerSpec("sonar", DefaultLayers.SONAR, "Sonar", StreamPattern.parse("type=1 dev=62 subtype=1"),
                true, 0x19E633, 0.3, 10), new SonarRenderer());
        scene.addLayer(new LayerSpec("laser", DefaultLayers.LASER, "Laser", StreamPattern.parse("type=1 dev=6 subtype=1"),
                true, 0x1A4DFF, 0.35, 20), new LaserRenderer());
        scene.addLayer(new LayerSpec("robots", DefaultLayers.POSITION2D, "Robots", StreamPattern.parse("type=1 dev=4 subtype=1"),
                true, 0xE61A1A, 0.9, 30), new Position2dRenderer());

        // robots on a grid 12 m apart, the camera fitting them all
        int cols = (int) Math.ceil(Math.sqrt(robots * 4.0 / 3));
        int rows = (int) Math.ceil(robots / (double) cols);
        double spacing = 12;
        rec.camera.centreOn((cols - 1) * spacing / 2, (rows - 1) * spacing / 2);
        rec.camera.setMetresPerPixel(Math.max(cols * spacing / W, rows * spacing / H));

        // geometry of every robot (from the recorded GET_GEOM replies), then rounds of sensor data
        List<List<StreamMessage>> rounds = new ArrayList<>();
        List<StreamMessage> round = new ArrayList<>();
        boolean laser = false, sonar = false, pose = false;
        for (StreamMessage m : recorded) {
            StreamKey k = m.key();
            if (k.messageType() == 4 && k.subtype() == 1) {
                for (int i = 0; i < robots; i++) {
                    rec.world.accept(moved(m, RecordedScene.PLAYER, address(i)));
                }
            }
            if (k.messageType() != 1) {
                continue;
            }
            boolean l = k.deviceType() == 6 && k.subtype() == 1, s = k.deviceType() == 62 && k.index() == 0 && k.subtype() == 1,
                    p = k.deviceType() == 4 && k.subtype() == 1;
            if (l || s || p) {
                round.add(m);
                laser |= l;
                sonar |= s;
                pose |= p;
                if (laser && sonar && pose) {
                    rounds.add(round);
                    round = new ArrayList<>();
                    laser = sonar = pose = false;
                }
            }
        }

        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        com.sun.management.OperatingSystemMXBean os = (com.sun.management.OperatingSystemMXBean) ManagementFactory
                .getOperatingSystemMXBean();
        long warmupEnd = System.nanoTime() + 2_000_000_000L;
        int frame = 0;
        while (System.nanoTime() < warmupEnd) {
            feed(rec, rounds.get(frame++ % rounds.size()), robots, cols, spacing);
            gl.frame(scene, false);
        }
        List<Long> times = new ArrayList<>();
        long cpu0 = os.getProcessCpuTime(), ui0 = threads.getCurrentThreadCpuTime(), t0 = System.nanoTime();
        long end = t0 + (long) (seconds * 1e9);
        int vertices = 0;
        while (System.nanoTime() < end) {
            long f0 = System.nanoTime();
            feed(rec, rounds.get(frame++ % rounds.size()), robots, cols, spacing);
            gl.frame(scene, false);
            times.add(System.nanoTime() - f0);
            Display.getCurrent().readAndDispatch(); // keep the UI responsive as the view would
        }
        long wall = System.nanoTime() - t0, cpu = os.getProcessCpuTime() - cpu0, ui = threads.getCurrentThreadCpuTime() - ui0;
        for (String id : List.of("sonar", "laser", "robots")) {
            vertices += ((org.stagecraft.views.ShapeRenderer) scene.renderer(id)).vertexCount();
        }
        assertTrue(times.size() > 0);
        long[] sorted = times.stream().mapToLong(Long::longValue).sorted().toArray();
        int n = sorted.length;
        double meanMs = wall / 1e6 / n;
        return String.format("%2d robots: %6d frames, %7.1f fps, frame time mean %.2f ms, p50 %.2f ms, p95 %.2f ms;"
                + " CPU per frame %.2f ms (process, all threads), UI thread %.2f ms; %d vertices per frame; load avg %.2f",
                robots, n, n / (wall / 1e9), meanMs, sorted[n / 2] / 1e6, sorted[(int) (n * 0.95)] / 1e6, cpu / 1e6 / n,
                ui / 1e6 / n, vertices, os.getSystemLoadAverage());
    }

    /** The same message as if it came from another robot (another Player address). */
    private static StreamMessage moved(StreamMessage m, String fromAddress, String toAddress) {
        StreamKey k = m.key();
        return new StreamMessage(new StreamKey(k.source().equals(fromAddress) ? toAddress : k.source(),
                k.destination().equals(fromAddress) ? toAddress : k.destination(), k.messageType(), k.deviceType(),
                k.index(), k.subtype()), m.timeNanos(), m.payload());
    }

    private static String address(int i) {
        return "127.0.0.1:" + (6665 + i);
    }

    /** One round of recorded data for every robot, the poses moved to the robot's grid cell. */
    private static void feed(RecordedScene rec, List<StreamMessage> round, int robots, int cols, double spacing) {
        for (int i = 0; i < robots; i++) {
            double ox = (i % cols) * spacing, oy = (i / cols) * spacing;
            for (StreamMessage m : round) {
                StreamMessage moved = moved(m, RecordedScene.PLAYER, address(i));
                if (moved.key().deviceType() == 4 && Payloads.body(moved) instanceof Position2d.State s) {
                    moved = new StreamMessage(moved.key(), moved.timeNanos(), new Position2d.State(
                            new Geometry.Pose2d(s.pos().px() + ox, s.pos().py() + oy, s.pos().pa()), s.vel(), s.stall()));
                    rec.world.accept(moved);
                    rec.scene.feed("robots").accept(moved);
                } else if (moved.key().deviceType() == 6) {
                    rec.scene.feed("laser").accept(moved);
                } else {
                    rec.scene.feed("sonar").accept(moved);
                }
            }
        }
    }

}
