package org.stagecraft.views.tests;

import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.scene.Camera;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.WorldModel;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.RobotScene;
import org.stagecraft.views.StreamRenderer;

/**
 * A scene holding the state of the recorded single-robot session at one moment: the world model fed with
 * everything up to the {@code n}-th laser scan, and the newest laser scan and ranger data of that moment.
 */
final class RecordedScene {
    static final String PLAYER = "127.0.0.1:6665";

    final WorldModel world = new WorldModel();
    final Camera camera = new Camera();
    final RobotScene scene = new RobotScene(world, camera, () -> { });
    StreamMessage laser, sonar, laserRanger;

    static Path trace(String name) {
        String dir = System.getProperty("stagecraft.traces");
        assertNotNull(dir, "-Dstagecraft.traces must name the trace corpus (tests/traces)");
        return Path.of(dir, name);
    }

    /** What a replay of the recorded session publishes: the spy's messages under the spy's keys. */
    static List<StreamMessage> recorded(String name) throws IOException {
        try (SessionLog log = SessionLogs.open(trace(name))) {
            return Replayer.allPublished(log);
        }
    }

    RecordedScene(int n) throws IOException {
        List<StreamMessage> msgs = recorded("pioneer-laser-sonar.gt.trace.jsonl");
        int scans = 0;
        for (StreamMessage m : msgs) {
            world.accept(m);
            StreamKey k = m.key();
            if (k.messageType() == 1 && k.deviceType() == 62 && k.subtype() == 1) {
                if (k.index() == 0) {
                    sonar = m;
                } else {
                    laserRanger = m;
                }
            }
            if (k.messageType() == 1 && k.deviceType() == 6 && k.subtype() == 1 && ++scans == n) {
                laser = m;
                break;
            }
        }
        assertNotNull(laser, "the trace has " + n + " laser scans");
        assertNotNull(sonar, "sonar data before scan " + n);
    }

    /** Adds a layer fed with {@code data} (as the bus would deliver it). */
    RecordedScene layer(LayerSpec spec, StreamRenderer renderer, StreamMessage... data) {
        scene.addLayer(spec, renderer);
        for (StreamMessage m : data) {
            scene.feed(spec.id()).accept(m);
        }
        return this;
    }

    void hideAll() {
        for (LayerSpec l : scene.layers()) {
            scene.updateLayer(l.visible(false));
        }
    }

    void show(String id, boolean visible) {
        for (LayerSpec l : scene.layers()) {
            if (l.id().equals(id)) {
                scene.updateLayer(l.visible(visible));
            }
        }
    }

    LayerSpec spec(String id) {
        return scene.layers().stream().filter(l -> l.id().equals(id)).findFirst().orElseThrow();
    }
}
