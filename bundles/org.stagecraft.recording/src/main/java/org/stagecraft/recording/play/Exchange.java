package org.stagecraft.recording.play;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * One side of a recorded connection played over a real socket at the recorded pace: each chunk is
 * written when it was recorded, the side half-closes when the recorded connection ended, and
 * meanwhile everything the other side sends is read (a peer that stops reading would stall the
 * other's writes) and compared with the recording. Both sides are read from their sources as they
 * are played (the caller opens and closes them), so only the chunk in hand is in memory.
 */
final class Exchange {
    private Exchange() {
    }

    static ExchangeResult play(Socket socket, ChunkSource send, ChunkSource expected, double length, double speed)
            throws IOException, InterruptedException {
        try (socket; ExecutorService writer = Executors.newVirtualThreadPerTaskExecutor()) {
            socket.setTcpNoDelay(true);
            Pacer pacer = new Pacer(speed);
            OutputStream out = socket.getOutputStream();
            Future<Long> sending = writer.submit(() -> {
                long sent = 0;
                for (TimedChunk c = send.next(); c != null; c = send.next()) {
                    pacer.awaitOffset(c.offset());
                    out.write(c.data());
                    sent += c.data().length;
                }
                pacer.awaitOffset(length);
                socket.shutdownOutput();
                return sent;
            });
            ByteMatcher matcher = new ByteMatcher(expected);
            InputStream in = socket.getInputStream();
            byte[] buffer = new byte[65536];
            try {
                for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                    matcher.accept(buffer, n);
                }
            } catch (IOException e) {
                sending.cancel(true);
                throw failed(e, matcher);
            }
            long sent;
            try {
                sent = sending.get();
            } catch (ExecutionException e) {
                throw failed(e.getCause() instanceof IOException io ? io : new IOException(e.getCause()), matcher);
            }
            return new ExchangeResult(sent, matcher.received(), matcher.matchesWhole(), matcher.firstDifference());
        }
    }

    /**
     * The connection broke: say also what the other side had sent by then, since a peer that
     * diverged from the recording (another program, another version) is the usual reason it gave up.
     */
    private static IOException failed(IOException e, ByteMatcher matcher) {
        String seen = "after receiving " + matcher.received() + " bytes"
                + (matcher.firstDifference() >= 0 ? ", which differ from the recording from byte " + matcher.firstDifference()
                        : ", all as recorded");
        return new IOException(e.getMessage() + " (" + seen + ")", e);
    }
}
