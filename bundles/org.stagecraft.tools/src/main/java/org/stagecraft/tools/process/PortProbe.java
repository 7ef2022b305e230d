package org.stagecraft.tools.process;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;

/**
 * Checks whether a tool's port is open the way a well-behaved client would: connect, read the
 * greeting the server sends first (Player's 32-byte ident string), then close in order (FIN).
 * <p>
 * Closing before the banner is read, or with a reset, makes Player print "failed to send ident
 * string" and "other error on client 0" into its console at every start; this probe leaves nothing
 * there. The port counts as open only once the whole banner has arrived, so a server that accepts
 * but is not serving yet is not taken as ready.
 */
public final class PortProbe {
    /** Player's {@code PLAYER_IDENT_STRLEN}: "Player v.3.1.1" padded to 32 bytes, sent on accept. */
    public static final int PLAYER_BANNER_BYTES = 32;

    private final int connectTimeoutMillis;
    private final int bannerTimeoutMillis;

    public PortProbe(int connectTimeoutMillis, int bannerTimeoutMillis) {
        this.connectTimeoutMillis = connectTimeoutMillis;
        this.bannerTimeoutMillis = bannerTimeoutMillis;
    }

    /** Whether {@code host:port} accepts a connection and sends {@code bannerBytes} bytes first. */
    public boolean isOpen(String host, int port, int bannerBytes) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(host, port), connectTimeoutMillis);
            if (bannerBytes > 0) {
                s.setSoTimeout(bannerTimeoutMillis);
                InputStream in = s.getInputStream();
                int read = 0;
                byte[] buf = new byte[bannerBytes];
                while (read < bannerBytes) {
                    int n = in.read(buf, read, bannerBytes - read);
                    if (n < 0) {
                        return false; // closed on us: not serving yet
                    }
                    read += n;
                }
                // Unread bytes at close make the kernel answer with a reset instead of a FIN.
                drain(in);
            }
            s.shutdownOutput();
            return true;
        } catch (SocketTimeoutException e) {
            return false;
        } catch (IOException e) {
            return false;
        }
    }

    private static void drain(InputStream in) throws IOException {
        byte[] buf = new byte[4096];
        while (in.available() > 0 && in.read(buf, 0, Math.min(buf.length, in.available())) > 0) {
            // discard: a probe has no use for what a server sends unasked
        }
    }
}
