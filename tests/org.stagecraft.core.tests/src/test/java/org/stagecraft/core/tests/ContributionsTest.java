package org.stagecraft.core.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.junit.jupiter.api.Test;
import org.stagecraft.core.codec.DecoderExtensionRegistry;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.core.streams.StreamProcessorExtensionRegistry.Descriptor;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.xdr.XdrWriter;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.StreamProcessors;
import org.stagecraft.streams.Subscription;

/** The one host of contributions: its codecs, its processors (an instance per bus), the workbench bus running them. */
class ContributionsTest {
    private static final String SONAR_AVERAGE = "org.stagecraft.core.tests.sonarAverage";
    private static final StreamKey RANGES = new StreamKey("127.0.0.1:6665", "127.0.0.1:40312", 1, 5, 0, 1);

    private final List<IStatus> problems = new ArrayList<>();
    private final Contributions contributions = Contributions.load(Platform.getExtensionRegistry(), problems::add);

    private static double[] ring(double first) {
        double[] r = new double[16];
        for (int i = 0; i < r.length; i++) {
            r[i] = first + i;
        }
        return r;
    }

    @Test
    void itsCodecsDecodeTheContributedInterfaceAndItsDecoderUsesThem() {
        byte[] payload = new XdrWriter().float64(-3.25).toByteArray();
        DecodedMessage m = contributions.decoder().decode(new MessageHeader(0, 6665, 300, 0, 1, 1, 0.0, 0, payload.length),
                payload);
        assertEquals(new ThermometerCodec.Temperature(-3.25), m.body());
        assertSame(contributions.codecs(), contributions.decoder().registry());
        assertEquals("barometer", contributions.codecs().interfaceName(301));
        // read once for the workbench: every caller gets the same registry
        assertSame(Contributions.workbench().codecs(), DecoderExtensionRegistry.get());
    }

    @Test
    void brokenContributionsAreReportedWhenReadAndAFailingStartEachTimeABusStartsIt() {
        List<String> ids = contributions.processors().stream().map(Descriptor::id).toList();
        assertEquals(List.of(SONAR_AVERAGE, "org.stagecraft.core.tests.failsToStart"), ids);
        assertEquals(4, problems.size(), problems.toString()); // 2 broken decoders + 2 broken processor classes
        try (StreamBus a = new StreamBus(Runnable::run); StreamBus b = new StreamBus(Runnable::run)) {
            contributions.startProcessors(a).stopAll();
            contributions.startProcessors(b).stopAll();
        }
        assertEquals(6, problems.size(), problems.toString());
        assertTrue(problems.subList(4, 6).stream().allMatch(p -> p.getMessage().contains("failsToStart")
                && p.getMessage().contains("start failed")), problems.toString());
    }

    @Test
    void everyBusGetsAProcessorOfItsOwn() {
        try (StreamBus a = new StreamBus(Runnable::run); StreamBus b = new StreamBus(Runnable::run)) {
            List<Object> fromA = new ArrayList<>();
            List<Object> fromB = new ArrayList<>();
            a.subscribe(StreamPattern.parse("type=128 dev=5"), DeliveryPolicy.lossless(16), m -> fromA.add(m.payload()));
            b.subscribe(StreamPattern.parse("type=128 dev=5"), DeliveryPolicy.lossless(16), m -> fromB.add(m.payload()));
            StreamProcessors onA = contributions.startProcessors(a);
            StreamProcessors onB = contributions.startProcessors(b);
            assertEquals(Set.of(SONAR_AVERAGE), onA.ids());
            assertEquals(Set.of(SONAR_AVERAGE), onB.ids());

            onA.stopAll(); // stopping one bus's processors leaves the other's running
            a.publish(new StreamMessage(RANGES, 1L, ring(0)));
            b.publish(new StreamMessage(RANGES, 1L, ring(10)));
            assertEquals(List.of(), fromA);
            assertEquals(List.of(17.5), fromB);
            onB.stopAll();
        }
    }

    @Test
    void theWorkbenchBusRunsTheContributedProcessors() throws Exception {
        StreamBus bus = WorkbenchBus.get();
        assertTrue(WorkbenchBus.processorIds().contains(SONAR_AVERAGE), WorkbenchBus.processorIds().toString());
        CountDownLatch derived = new CountDownLatch(1);
        AtomicReference<StreamMessage> got = new AtomicReference<>();
        Subscription s = bus.subscribe(StreamPattern.parse("src=127.0.0.1:6665 type=128 dev=5"), DeliveryPolicy.latestValue(), m -> {
            got.set(m);
            derived.countDown();
        });
        try {
            bus.publish(new StreamMessage(RANGES, 5L, ring(2)));
            assertTrue(derived.await(10, TimeUnit.SECONDS), "a derived stream on the workbench bus");
            assertEquals(9.5, got.get().payload());
            assertEquals(RANGES.withMessageType(128), got.get().key());
        } finally {
            s.close();
        }
    }
}
