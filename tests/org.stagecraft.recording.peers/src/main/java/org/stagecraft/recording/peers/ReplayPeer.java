package org.stagecraft.recording.peers;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * One side of a recorded connection played back over a real socket: it sends its side's recorded
 * chunks in order (as fast as the socket takes them), half-closes, and collects everything the
 * other side sends until that side closes. Run as the server it stands in for Player; run as the
 * client it stands in for the robot program. Sending and receiving run concurrently so neither
 * side can block the other however large the streams are.
 */
public final class ReplayPeer {
    private ReplayPeer() {
    }

    /** What one side of a replayed connection saw. */
    public record Result(byte[] received, byte[] expected) {
        /** Whether the bytes from the other side are exactly what was recorded. */
        public boolean matches() {
            return Arrays.equals(received, expected);
        }

        /** Where received and expected first differ, or -1 when they are equal. */
        public long firstDifference() {
            return Arrays.mismatch(received, expected);
        }
    }

    /** Plays the server side of {@code recorded} on an accepted socket (closes it when done). */
    public static Result serve(Socket accepted, RecordedConnection recorded) throws IOException {
        return exchange(accepted, recorded.serverChunks(), recorded.clientBytes());
    }

    /** Plays the client side of {@code recorded} on a connected socket (closes it when done). */
    public static Result client(Socket connected, RecordedConnection recorded) throws IOException {
        return exchange(connected, recorded.clientChunks(), recorded.serverBytes());
    }

    private static Result exchange(Socket socket, List<byte[]> send, byte[] expected) throws IOException {
        try (socket; ExecutorService sender = Executors.newVirtualThreadPerTaskExecutor()) {
            socket.setTcpNoDelay(true);
            OutputStream out = socket.getOutputStream();
            Future<?> sending = sender.submit(() -> {
                for (byte[] chunk : send) {
                    out.write(chunk);
                }
                socket.shutdownOutput();
                return null;
            });
            InputStream in = socket.getInputStream();
            byte[] received = in.readAllBytes();
            try {
                sending.get();
            } catch (java.util.concurrent.ExecutionException e) {
                throw e.getCause() instanceof IOException io ? io : new IOException(e.getCause());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while sending", e);
            }
            return new Result(received, expected);
        }
    }
}
