package org.stagecraft.spy.proxy;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.concurrent.Executors;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;
import org.stagecraft.spy.Cleanup;

/**
 * One recorded connection played through a spy in the pipeline tests: its two byte streams, a
 * stand-in Player that sends Player's side and keeps what it got, and a robot program that sends
 * the program's side and returns what it got. Both send as fast as the sockets take it.
 */
public final class RecordedSession {
    /** Peers block in socket reads: each gets a virtual thread (the common pool may have one worker). */
    static final Executor PEERS = Executors.newVirtualThreadPerTaskExecutor();

    private RecordedSession() {
    }

    /** The two byte streams of connection 1 of a recording in the corpus: [0] program to Player, [1] back. */
    public static byte[][] streams(String trace) throws IOException {
        ByteArrayOutputStream c2s = new ByteArrayOutputStream();
        ByteArrayOutputStream s2c = new ByteArrayOutputStream();
        try (TraceReader r = new TraceReader(TraceCorpus.file(trace))) {
            for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                if (rec instanceof TraceRecord.Chunk c && c.stream().conn() == 1) {
                    (c.stream().dir() == Direction.CLIENT_TO_SERVER ? c2s : s2c).writeBytes(c.data());
                }
            }
        }
        return new byte[][] {c2s.toByteArray(), s2c.toByteArray()};
    }

    /**
     * A stand-in Player for one session: sends {@code s2c} and completes {@code received} with what the
     * program sent. Its socket is added to {@code cleanup}.
     */
    static ServerSocket player(byte[] s2c, CompletableFuture<byte[]> received, Cleanup cleanup)
            throws IOException {
        ServerSocket up = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        cleanup.add(up);
        Thread.ofVirtual().start(() -> {
            try (Socket s = up.accept()) {
                CompletableFuture<Void> w = CompletableFuture.runAsync(() -> {
                    try {
                        s.getOutputStream().write(s2c);
                        s.shutdownOutput();
                    } catch (IOException e) {
                        throw new IllegalStateException(e);
                    }
                }, PEERS);
                received.complete(s.getInputStream().readAllBytes());
                w.join();
            } catch (IOException e) {
                received.completeExceptionally(e);
            }
        });
        return up;
    }

    /** A robot program at {@code at} sending {@code c2s}; returns what it received until Player's side ended. */
    static byte[] program(InetSocketAddress at, byte[] c2s) throws IOException {
        try (Socket s = new Socket()) {
            s.connect(at);
            CompletableFuture<Void> w = CompletableFuture.runAsync(() -> {
                try {
                    s.getOutputStream().write(c2s);
                    s.shutdownOutput();
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            }, PEERS);
            byte[] got = s.getInputStream().readAllBytes();
            w.join();
            return got;
        }
    }
}
