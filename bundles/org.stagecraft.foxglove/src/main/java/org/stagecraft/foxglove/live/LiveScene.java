package org.stagecraft.foxglove.live;

import java.util.function.Consumer;
import java.util.function.Function;

import org.stagecraft.foxglove.FoxgloveScene;
import org.stagecraft.foxglove.FoxgloveSink;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.streams.StreamMessage;

/**
 * What the live view serves, the same channels as an MCAP export: each robot as Foxglove's well-known
 * messages ({@link FoxgloveScene}) and Player's own messages decoded ({@link PlayerChannels}).
 */
public final class LiveScene {
    private LiveScene() {
    }

    /** The converter for {@link BusRelay#start}. */
    public static Function<FoxgloveSink, Consumer<StreamMessage>> converter() {
        return sink -> {
            FoxgloveScene scene = new FoxgloveScene(sink);
            PlayerChannels player = new PlayerChannels(sink, CodecRegistry.standard());
            return m -> {
                scene.accept(m);
                player.accept(m);
            };
        };
    }
}
