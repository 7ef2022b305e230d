package org.stagecraft.streams;

/**
 * The worked example: averages each sonar ring (DATA RANGES of interface 5, payload {@code double[]})
 * and publishes the mean as a user-defined stream, message type 128, same addresses and device.
 * Listed in META-INF/services for the ServiceLoader test.
 */
public final class SonarRingAverage implements StreamProcessor {
    static final int AVERAGE = StreamTypes.USER_MIN;

    @Override
    public void start(ProcessorContext ctx) {
        ctx.subscribe(StreamPattern.parse("type=1 dev=5 subtype=1"), DeliveryPolicy.lossless(64), m -> {
            double[] ranges = (double[]) m.payload();
            double sum = 0;
            for (double r : ranges) {
                sum += r;
            }
            ctx.publish(new StreamMessage(m.key().withMessageType(AVERAGE), m.timeNanos(), sum / ranges.length));
        });
    }
}
