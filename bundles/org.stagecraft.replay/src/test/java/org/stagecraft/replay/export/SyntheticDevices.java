package org.stagecraft.replay.export;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import org.stagecraft.foxglove.FoxgloveChannel;
import org.stagecraft.foxglove.FoxgloveScene;
import org.stagecraft.foxglove.FoxgloveSink;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Blobfinder;
import org.stagecraft.player.msg.Bumper;
import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.Fiducial;
import org.stagecraft.player.msg.FloatArray;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.msg.MapInterface;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Sonar;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.spy.proxy.SpyStreams;
import org.stagecraft.streams.StreamMessage;

/**
 * Devices the corpus recordings do not have (a map, bumpers, fiducials, blobs, a sonar interface),
 * as Player's decoded messages, through the Foxglove scene: what the export would write for them.
 * Made here because no recording of them exists; the values are plausible Stage values.
 */
final class SyntheticDevices {
    /** One message the scene sent: its channel and JSON. */
    record Sent(FoxgloveChannel channel, String json) {
    }

    private SyntheticDevices() {
    }

    static List<Sent> scene() {
        List<Sent> sent = new ArrayList<>();
        FoxgloveScene scene = new FoxgloveScene(new FoxgloveSink() {
            @Override
            public void advertise(FoxgloveChannel channel) {
            }

            @Override
            public void publish(FoxgloveChannel channel, long log, long publish, byte[] json) {
                sent.add(new Sent(channel, new String(json, StandardCharsets.UTF_8)));
            }
        });
        ConnectionInfo c = new ConnectionInfo(1, 6665, "127.0.0.1:40001", "127.0.0.1:6665", "127.0.0.1:7665");
        long t = 1_795_315_969_000_000_000L;
        Pose3d front = new Pose3d(0.2, 0, 0.1, 0, 0, 0);
        scene.accept(msg(c, t, MapInterface.CODE, 4, 1, new MapInterface.Info(0.05f, 4, 3, new Pose2d(-0.1, -0.075, 0))));
        byte[] cells = { -1, -1, 0, 1, -1, 1, 1, 0, 0, 0, -1, -1 };
        scene.accept(msg(c, t + 1, MapInterface.CODE, 4, 2,
                new MapInterface.Tile(0, 0, 4, 3, cells.length, 1, ByteArray.of(cells))));
        scene.accept(msg(c, t + 2, Bumper.CODE, 4, 1, new Bumper.Geom(2, List.of(new Bumper.Define(front, 0.1f, 0),
                new Bumper.Define(new Pose3d(-0.2, 0, 0.1, 0, 0, Math.PI), 0.1f, 0)))));
        scene.accept(msg(c, t + 3, Bumper.CODE, 1, 1, new Bumper.State(2, ByteArray.of((byte) 1, (byte) 0))));
        scene.accept(msg(c, t + 4, Fiducial.CODE, 1, 1, new Fiducial.Scan(1,
                List.of(new Fiducial.Item(7, new Pose3d(2, 0.5, 0, 0, 0, 0.3), new Pose3d(0, 0, 0, 0, 0, 0))))));
        scene.accept(msg(c, t + 5, Blobfinder.CODE, 1, 1, new Blobfinder.Blobs(80, 60, 1,
                List.of(new Blobfinder.Blob(0, 0xff0000, 64, 20, 30, 16, 24, 26, 34, 2.5f)))));
        List<Pose3d> ring = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            ring.add(new Pose3d(0.2 * Math.cos(i * Math.PI / 4), 0.2 * Math.sin(i * Math.PI / 4), 0, 0, 0, i * Math.PI / 4));
        }
        scene.accept(msg(c, t + 6, Sonar.CODE, 4, 1, new Sonar.Geom(8, ring)));
        scene.accept(msg(c, t + 7, Sonar.CODE, 1, 1, new Sonar.Ranges(8, FloatArray.of(1, 2, 3, 4, 5, 0, 1, 2))));
        scene.accept(msg(c, t + 8, Position2d.CODE, 1, 1,
                new Position2d.State(new Pose2d(1, 2, 0.5), new Pose2d(0, 0, 0), 0)));
        return sent;
    }

    private static StreamMessage msg(ConnectionInfo c, long t, int interf, int type, int subtype, MessageBody body) {
        MessageHeader h = new MessageHeader(0, 0, interf, 0, type, subtype, 1.5, 0, 0);
        return new StreamMessage(SpyStreams.messageKey(c, Direction.SERVER_TO_CLIENT, h), t,
                new SpyMessage(c, Direction.SERVER_TO_CLIENT, 0, new DecodedMessage(h, body, null)));
    }
}
