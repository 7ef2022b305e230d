package org.stagecraft.views.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.Test;
import org.stagecraft.scene.DefaultLayers;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.RobotId;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.views.FramePixels;
import org.stagecraft.views.RendererExtensionRegistry;
import org.stagecraft.views.RendererExtensionRegistry.Contribution;
import org.stagecraft.views.StreamRenderer;

/** The renderers extension point: built-ins, a user's renderer, broken contributions; the perspective. */
class RendererRegistryTest {

    @Test
    void builtInsAndAUsersRendererLoadAndBrokenOnesAreReported() {
        List<IStatus> problems = new ArrayList<>();
        Map<String, Contribution> loaded = RendererExtensionRegistry.load(Platform.getExtensionRegistry(), problems::add);
        for (LayerSpec l : DefaultLayers.create()) {
            assertTrue(loaded.containsKey(l.rendererId()), "default layer renderer " + l.rendererId());
        }
        assertTrue(loaded.containsKey("org.stagecraft.views.ranger"));
        Contribution user = loaded.get("org.stagecraft.views.tests.sonarAverage");
        assertNotNull(user);
        assertEquals(0xFF00FF, user.rgb());
        assertEquals(StreamPattern.parse("type=128 dev=62"), user.defaultPattern());
        assertEquals("org.stagecraft.views.tests", user.contributor());

        assertEquals(3, problems.size(), problems.toString()); // duplicate id, bad colour, bad pattern
        assertTrue(problems.stream().anyMatch(p -> p.getMessage().contains("already has id 'org.stagecraft.views.laser'")));
        assertTrue(problems.stream().anyMatch(p -> p.getMessage().contains("defaultColour 'blue'")));
        assertTrue(problems.stream().allMatch(p -> p.getMessage().contains("plug-in org.stagecraft.views.tests")));

        // classes that cannot serve are reported when a layer asks for them; the others are created
        problems.clear();
        List<Map.Entry<LayerSpec, StreamRenderer>> made = RendererExtensionRegistry.instantiate(List.of(
                loaded.get("org.stagecraft.views.tests.missing").layer("a", 0),
                loaded.get("org.stagecraft.views.tests.notARenderer").layer("b", 1),
                user.layer("c", 2),
                new LayerSpec("d", "com.example.uninstalled", "Gone", StreamPattern.any(), true, 0, 1, 3)),
                loaded, problems::add);
        assertEquals(1, made.size());
        assertEquals("c", made.get(0).getKey().id());
        assertEquals(3, problems.size(), problems.toString());
    }

    @Test
    void theWorkedExampleDrawsTheDerivedStreamAroundTheRobot() throws Exception {
        RecordedScene rec = new RecordedScene(150);
        Contribution user = RendererExtensionRegistry.load(Platform.getExtensionRegistry(), p -> { })
                .get("org.stagecraft.views.tests.sonarAverage");
        double mean = 1.25;
        StreamKey derived = new StreamKey(RecordedScene.PLAYER, "127.0.0.1:40001", 128, 62, 0, 1);
        rec.layer(user.layer("average", 0), user.create(), new StreamMessage(derived, 0, mean));
        Pose2 robot = rec.world.robot(new RobotId(RecordedScene.PLAYER)).pose();
        rec.camera.centreOn(robot.x(), robot.y());
        rec.camera.setMetresPerPixel(0.01);
        try (GlHarness gl = new GlHarness(320, 320)) {
            FramePixels f = gl.frame(rec.scene);
            int onCircle = 0;
            for (int i = 0; i < SonarAverageRenderer.SEGMENTS; i++) {
                double a = 2 * Math.PI * i / SonarAverageRenderer.SEGMENTS;
                int col = rec.camera.pixelColumn(robot.x() + mean * Math.cos(a));
                int row = rec.camera.pixelRow(robot.y() + mean * Math.sin(a));
                if (f.contains(col, row)) {
                    assertTrue(FramePixels.close(0xFF00FF, f.rgb(col, row), 2), "circle vertex " + i);
                    onCircle++;
                }
            }
            assertEquals(SonarAverageRenderer.SEGMENTS, onCircle, "the whole circle is in the frame");
            int centre = f.rgb(rec.camera.pixelColumn(robot.x()), rec.camera.pixelRow(robot.y()));
            assertTrue(!FramePixels.close(0xFF00FF, centre, 40), "nothing drawn at the centre");
        }
    }

    @Test
    void theStagecraftPerspectiveShowsARobotView() throws Exception {
        IWorkbenchPage page = PlatformUI.getWorkbench().showPerspective("org.stagecraft.ui.perspective",
                PlatformUI.getWorkbench().getActiveWorkbenchWindow());
        assertNotNull(page.findViewReference("org.stagecraft.views.robot"), "the Robot View is in the perspective");
    }
}
