package org.stagecraft.spy.proxy;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.player.xdr.XdrWriter;
import org.stagecraft.streams.StreamMessage;

/**
 * Loads the classes observation needs before the first connection. A class is loaded the first
 * time it is used, which means opening the bundle's jar: a spy that has run out of file
 * descriptors (hundreds of hostile connections) would then fail inside the observer with a
 * NoClassDefFoundError, on a path that must not fail. So the paths are run once at construction,
 * on a made-up stream: a banner, a message of every Player type, garbage, a message cut short.
 */
final class ObservationClasses {
    private ObservationClasses() {
    }

    static void load(PlayerDecoder decoder) {
        XdrWriter w = new XdrWriter(512);
        byte[] ident = new byte[PlayerFramer.IDENT_LENGTH];
        byte[] text = "Player v.3.1.0".getBytes(StandardCharsets.US_ASCII);
        System.arraycopy(text, 0, ident, 0, text.length);
        w.raw(ident, 0, ident.length);
        for (int type = 1; type <= 6; type++) {
            new MessageHeader(0, 0, 4, 0, type, 1, 0.0, 0, 8).write(w);
            w.int32(1).int32(2);
        }
        w.raw(new byte[] {(byte) 0xEE, (byte) 0xEE, (byte) 0xEE}, 0, 3); // garbage
        new MessageHeader(0, 0, 4, 0, 1, 1, 0.0, 0, 100).write(w); // cut short
        byte[] stream = w.toByteArray();
        ConnectionInfo c = new ConnectionInfo(0, 0, "127.0.0.1:1", "127.0.0.1:2", "127.0.0.1:3");
        for (Direction dir : Direction.values()) {
            List<WireEvent> events = new ArrayList<>();
            PlayerFramer f = new PlayerFramer(dir, events::add);
            f.accept(stream, 0, stream.length / 2);
            f.accept(stream, stream.length / 2, stream.length - stream.length / 2);
            f.abandon();
            f.gap(1, "preloading");
            f.end();
            for (WireEvent e : events) {
                if (e instanceof WireEvent.Frame fr) {
                    DecodedMessage m = decoder.decode(fr);
                    new StreamMessage(SpyStreams.messageKey(c, dir, fr.header()), 0, new SpyMessage(c, dir, fr.offset(), m));
                }
            }
            new StreamMessage(SpyStreams.diagnosticKey(c, dir), 0, new SpyDiagnostic(c, dir, 0, ""));
        }
        new SpyNotice(c, SpyNotice.Kind.OBSERVATION_FAILED, "");
        ObservationPipeline.describe(new IllegalStateException());
    }
}
