package org.stagecraft.demo.ui;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.ui.view.ToolsModel;
import org.stagecraft.views.FramePixels;
import org.stagecraft.views.RobotView;

import com.google.gson.GsonBuilder;

/**
 * What the demo did, written as JSON for whoever started it (a test, a script): the phase, the error
 * if it failed, the Player used, and once a second the frames each Robot View has drawn and the size
 * of the spy log, so that "the views drew and the log grew" can be checked from outside the product.
 * The last sample also counts the coloured pixels of each view's frame. Written to a temporary file
 * and moved, so a reader never sees half a file. {@link #finish} runs on the UI thread (it reads the views' frames back).
 */
final class DemoStatus {
    private static final int MAX_SAMPLES = 600;

    private final @Nullable Path file;
    private final long start = System.nanoTime();
    private final Map<String, @Nullable Object> fields = new LinkedHashMap<>();
    private final List<Map<String, Object>> samples = new ArrayList<>();

    DemoStatus(@Nullable Path file) {
        this.file = file;
        fields.put("phase", "starting");
    }

    synchronized void put(String key, @Nullable Object value) {
        fields.put(key, value);
        write();
    }

    synchronized void sample(List<RobotView> views, @Nullable Path spyLog) {
        Map<String, Object> s = new LinkedHashMap<>();
        s.put("t", Math.round(seconds() * 10) / 10.0);
        s.put("frames", views.stream().map(v -> v.frames()).toList());
        s.put("spyLogBytes", size(spyLog));
        samples.add(s);
        if (samples.size() > MAX_SAMPLES) {
            samples.remove(1); // keep the first sample: it is the baseline of "grew"
        }
        fields.put("samples", samples);
        fields.put("tools", ToolsModel.get().rows().stream().map(r -> Map.of("part", r.part(), "state", r.state().name(),
                "pid", r.pid())).toList());
        write();
    }

    /** The final look at the views: frames so far, then one frame read back and its coloured pixels. */
    synchronized void finish(List<RobotView> views, @Nullable Path spyLog) {
        sample(views, spyLog);
        List<Map<String, Object>> out = new ArrayList<>();
        for (RobotView v : views) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("id", v.getViewSite().getId() + (v.getViewSite().getSecondaryId() == null ? ""
                    : ":" + v.getViewSite().getSecondaryId()));
            m.put("frames", v.frames());
            FramePixels frame = v.capture();
            m.put("width", frame == null ? 0 : frame.width());
            m.put("height", frame == null ? 0 : frame.height());
            m.put("colouredPixels", frame == null ? 0 : ViewPixels.coloured(frame));
            out.add(m);
        }
        fields.put("views", out);
        fields.put("phase", "finished");
        write();
    }

    double seconds() {
        return (System.nanoTime() - start) / 1e9;
    }

    private static long size(@Nullable Path p) {
        try {
            return p == null ? -1 : Files.size(p);
        } catch (IOException e) {
            return -1;
        }
    }

    private void write() {
        if (file == null) {
            return;
        }
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            Path tmp = Files.createTempFile(file.toAbsolutePath().getParent(), "status", ".tmp");
            Files.writeString(tmp, new GsonBuilder().setPrettyPrinting().serializeNulls().create().toJson(fields));
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException e) {
            DemoLog.warn("cannot write the status file " + file + ": " + e.getMessage());
        }
    }
}
