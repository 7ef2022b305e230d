package org.stagecraft.tools.session;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.EmptyBody;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.xdr.XdrWriter;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;
import org.stagecraft.tools.process.Recorder;
import org.stagecraft.tools.process.RestartPolicy;

/** A session's spy decodes with the codecs it is given (in the workbench: contributed decoders included). */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RobotSessionCodecsTest {
    private static final Duration WAIT = Duration.ofSeconds(30);

    @TempDir
    Path tmp;

    /** What the given registry's decoder makes of position2d data: the standard body, marked. */
    record Marked(MessageBody standard) implements MessageBody {
        @Override
        public void encode(XdrWriter out) {
            standard.encode(out);
        }

        @Override
        public void describe(FieldVisitor visitor) {
            standard.describe(visitor);
        }
    }

    @Test
    void theSpyDecodesWithTheGivenCodecs() throws Exception {
        CodecRegistry codecs = CodecRegistry.standard();
        CodecRegistry.Layout position = codecs.lookup(4, MessageType.DATA.code(), 1);
        codecs.register(4, MessageType.DATA, 1, position.subtypeName(), in -> new Marked(position.decoder().decode(in)));

        int port = Ports.free("127.0.0.1", 1).get(0);
        SessionConfig config = SessionConfig.of(Worlds.file("pioneer-laser-sonar.cfg")).withDefaultPort(port)
                .withPlayer(List.of("python3", Worlds.standIn().toString()),
                        Map.of("STANDIN_TRACE", Worlds.traces().resolve("pioneer-laser-sonar.gt.trace.jsonl").toString()))
                .withPlayerRestart(RestartPolicy.NEVER, WAIT).withScratchRoot(tmp.resolve("scratch"));
        try (RobotSession session = RobotSession.start(config, codecs, new Recorder())) {
            CountDownLatch pose = new CountDownLatch(1);
            AtomicReference<Object> body = new AtomicReference<>();
            Subscription s = session.bus().subscribe(StreamPattern.parse("type=1 dev=4 subtype=1"),
                    DeliveryPolicy.latestValue(), m -> {
                        body.compareAndSet(null, ((SpyMessage) m.payload()).message().body());
                        pose.countDown();
                    });
            try (Socket client = new Socket(InetAddress.getLoopbackAddress(), port)) {
                new DataInputStream(client.getInputStream()).readFully(new byte[32]); // the banner
                OutputStream out = client.getOutputStream();
                out.write(PlayerEncoder.encode(new MessageHeader(0, port, 1, 0, MessageType.REQ.code(), 1, 0.0, 0, 0),
                        EmptyBody.INSTANCE)); // once the client speaks, the stand-in serves the recorded data
                out.flush();
                assertTrue(pose.await(WAIT.toSeconds(), TimeUnit.SECONDS), "position2d data on the session's bus");
            }
            s.close();
            assertTrue(body.get() instanceof Marked, "decoded by the given registry: " + body.get());
        }
    }
}
