package org.stagecraft.tools.world;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.time.Duration;

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
 * The session's line to its world driver: a Player client of the driver's simulation device, on the
 * driver's own port of the session's Player (loopback; never through the spy: it is not the program's
 * traffic, and what it does is logged as the session's own). One request at a time.
 */
public final class WorldChannel implements AutoCloseable {
    private static final int BANNER = 32;
    private static final int REQ_DEV = 3;
    private static final int GET_PROPERTY = 5;
    private static final int SET_PROPERTY = 6;
    private static final String PROPERTY = "frozen";

    private final Socket socket;
    private final DataInputStream in;
    private final OutputStream out;
    private final int port;

    private WorldChannel(Socket socket, int port) throws IOException {
        this.socket = socket;
        this.in = new DataInputStream(socket.getInputStream());
        this.out = socket.getOutputStream();
        this.port = port;
    }

    /**
     * Connects to the world driver on {@code port} and opens its device.
     *
     * @param timeout for connecting and for each answer
     */
    public static WorldChannel open(String host, int port, Duration timeout) throws WorldException {
        Socket s = new Socket();
        try {
            s.setTcpNoDelay(true);
            s.connect(new InetSocketAddress(host, port), (int) timeout.toMillis());
            s.setSoTimeout((int) timeout.toMillis());
            WorldChannel c = new WorldChannel(s, port);
            c.in.readFully(new byte[BANNER]);
            c.request(PlayerDevice.CODE, REQ_DEV, new PlayerDevice.DeviceReq(new Geometry.DevAddr(0, port, Simulation.CODE, 0),
                    PlayerDevice.ACCESS_OPEN, 0, ByteArray.EMPTY));
            return c;
        } catch (IOException | WorldException e) {
            try {
                s.close();
            } catch (IOException ignored) {
                // the error below says what went wrong
            }
            throw e instanceof WorldException w ? w
                    : new WorldException("no world driver answers on port " + port + ": " + e.getMessage(), e);
        }
    }

    /** Freezes ({@code true}) or thaws the world; returns its state after. */
    public synchronized WorldState set(boolean frozen) throws WorldException {
        return property(SET_PROPERTY, frozen ? "1" : "0");
    }

    public synchronized WorldState get() throws WorldException {
        return property(GET_PROPERTY, "");
    }

    private WorldState property(int subtype, String value) throws WorldException {
        ByteArray v = value.isEmpty() ? ByteArray.EMPTY : ByteArray.ofText(value);
        ByteArray name = ByteArray.ofText("stagecraft");
        ByteArray prop = ByteArray.ofText(PROPERTY);
        byte[] reply = request(Simulation.CODE, subtype,
                new Simulation.PropertyReq(name.size(), name, prop.size(), prop, 0, v.size(), v));
        XdrReader r = new XdrReader(reply);
        // the request as Player sent it back: name, prop, index, then the value the driver wrote
        r.uint32();
        r.bytes();
        r.uint32();
        r.bytes();
        r.uint32();
        r.uint32();
        byte[] text = r.bytes();
        int end = 0;
        while (end < text.length && text[end] != 0) {
            end++;
        }
        return WorldState.parse(new String(text, 0, end, StandardCharsets.US_ASCII));
    }

    /** Sends one request and returns the payload of its ACK (other messages on the way are skipped). */
    private byte[] request(int interf, int subtype, MessageBody body) throws WorldException {
        MessageHeader h = new MessageHeader(0, port, interf, 0, MessageType.REQ.code(), subtype, 0.0, 0, 0);
        try {
            out.write(PlayerEncoder.encode(h, body));
            out.flush();
            while (true) {
                byte[] head = new byte[MessageHeader.SIZE];
                in.readFully(head);
                MessageHeader a = MessageHeader.read(head, 0);
                if (a.size() < 0 || a.size() > MessageHeader.MAX_PAYLOAD) {
                    throw new WorldException("the world driver's port " + port + " sent a message of " + a.sizeUnsigned() + " bytes");
                }
                byte[] payload = new byte[a.size()];
                in.readFully(payload);
                if (a.interf() != interf || a.subtype() != subtype) {
                    continue;
                }
                if (a.type() == MessageType.RESP_NACK.code()) {
                    throw new WorldException(interf == Simulation.CODE
                            ? "the world driver refused: this Player runs no Stage world (is there a \"stage\" driver in the .cfg?)"
                            : "Player refused to open the world driver's device on port " + port);
                }
                if (a.type() == MessageType.RESP_ACK.code()) {
                    return payload;
                }
            }
        } catch (IOException e) {
            throw new WorldException("the world driver on port " + port + " did not answer: " + e.getMessage(), e);
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
