package org.stagecraft.core.tests;

import org.stagecraft.player.codec.CodecContribution;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.xdr.XdrWriter;

/** A user-defined interface 300 whose DATA 1 carries one double, contributed through plugin.xml. */
public final class ThermometerCodec implements CodecContribution {

    public record Temperature(double celsius) implements MessageBody {
        @Override
        public void encode(XdrWriter out) {
            out.float64(celsius);
        }

        @Override
        public void describe(FieldVisitor visitor) {
            visitor.float64("celsius", celsius);
        }
    }

    @Override
    public void contributeTo(CodecRegistry registry) {
        registry.registerInterface(300, "thermometer");
        registry.register(300, MessageType.DATA, 1, "TEMPERATURE", in -> new Temperature(in.float64()));
    }
}
