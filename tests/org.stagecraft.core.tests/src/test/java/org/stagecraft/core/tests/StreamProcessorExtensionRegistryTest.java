package org.stagecraft.core.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.stagecraft.core.streams.StreamProcessorExtensionRegistry;
import org.stagecraft.core.streams.StreamProcessorExtensionRegistry.Contribution;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.StreamProcessors;
import org.stagecraft.streams.Subscription;

/** Stream processors contributed through org.stagecraft.core.streamProcessors, in a running OSGi runtime. */
class StreamProcessorExtensionRegistryTest {
    private static final String SONAR_AVERAGE = "org.stagecraft.core.tests.sonarAverage";

    private final List<IStatus> problems = new ArrayList<>();
    private final StreamBus bus = new StreamBus(Runnable::run); // deterministic: delivery on the publisher's thread

    @AfterEach
    void close() {
        bus.close();
    }

    private static double[] ring(double first) {
        double[] r = new double[16];
        for (int i = 0; i < r.length; i++) {
            r[i] = first + i;
        }
        return r;
    }

    @Test
    void contributedProcessorIsFound() {
        List<Contribution> loaded = StreamProcessorExtensionRegistry.load(Platform.getExtensionRegistry(), problems::add);
        Contribution sonar = loaded.stream().filter(c -> c.id().equals(SONAR_AVERAGE)).findFirst()
                .orElseThrow(() -> new AssertionError("not loaded: " + loaded + " problems " + problems));
        assertEquals("Sonar ring average", sonar.name());
        assertEquals("org.stagecraft.core.tests", sonar.contributor());
        assertTrue(sonar.processor() instanceof SonarAverageProcessor);
        // the one that fails only at start is loaded too; the two broken classes are not
        Set<String> ids = loaded.stream().map(Contribution::id).collect(Collectors.toSet());
        assertEquals(Set.of(SONAR_AVERAGE, "org.stagecraft.core.tests.failsToStart"), ids);
    }

    @Test
    void brokenContributionsAreReportedByPluginAndElementAndSkipped() {
        StreamProcessorExtensionRegistry.load(Platform.getExtensionRegistry(), problems::add);
        assertEquals(2, problems.size(), problems.toString());
        assertTrue(problems.stream().allMatch(s -> s.getSeverity() == IStatus.ERROR));
        assertTrue(problems.stream().allMatch(s -> s.getMessage().contains("plug-in org.stagecraft.core.tests")
                && s.getMessage().contains("<processor>")
                && s.getMessage().contains(StreamProcessorExtensionRegistry.EXTENSION_POINT)), problems.toString());
        assertTrue(problems.stream().anyMatch(s -> s.getMessage().contains("org.stagecraft.core.tests.missing")),
                problems.toString());
        assertTrue(problems.stream().anyMatch(s -> s.getMessage().contains("notAProcessor")
                && s.getMessage().contains("does not implement org.stagecraft.streams.StreamProcessor")),
                problems.toString());
    }

    @Test
    void startedProcessorPublishesASubscribableDerivedStream() {
        // subscribed before the derived stream exists
        List<StreamMessage> averages = new ArrayList<>();
        Subscription s = bus.subscribe(StreamPattern.parse("type=128 dev=5"), DeliveryPolicy.latestValue(),
                averages::add);

        StreamProcessors processors = StreamProcessorExtensionRegistry.startAll(bus, Platform.getExtensionRegistry(),
                problems::add);
        assertEquals(Set.of(SONAR_AVERAGE), processors.ids());
        assertEquals(3, problems.size(), problems.toString()); // two broken classes + one failing start
        assertTrue(problems.stream().anyMatch(p -> p.getMessage().contains("failsToStart")
                && p.getMessage().contains("start failed") && p.getMessage().contains("no sonar configured")),
                problems.toString());

        StreamKey ranges = new StreamKey("127.0.0.1:6665", "127.0.0.1:40312", 1, 5, 0, 1);
        bus.publish(new StreamMessage(ranges, 1_000L, ring(0))); // 0..15 -> 7.5
        assertEquals(1, averages.size());
        StreamMessage avg = averages.get(0);
        assertEquals(new StreamKey("127.0.0.1:6665", "127.0.0.1:40312", 128, 5, 0, 1), avg.key());
        assertTrue(avg.key().isUserDefined());
        assertEquals(7.5, avg.payload());
        assertEquals(1_000L, avg.timeNanos());
        assertTrue(bus.streams().contains(avg.key()));
        assertEquals(1, s.delivered());

        processors.stopAll();
        assertTrue(SonarAverageProcessor.stopped);
        bus.publish(new StreamMessage(ranges, 2_000L, ring(10)));
        assertEquals(1, averages.size(), "a stopped processor publishes nothing more");
    }
}
