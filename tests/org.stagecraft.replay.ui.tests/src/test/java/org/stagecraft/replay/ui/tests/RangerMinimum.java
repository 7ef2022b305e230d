package org.stagecraft.replay.ui.tests;

import java.util.OptionalDouble;

import org.stagecraft.replay.fields.FieldPath;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.ProcessorContext;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.StreamProcessor;
import org.stagecraft.streams.StreamTypes;

/** Contributed in plugin.xml: the nearest echo of each ranger reading (DATA RANGE), as user type 128 (a Double). */
public final class RangerMinimum implements StreamProcessor {
    static final int TYPE = StreamTypes.USER_MIN;
    static final FieldPath MIN = FieldPath.parse("min(ranges)");

    @Override
    public void start(ProcessorContext ctx) {
        ctx.subscribe(StreamPattern.parse("type=1 dev=62 subtype=1"), DeliveryPolicy.lossless(1024), m -> {
            if (m.payload() instanceof SpyMessage s) {
                OptionalDouble min = MIN.evaluate(s.message().body());
                if (min.isPresent()) {
                    ctx.publish(new StreamMessage(m.key().withMessageType(TYPE), m.timeNanos(), min.getAsDouble()));
                }
            }
        });
    }

    @Override
    public void stop() {
    }
}
