package org.stagecraft.player.it;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.Geometry;
import org.stagecraft.player.msg.PlayerDevice;
import org.stagecraft.player.msg.Simulation;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.xdr.XdrReader;

/**
 * A test's own Player client of Stage's simulation device (simulation:0 on Player's port): where a model is, and
 * the simulated time of Stage's answer (the reply's header timestamp). Connected to Player directly, not through
 * the spy: it observes the world, it is not a robot program.
 */
final class StageSimulation implements AutoCloseable {
    /** A model's pose and the simulated time Stage answered at. */
    record Pose(double x, double y, double a, double simTime) {
        double distanceTo(Pose o) {
            return Math.hypot(x - o.x, y - o.y);
        }
    }

    private final Socket socket;
    private final DataInputStream in;
    private final OutputStream out;
    private final int port;
    private double lastTimestamp;

    StageSimulation(int port) throws IOException {
        this.port = port;
        socket = new Socket("127.0.0.1", port);
        socket.setSoTimeout(10_000);
        in = new DataInputStream(socket.getInputStream());
        out = socket.getOutputStream();
        in.readFully(new byte[32]);
        request(PlayerDevice.CODE, 3, new PlayerDevice.DeviceReq(new Geometry.DevAddr(0, port, Simulation.CODE, 0),
                PlayerDevice.ACCESS_OPEN, 0, ByteArray.EMPTY));
    }

    Pose pose(String model) throws IOException {
        ByteArray name = ByteArray.ofText(model);
        byte[] reply = request(Simulation.CODE, 1, new Simulation.PoseReq2d(name.size(), name, new Geometry.Pose2d(0, 0, 0)));
        XdrReader r = new XdrReader(reply);
        r.uint32();
        r.bytes();
        Geometry.Pose2d p = Geometry.Pose2d.read(r);
        return new Pose(p.px(), p.py(), p.pa(), lastTimestamp);
    }

    private byte[] request(int interf, int subtype, MessageBody body) throws IOException {
        out.write(PlayerEncoder.encode(new MessageHeader(0, port, interf, 0, MessageType.REQ.code(), subtype, 0, 0, 0), body));
        out.flush();
        while (true) {
            byte[] head = new byte[MessageHeader.SIZE];
            in.readFully(head);
            MessageHeader h = MessageHeader.read(head, 0);
            byte[] payload = new byte[h.size()];
            in.readFully(payload);
            if (h.interf() == interf && h.subtype() == subtype) {
                if (h.type() != MessageType.RESP_ACK.code()) {
                    throw new IOException("Player refused " + interf + ":" + subtype + " (type " + h.type() + ")");
                }
                lastTimestamp = h.timestamp();
                return payload;
            }
        }
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
