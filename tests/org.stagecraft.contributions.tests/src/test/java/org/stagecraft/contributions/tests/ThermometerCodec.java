package org.stagecraft.contributions.tests;

import org.stagecraft.player.codec.CodecContribution;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.xdr.XdrWriter;

/**
 * The worked example of docs/extending-decoders.md, contributed through this bundle's plugin.xml: a driver's
 * own interface 300, "thermometer", whose DATA subtype 1 carries one XDR double.
 */
public final class ThermometerCodec implements CodecContribution {
    public static final int THERMOMETER = 300;
    public static final int TEMPERATURE = 1;

    /** The payload; field names as in the driver's .def file. */
    public record Temperature(double celsius) implements MessageBody {
        @Override
        public void encode(XdrWriter out) {
            out.float64(celsius);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float64("celsius", celsius);
        }
    }

    @Override
    public void contributeTo(CodecRegistry registry) {
        registry.registerInterface(THERMOMETER, "thermometer");
        registry.register(THERMOMETER, MessageType.DATA, TEMPERATURE, "TEMPERATURE", in -> new Temperature(in.float64()));
    }
}
