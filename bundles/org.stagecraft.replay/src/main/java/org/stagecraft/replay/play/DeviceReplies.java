package org.stagecraft.replay.play;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.stagecraft.player.msg.PlayerDevice;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;

/**
 * The replies that describe a device — geometry, configuration: every acknowledged request of a
 * device interface, as opposed to the player interface's housekeeping — found by one pass over the
 * log on a thread of its own. A client asks for them once, when it starts, so a replay that seeks
 * into the middle of a log would leave views drawing sensors at default mounts; the replayer
 * publishes, after a seek, the latest of each that came before the new position.
 *
 * <p>Memory: one entry per reply that differs from the previous reply of its device (geometry is
 * asked again and again with the same answer by some programs), at most {@link #MAX} in all;
 * beyond that the pass stops and later replies are not known.
 */
final class DeviceReplies implements AutoCloseable {
    static final int MAX = 10_000;

    private record Device(int conn, int interf, int index, int subtype) {
    }

    private final Map<Device, TreeMap<Long, LogMessage>> replies = new HashMap<>();
    private final Thread pass;
    private volatile boolean stop;
    private volatile boolean done;
    private int count;

    DeviceReplies(SessionLog log) {
        pass = Thread.ofPlatform().daemon().name("stagecraft-replay-device-replies " + log.path().getFileName())
                .unstarted(() -> read(log));
        pass.start();
    }

    private void read(SessionLog log) {
        // no interrupts here: an interrupt during a file read would close the log's channel
        try (LogCursor c = log.cursor(log.startNanos())) {
            for (LogMessage m = c.next(); m != null && !stop; m = c.next()) {
                if (describesDevice(m) && !add(m)) {
                    break;
                }
            }
        } catch (IOException | RuntimeException e) {
            // what was found so far still serves; the replayer itself reports a log it cannot read
        } finally {
            done = true;
        }
    }

    static boolean describesDevice(LogMessage m) {
        if (m.kind() != LogMessage.Kind.FRAME || m.dir() != Direction.SERVER_TO_CLIENT || m.decoded().hasProblem()) {
            return false;
        }
        MessageHeader h = m.decoded().header();
        return h.type() == MessageType.RESP_ACK.code() && h.interf() != PlayerDevice.CODE;
    }

    /** @return false when full */
    private synchronized boolean add(LogMessage m) {
        MessageHeader h = m.decoded().header();
        TreeMap<Long, LogMessage> times = replies.computeIfAbsent(
                new Device(m.connection().id(), h.interf(), h.index(), h.subtype()), k -> new TreeMap<>());
        Map.Entry<Long, LogMessage> last = times.lastEntry();
        if (last != null && Arrays.equals(last.getValue().bytes(), MessageHeader.SIZE, last.getValue().bytes().length,
                m.bytes(), MessageHeader.SIZE, m.bytes().length)) {
            return true; // the same answer again
        }
        if (count >= MAX) {
            return false;
        }
        times.put(m.timeNanos(), m);
        count++;
        return true;
    }

    /** For each device, the latest reply strictly before log time {@code t} found so far, in time order. */
    synchronized List<LogMessage> before(long t) {
        List<LogMessage> out = new ArrayList<>();
        for (TreeMap<Long, LogMessage> times : replies.values()) {
            Map.Entry<Long, LogMessage> e = times.lowerEntry(t);
            if (e != null) {
                out.add(e.getValue());
            }
        }
        out.sort((a, b) -> Long.compare(a.timeNanos(), b.timeNanos()));
        return out;
    }

    /** Whether the pass has read the whole log (or stopped). */
    boolean done() {
        return done;
    }

    /** Waits for the pass to end, at most {@code millis}; for tests. */
    boolean awaitDone(long millis) throws InterruptedException {
        pass.join(millis);
        return done;
    }

    @Override
    public void close() {
        stop = true;
        try {
            pass.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
