package org.stagecraft.core.tests;

import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.ProcessorContext;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.StreamProcessor;
import org.stagecraft.streams.StreamTypes;

/**
 * Contributed through plugin.xml: averages each sonar ring (DATA RANGES of interface 5, here a
 * {@code double[]} payload) and publishes the mean as user type 128 on the same addresses and device.
 */
public final class SonarAverageProcessor implements StreamProcessor {
    public static final int AVERAGE = StreamTypes.USER_MIN;
    static volatile boolean stopped;

    @Override
    public void start(ProcessorContext ctx) {
        stopped = false;
        ctx.subscribe(StreamPattern.parse("type=1 dev=5 subtype=1"), DeliveryPolicy.lossless(64), m -> {
            if (m.payload() instanceof double[] ranges && ranges.length > 0) {
                double sum = 0;
                for (double r : ranges) {
                    sum += r;
                }
                ctx.publish(new StreamMessage(m.key().withMessageType(AVERAGE), m.timeNanos(), sum / ranges.length));
            }
        });
    }

    @Override
    public void stop() {
        stopped = true;
    }
}
