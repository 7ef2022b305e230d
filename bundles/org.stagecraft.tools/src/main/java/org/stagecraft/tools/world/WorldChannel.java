package org.stagecraft.tools.world;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;

import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.Simulation;
import org.stagecraft.player.xdr.XdrReader;

/**
 * The session's line to its world driver: a Player client of the driver's simulation device, on the
 * driver's own port of the session's Player (loopback; never through the spy: it is not the program's
 * traffic, and what it does is logged as the session's own). One request at a time.
 */
public final class WorldChannel implements AutoCloseable {
    private static final int GET_PROPERTY = 5;
    private static final int SET_PROPERTY = 6;
    private static final String FROZEN = "frozen", WINDOW = "window";

    private final DeviceRequests device;
    private final int port;

    private WorldChannel(DeviceRequests device, int port) {
        this.device = device;
        this.port = port;
    }

    /**
     * Connects to the world driver on {@code port} and opens its device.
     *
     * @param timeout for connecting and for each answer
     */
    public static WorldChannel open(String host, int port, Duration timeout) throws WorldException {
        try {
            return new WorldChannel(DeviceRequests.open(host, port, Simulation.CODE, 0, timeout), port);
        } catch (DeviceRequests.Refused e) {
            throw new WorldException("Player refused to open the world driver's device on port " + port, e);
        } catch (IOException e) {
            throw new WorldException("no world driver answers on port " + port + ": " + e.getMessage(), e);
        }
    }

    /** Freezes ({@code true}) or thaws the world; returns its state after. */
    public WorldState set(boolean frozen) throws WorldException {
        return property(SET_PROPERTY, FROZEN, frozen ? "1" : "0");
    }

    public WorldState get() throws WorldException {
        return property(GET_PROPERTY, FROZEN, "");
    }

    /** Brings Stage's window to the front (nothing without a window: see {@link WorldState#gui()}). */
    public WorldState raiseWindow() throws WorldException {
        return property(SET_PROPERTY, WINDOW, "raise");
    }

    private WorldState property(int subtype, String property, String value) throws WorldException {
        ByteArray v = value.isEmpty() ? ByteArray.EMPTY : ByteArray.ofText(value);
        ByteArray name = ByteArray.ofText("stagecraft");
        ByteArray prop = ByteArray.ofText(property);
        byte[] reply;
        try {
            reply = device.request(subtype, new Simulation.PropertyReq(name.size(), name, prop.size(), prop, 0, v.size(), v)).payload();
        } catch (DeviceRequests.Refused e) {
            throw new WorldException("the world driver refused: this Player runs no Stage world (is there a \"stage\" driver in the .cfg?)", e);
        } catch (IOException e) {
            throw new WorldException("the world driver on port " + port + " did not answer: " + e.getMessage(), e);
        }
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

    @Override
    public void close() {
        device.close();
    }
}
