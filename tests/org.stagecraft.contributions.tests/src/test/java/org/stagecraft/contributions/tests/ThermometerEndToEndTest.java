package org.stagecraft.contributions.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.FileLocator;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.contributions.tests.ThermometerCodec.Temperature;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.replay.analysis.Series;
import org.stagecraft.replay.export.ExportFilter;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.ui.PlotView;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.replay.ui.internal.FieldTreeContent;
import org.stagecraft.replay.ui.internal.LogExport;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;
import org.stagecraft.tests.support.Await;
import org.stagecraft.tools.session.Ports;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.RobotSessionLaunchDelegate;
import org.stagecraft.tools.ui.launch.SessionParts;

/**
 * The thermometer of docs/extending-decoders.md and docs/stream-bus.md, contributed by this bundle's
 * plugin.xml (a decoder for the made-up interface 300 and a processor deriving degrees Fahrenheit), read by
 * the real extension registry, travels the whole way: a live Robot Session's spy decodes it, the workbench
 * bus carries it and the derived stream; the spy log it wrote opens in the Session Log editor with the
 * readings in the inspector and both streams in the Plot; and a recorded log of it opens, inspects and
 * exports with its fields named.
 *
 * <p>No Player driver provides a thermometer, so a stand-in (standin/thermometer-player.py) plays Player's
 * part on the wire: the banner, then the messages this test encoded.
 */
@Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ThermometerEndToEndTest {
    private static final Duration WAIT = Duration.ofSeconds(60);
    private static final int READINGS = 40;
    private static final String DERIVED = "type=128 dev=300 index=0 | value";
    private static final String CELSIUS = "thermometer.celsius";

    private final List<ILaunch> launches = new ArrayList<>();
    private Path tmp;
    private IProject project;

    @BeforeEach
    void setUp() throws Exception {
        tmp = Files.createTempDirectory("stagecraft-thermometer");
        project = ResourcesPlugin.getWorkspace().getRoot().getProject("thermometer-" + System.nanoTime());
        project.create(new NullProgressMonitor());
        project.open(new NullProgressMonitor());
    }

    @AfterEach
    void tearDown() throws Exception {
        for (ILaunch l : launches) {
            if (!l.isTerminated()) {
                l.terminate();
            }
        }
        Await.ui(() -> page().closeAllEditors(false));
        project.delete(true, true, new NullProgressMonitor());
    }

    private static IWorkbenchPage page() {
        return PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
    }

    private static double celsius(int i) {
        return 18.0 + 0.25 * i;
    }

    /** What the thermometer's Player sends after the banner: READINGS DATA TEMPERATURE messages of thermometer:0. */
    private static byte[] readings(int port) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (int i = 0; i < READINGS; i++) {
            out.writeBytes(reading(port, i));
        }
        return out.toByteArray();
    }

    private static byte[] reading(int port, int i) {
        MessageHeader h = new MessageHeader(0, port, ThermometerCodec.THERMOMETER, 0, MessageType.DATA.code(),
                ThermometerCodec.TEMPERATURE, 1.0 + 0.1 * i, i, 8);
        return PlayerEncoder.encode(h, new Temperature(celsius(i)));
    }

    /** What a client says first (Player sends data only once a client has spoken): a device list request. */
    private static byte[] request(int port) {
        return PlayerEncoder.encode(new MessageHeader(0, port, 1, 0, MessageType.REQ.code(), 1, 0.0, 0, 0),
                org.stagecraft.player.codec.EmptyBody.INSTANCE);
    }

    private Path standIn() throws Exception {
        URL url = FileLocator.toFileURL(Platform.getBundle("org.stagecraft.contributions.tests")
                .getEntry("standin/thermometer-player.py"));
        Path target = tmp.resolve("thermometer-player.py");
        try (InputStream in = url.openStream()) {
            Files.copy(in, target);
        }
        Files.setPosixFilePermissions(target, PosixFilePermissions.fromString("rwxr-xr-x"));
        return target;
    }

    @Test
    void aLiveSessionDecodesTheContributedInterfaceAndTheWorkbenchBusDerivesItsStream() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        byte[] sent = readings(port);
        Path messages = tmp.resolve("readings.bin");
        Files.write(messages, sent);
        IFile cfg = project.getFile("thermometer.cfg");
        Files.writeString(cfg.getLocation().toPath(), """
                # a driver of one's own that provides the made-up interface "thermometer"
                driver
                (
                  name "thermometerdriver"
                  plugin "libthermometerdriver"
                  provides [ "thermometer:0" ]
                )
                """);
        project.refreshLocal(IResource.DEPTH_INFINITE, new NullProgressMonitor());

        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null,
                lm.generateLaunchConfigurationName("thermometer"));
        wc.setAttribute(LaunchAttributes.CFG, cfg.getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, standIn().toString());
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, Map.of("STANDIN_MESSAGES", messages.toString()));
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, port);
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, "spy-logs");
        wc.setAttribute(LaunchAttributes.TOOLS, List.<String>of());

        // the views listen on the workbench bus: subscribed before the streams exist
        List<Object> decoded = new CopyOnWriteArrayList<>();
        List<StreamMessage> derived = new CopyOnWriteArrayList<>();
        Subscription readingsOnBus = WorkbenchBus.get().subscribe(StreamPattern.parse("src=*:" + port + " type=1 dev=300 subtype=1"),
                DeliveryPolicy.lossless(1024), m -> decoded.add(((SpyMessage) m.payload()).message().body()));
        Subscription derivedOnBus = WorkbenchBus.get().subscribe(StreamPattern.parse("src=*:" + port + " type=128 dev=300"),
                DeliveryPolicy.lossless(1024), derived::add);
        ILaunch launch = wc.launch(ILaunchManager.RUN_MODE, new NullProgressMonitor());
        launches.add(launch);
        SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
        assertNotNull(parts, "the session runs when launch returns");
        Path log = parts.session().config().log();

        // a robot program's side: the banner, a request, then every reading, byte for byte through the spy
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            DataInputStream in = new DataInputStream(s.getInputStream());
            byte[] banner = new byte[32];
            in.readFully(banner);
            assertTrue(new String(banner, StandardCharsets.US_ASCII).startsWith("Player v.3.1.1"));
            OutputStream out = s.getOutputStream();
            out.write(request(port));
            out.flush();
            byte[] got = new byte[sent.length];
            in.readFully(got);
            assertArrayEquals(sent, got, "the spy relays the readings unchanged");
        }

        // live: the spy decoded them with the contributed decoder ...
        Await.until(READINGS + " readings on the workbench bus", WAIT, () -> decoded.size() == READINGS);
        readingsOnBus.close();
        for (int i = 0; i < READINGS; i++) {
            assertEquals(new Temperature(celsius(i)), decoded.get(i), "reading " + i + " decoded by the spy");
        }
        // ... and the contributed processor, running on the workbench bus, derived Fahrenheit from them
        assertTrue(WorkbenchBus.processorIds().contains("org.stagecraft.contributions.tests.fahrenheit"),
                "the contributed processor runs on the workbench bus: " + WorkbenchBus.processorIds());
        Await.until(READINGS + " derived readings on the workbench bus", WAIT, () -> derived.size() == READINGS);
        derivedOnBus.close();
        for (int i = 0; i < READINGS; i++) {
            StreamMessage d = derived.get(i);
            assertEquals(Fahrenheit.fahrenheit(celsius(i)), d.payload(), "derived " + i);
            assertEquals(Fahrenheit.TYPE, d.key().messageType());
            assertEquals("127.0.0.1:" + port, d.key().source(), "the reading's addresses");
        }

        // the session ends; the spy log it wrote opens in the Session Log editor, decoded the same way
        parts.stopNow();
        project.getFolder("spy-logs").refreshLocal(IResource.DEPTH_ONE, new NullProgressMonitor());
        IFile logFile = project.getFolder("spy-logs").getFile(log.getFileName().toString());
        assertTrue(logFile.exists(), "the session's spy log in the project: " + log);
        SessionLogEditor editor = open(logFile);
        inspectorShowsTheReadings(editor);
        plotShowsTheReadingsAndTheDerivedStream(editor);
    }

    @Test
    void aRecordedLogOpensInspectsPlotsAndExportsTheContributedInterface() throws Exception {
        // a recording of the same conversation (player-trace format): banner, request, readings
        int port = 6665;
        byte[] banner = "Player v.3.1.1".getBytes(StandardCharsets.US_ASCII);
        byte[] padded = new byte[32];
        System.arraycopy(banner, 0, padded, 0, banner.length);
        List<String> lines = new ArrayList<>(List.of(
                "{\"format\":\"player-trace\",\"version\":1,\"scenario\":\"thermometer\"}",
                "{\"conn\":1,\"event\":\"open\",\"t\":0.5,\"port\":" + port + "}",
                data(0.500001, port, "s2c", padded),
                data(0.6, port, "c2s", request(port))));
        for (int i = 0; i < READINGS; i++) {
            lines.add(data(1.0 + 0.1 * i, port, "s2c", reading(port, i))); // a reading every 100 ms
        }
        lines.add("{\"conn\":1,\"event\":\"close\",\"t\":6.0,\"port\":" + port + "}");
        String trace = String.join("\n", lines) + "\n";
        IFile file = project.getFile("thermometer.trace.jsonl");
        Files.writeString(file.getLocation().toPath(), trace);
        project.refreshLocal(IResource.DEPTH_INFINITE, new NullProgressMonitor());

        SessionLogEditor editor = open(file);
        inspectorShowsTheReadings(editor);
        plotShowsTheReadingsAndTheDerivedStream(editor);

        // the export decodes as the editor does: the contributed field is a CSV column and a JSON field
        Path csv = tmp.resolve("thermometer.csv");
        IStatus s = finish(LogExport.start(editor.file(), LogExport.Kind.CSV, ExportFilter.all(), editor.columns().registry(), csv));
        assertTrue(s.isOK(), s.getMessage());
        List<String> rows = Files.readAllLines(csv, StandardCharsets.UTF_8);
        List<String> header = List.of(rows.get(0).split(","));
        int celsius = header.indexOf("celsius");
        assertTrue(celsius > 0, "a celsius column: " + header);
        List<Double> exported = new ArrayList<>();
        for (String line : rows.subList(1, rows.size())) {
            if (line.contains(",thermometer,")) {
                exported.add(Double.parseDouble(line.split(",", -1)[celsius]));
            }
        }
        List<Double> expected = new ArrayList<>();
        for (int i = 0; i < READINGS; i++) {
            expected.add(celsius(i));
        }
        assertEquals(expected, exported, "every reading, exact");

        Path mcap = tmp.resolve("thermometer.mcap");
        s = finish(LogExport.start(editor.file(), LogExport.Kind.MCAP, ExportFilter.all(), editor.columns().registry(), mcap));
        assertTrue(s.isOK(), s.getMessage());
        // the summary section (never compressed) holds the channels and their JSON Schemas
        String bytes = new String(Files.readAllBytes(mcap), StandardCharsets.ISO_8859_1);
        assertTrue(bytes.contains("/" + port + "/1/thermometer:0/DATA/TEMPERATURE"), "a channel named by the contributed names");
        assertTrue(bytes.contains("\"celsius\""), "its JSON Schema has the contributed field");
    }

    private static String data(double t, int port, String dir, byte[] bytes) {
        return "{\"t\":" + t + ",\"conn\":1,\"port\":" + port + ",\"dir\":\"" + dir + "\",\"data\":\""
                + Base64.getEncoder().encodeToString(bytes) + "\"}";
    }

    private static IStatus finish(Job job) {
        Await.until("the export job", WAIT, () -> job.getResult() != null);
        return job.getResult();
    }

    private SessionLogEditor open(IFile file) {
        SessionLogEditor e = Await.ui(() -> (SessionLogEditor) IDE.openEditor(page(), file, SessionLogEditor.ID, true));
        Await.untilUi("the editor to read " + file.getName(), WAIT, () -> !e.reading() && e.log() != null);
        assertTrue(e.columns().registry() == Contributions.workbench().codecs(), "the editor decodes with the workbench's codecs");
        return e;
    }

    /** The inspector lists the readings by the contributed names, with their field. */
    private static void inspectorShowsTheReadings(SessionLogEditor e) {
        Await.ui(() -> {
            e.inspector().setFilter("thermometer:0", "");
            return null;
        });
        Await.untilUi("the inspector's readings", WAIT, () -> e.inspector().window().rows().size() == READINGS
                && e.inspector().window().rows().stream().allMatch(r -> e.columns().device(r.message()).equals("thermometer:0")));
        Await.ui(() -> {
            var row = e.inspector().table().getItem(3);
            assertEquals("TEMPERATURE", row.getText(5), "the subtype's contributed name");
            assertTrue(row.getText(7).contains("celsius"), "the summary names the field: " + row.getText(7));
            e.inspector().selectRow(3);
            return null;
        });
        Await.untilUi("the selected reading's fields", WAIT, () -> e.inspector().fields().getInput() != null
                && FieldTreeContent.topNames(e.inspector().fields().getInput()).contains("celsius"));
        LogMessage shown = Await.ui(() -> e.inspector().detailed());
        assertEquals(new Temperature(celsius(3)), shown.decoded().body());
    }

    /** The Plot samples the logged readings and records the derived stream as the replay publishes it. */
    private static void plotShowsTheReadingsAndTheDerivedStream(SessionLogEditor e) throws Exception {
        // the readings by log time: live, two may arrive in one chunk and so share a time
        Map<Long, List<Double>> logged = new LinkedHashMap<>();
        try (LogCursor c = e.log().cursor(e.log().startNanos())) {
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                if (m.decoded() != null && m.decoded().body() instanceof Temperature t) {
                    logged.computeIfAbsent(m.timeNanos(), k -> new ArrayList<>()).add(t.celsius());
                }
            }
        }
        assertEquals(READINGS, logged.values().stream().mapToInt(List::size).sum(), "the log holds every reading");

        PlotView plot = Await.ui(e::showPlot);
        Await.ui(() -> {
            for (String s : List.copyOf(plot.seriesTexts())) {
                plot.removeSeries(s);
            }
            plot.addSeries(CELSIUS);
            plot.addSeries(DERIVED);
            e.replayer().seek(e.log().startNanos());
            e.replayer().setSpeed(16);
            e.replayer().play();
            return null;
        });
        // a derived point per time the replay published readings at (the last one at that time)
        Await.untilUi("the readings sampled and the derived stream recorded", WAIT, () -> !plot.sampling()
                && plot.series().size() == 2 && plot.series().get(0).matched() == READINGS
                && plot.series().get(1).size() == logged.size(),
                () -> "; sampling " + plot.sampling() + ", series " + plot.series().stream()
                        .map(x -> x.spec().label() + ": " + x.size() + " points, " + x.matched() + " matched").toList()
                        + ", " + logged.size() + " reading times, replay at " + e.replayer().position() + " of "
                        + e.log().startNanos() + ".." + e.log().endNanos());
        List<Series> series = Await.ui(plot::series);

        Series sampled = series.get(0);
        assertTrue(sampled.size() >= 2, "points drawn: " + sampled.size());
        for (int i = 0; i < sampled.size(); i++) {
            List<Double> at = logged.get(sampled.times()[i]);
            assertTrue(at != null && at.contains(sampled.values()[i]), "sampled point " + i + " is a reading at its time");
        }
        assertEquals(celsius(0), sampled.range()[0]);
        assertEquals(celsius(READINGS - 1), sampled.range()[1]);
        Series derived = series.get(1);
        for (int i = 0; i < derived.size(); i++) {
            List<Double> at = logged.get(derived.times()[i]);
            assertNotNull(at, "derived point " + i + " at the time of a reading");
            assertEquals(Fahrenheit.fahrenheit(at.get(at.size() - 1)), derived.values()[i], "derived point " + i);
        }
        Await.ui(() -> {
            e.replayer().pause();
            page().hideView(plot);
            return null;
        });
    }
}
