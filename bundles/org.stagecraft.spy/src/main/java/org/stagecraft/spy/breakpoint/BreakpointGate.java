package org.stagecraft.spy.breakpoint;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.io.OutputStream;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.spy.hold.SpanWriter;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * The Player-to-program direction of one connection when robot data breakpoints are enabled. It follows
 * message boundaries (Player's 32-byte banner, then 40-byte headers and their payloads) however the
 * stream is chunked, and forwards every byte unchanged and in order:
 *
 * <ul>
 * <li>With no breakpoint armed, each chunk goes on at once, whole.</li>
 * <li>Armed, a message's header is kept until it is complete; a message no breakpoint watches then goes
 * on as it comes; a watched one is kept until its last byte and tested.</li>
 * <li>On a hit, the bytes before the message have gone on; the message and everything after it wait
 * (this relay thread stops reading from Player) until the hit is passed on or its bound passes.</li>
 * </ul>
 *
 * If the stream stops looking like Player messages, boundaries are lost for good and every byte goes on
 * untested (the relay cannot resynchronise without guessing).
 */
public final class BreakpointGate {
    private final DataBreakpoints owner;
    private final ConnectionInfo connection;
    private final SpanWriter downstream;

    private long offset;
    private int bannerLeft = PlayerFramer.IDENT_LENGTH;
    private final byte[] header = new byte[MessageHeader.SIZE];
    private int headerFill;
    private long payloadLeft;
    private long messageStart;
    private boolean lost;
    /** The current message's header is kept until complete (breakpoints were armed at its start). */
    private boolean keepHeader;
    /** The current message is kept whole to be tested. */
    private boolean keepMessage;
    private @Nullable MessageHeader kept;
    private final ByteArrayOutputStream keptBytes = new ByteArrayOutputStream();


    BreakpointGate(DataBreakpoints owner, ConnectionInfo connection, OutputStream downstream) {
        this.owner = owner;
        this.connection = connection;
        this.downstream = new SpanWriter(downstream);
    }

    public ConnectionInfo connection() {
        return connection;
    }

    /** Relays one chunk Player sent (on the connection's Player-to-program relay thread). */
    public void relay(byte[] buf, int off, int len) throws IOException {
        int pos = off;
        int end = off + len;
        downstream.begin(buf, off);
        try {
            while (pos < end) {
                if (lost) {
                    downstream.later(pos, end - pos);
                    offset += end - pos;
                    break;
                }
                if (bannerLeft > 0) {
                    int n = Math.min(bannerLeft, end - pos);
                    downstream.later(pos, n);
                    bannerLeft -= n;
                    offset += n;
                    pos += n;
                } else if (payloadLeft == 0) {
                    pos = header(buf, pos, end);
                } else {
                    int n = (int) Math.min(payloadLeft, end - pos);
                    if (keepMessage) {
                        downstream.flush();
                        keptBytes.write(buf, pos, n);
                    } else {
                        downstream.later(pos, n);
                    }
                    payloadLeft -= n;
                    offset += n;
                    pos += n;
                    if (payloadLeft == 0) {
                        messageDone();
                    }
                }
            }
            downstream.flush();
        } finally {
            downstream.end();
        }
    }

    /** Player closed its side: a header still kept goes on (a direct connection would have delivered it). */
    public void end() throws IOException {
        if (keepHeader && headerFill > 0) {
            keepHeader = false;
            downstream.write(header, headerFill);
        }
        if (keepMessage) {
            keepMessage = false;
            downstream.write(keptBytes.toByteArray());
            keptBytes.reset();
        }
    }

    private int header(byte[] buf, int pos, int end) throws IOException {
        if (headerFill == 0) {
            messageStart = offset;
            keepHeader = owner.armed();
        }
        int n = Math.min(MessageHeader.SIZE - headerFill, end - pos);
        System.arraycopy(buf, pos, header, headerFill, n);
        if (keepHeader) {
            downstream.flush();
        } else {
            downstream.later(pos, n);
        }
        headerFill += n;
        offset += n;
        pos += n;
        if (headerFill < MessageHeader.SIZE) {
            return pos;
        }
        headerFill = 0;
        MessageHeader h = MessageHeader.read(header, 0);
        if (h.problem() != null) {
            lost = true; // not a Player message: from here on every byte goes on untested
            if (keepHeader) {
                keepHeader = false;
                write(header);
            }
            return pos;
        }
        payloadLeft = h.size();
        if (keepHeader) {
            keepHeader = false;
            if (owner.watches(connection, h)) {
                keepMessage = true;
                kept = h;
                keptBytes.reset();
                keptBytes.write(header);
            } else {
                write(header);
            }
        }
        if (payloadLeft == 0) {
            messageDone();
        }
        return pos;
    }

    private void messageDone() throws IOException {
        if (!keepMessage) {
            return;
        }
        keepMessage = false;
        byte[] message = keptBytes.toByteArray();
        keptBytes.reset();
        MessageHeader h = kept;
        kept = null;
        downstream.flush(); // everything before the message has gone on
        BreakpointHit hit = h == null ? null : owner.test(connection, messageStart, h, message);
        if (hit != null) {
            try {
                hit.awaitPassOn(owner.passOnBound().toNanos(), "the program was not suspended within "
                        + owner.passOnBound().toMillis() + " ms (is it being debugged?)");
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                hit.passOn("the relay was interrupted");
                owner.passedOn(hit);
                throw new InterruptedIOException("interrupted while holding a message back for a robot data breakpoint");
            }
            owner.passedOn(hit);
        }
        write(message);
    }

    private void write(byte[] b) throws IOException {
        downstream.write(b);
    }
}
