package org.stagecraft.tools.world;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.time.Duration;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.Geometry;
import org.stagecraft.player.msg.PlayerDevice;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;

/**
 * A Player client that opens one device and sends it requests, one at a time, each answered by its ACK (what else
 * arrives on the way is skipped). The session's line to its world driver, and a test's line to Stage's simulation
 * device.
 */
public final class DeviceRequests implements AutoCloseable {
    private static final int BANNER = 32;
    private static final int REQ_DEV = 3;

    /** Player answered a request with a NACK. */
    public static final class Refused extends IOException {
        private static final long serialVersionUID = 1L;

        Refused(String message) {
            super(message);
        }
    }

    /** An ACK's payload and the timestamp of its header (Stage's simulated time, under Stage). */
    public record Answer(byte[] payload, double timestamp) {
    }

    private final Socket socket;
    private final DataInputStream in;
    private final OutputStream out;
    private final int port;
    private final int interf;
    private final int index;

    private DeviceRequests(Socket socket, int port, int interf, int index) throws IOException {
        this.socket = socket;
        this.in = new DataInputStream(socket.getInputStream());
        this.out = socket.getOutputStream();
        this.port = port;
        this.interf = interf;
        this.index = index;
    }

    /**
     * Connects to Player on {@code port}, reads its banner and opens {@code interf:index} there.
     *
     * @param timeout for connecting and for each answer
     * @throws Refused when Player refuses to open the device
     */
    public static DeviceRequests open(String host, int port, int interf, int index, Duration timeout) throws IOException {
        Socket s = new Socket();
        try {
            s.setTcpNoDelay(true);
            s.connect(new InetSocketAddress(host, port), (int) timeout.toMillis());
            s.setSoTimeout((int) timeout.toMillis());
            DeviceRequests d = new DeviceRequests(s, port, interf, index);
            d.in.readFully(new byte[BANNER]);
            d.send(PlayerDevice.CODE, 0, REQ_DEV, new PlayerDevice.DeviceReq(new Geometry.DevAddr(0, port, interf, index),
                    PlayerDevice.ACCESS_OPEN, 0, ByteArray.EMPTY));
            return d;
        } catch (IOException e) {
            s.close();
            throw e;
        }
    }

    /** Sends one request to the device and returns its ACK. */
    public synchronized Answer request(int subtype, MessageBody body) throws IOException {
        return send(interf, index, subtype, body);
    }

    private Answer send(int toInterf, int toIndex, int subtype, MessageBody body) throws IOException {
        out.write(PlayerEncoder.encode(new MessageHeader(0, port, toInterf, toIndex, MessageType.REQ.code(), subtype, 0.0, 0, 0), body));
        out.flush();
        while (true) {
            byte[] head = new byte[MessageHeader.SIZE];
            in.readFully(head);
            MessageHeader a = MessageHeader.read(head, 0);
            if (a.size() < 0 || a.size() > MessageHeader.MAX_PAYLOAD) {
                throw new IOException("port " + port + " sent a message of " + a.sizeUnsigned() + " bytes");
            }
            byte[] payload = new byte[a.size()];
            in.readFully(payload);
            if (a.interf() != toInterf || a.subtype() != subtype) {
                continue;
            }
            if (a.type() == MessageType.RESP_NACK.code()) {
                throw new Refused("Player refused request " + subtype + " to interface " + toInterf + " on port " + port);
            }
            if (a.type() == MessageType.RESP_ACK.code()) {
                return new Answer(payload, a.timestamp());
            }
        }
    }

    @Override
    public void close() {
        try {
            socket.close();
        } catch (IOException ignored) {
            // closing a socket we no longer need; nothing to tell
        }
    }
}
