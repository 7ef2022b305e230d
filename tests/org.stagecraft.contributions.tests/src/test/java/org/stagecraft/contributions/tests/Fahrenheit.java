package org.stagecraft.contributions.tests;

import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.ProcessorContext;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.StreamProcessor;
import org.stagecraft.streams.StreamTypes;

/**
 * The derived stream of docs/stream-bus.md's thermometer, contributed through this bundle's plugin.xml: every
 * thermometer reading in degrees Fahrenheit (a {@code Double}) as user type 128 on the reading's addresses and
 * device.
 */
public final class Fahrenheit implements StreamProcessor {
    public static final int TYPE = StreamTypes.USER_MIN; // 128

    @Override
    public void start(ProcessorContext ctx) {
        ctx.subscribe(StreamPattern.parse("type=1 dev=300 subtype=1"), DeliveryPolicy.lossless(1024), m -> {
            if (m.payload() instanceof SpyMessage s && s.message().body() instanceof ThermometerCodec.Temperature t) {
                ctx.publish(new StreamMessage(m.key().withMessageType(TYPE), m.timeNanos(), fahrenheit(t.celsius())));
            }
        });
    }

    public static double fahrenheit(double celsius) {
        return celsius * 9 / 5 + 32;
    }
}
