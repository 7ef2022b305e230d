package org.stagecraft.replay.log;

import java.util.Objects;
import java.util.Optional;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.SpyDiagnostic;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.spy.proxy.SpyStreams;
import org.stagecraft.streams.StreamMessage;

/**
 * One thing a log recorded: a Player message with its wire bytes and its decoding, or a connection
 * event, banner, unframed bytes or diagnostic.
 *
 * @param timeNanos    the recorder's receive time
 * @param connection   the connection it belongs to
 * @param dir          its direction; null for {@link Kind#OPENED}/{@link Kind#CLOSED} and connection-wide
 *                     diagnostics
 * @param streamOffset byte offset in its connection's direction (-1 when the format does not say)
 * @param kind         what it is
 * @param bytes        the exact wire bytes (header and payload for a frame); empty for events
 * @param decoded      the decoded message for {@link Kind#FRAME}, else null
 * @param text         the reason or diagnostic text; empty when there is none
 */
public record LogMessage(long timeNanos, ConnectionInfo connection, @Nullable Direction dir, long streamOffset, Kind kind,
        byte[] bytes, @Nullable DecodedMessage decoded, String text) {

    /** What a log message is. */
    public enum Kind {
        OPENED, CLOSED, BANNER, FRAME, UNFRAMED, DIAGNOSTIC,
        /**
         * Something Stagecraft did to the streams, from the log's hold channel (see {@link HoldRows}): a zero
         * command it injected, a program message it held back, a robot data breakpoint's hit, a hold or a
         * frozen world starting or ending. Shown among the messages; never replayed or exported (a cursor
         * does not return them).
         */
        HOLD
    }

    public LogMessage {
        bytes = bytes == null ? new byte[0] : bytes;
        text = text == null ? "" : text;
    }

    /** Whether this is a decode diagnostic or bytes that were not a message. */
    public boolean isProblem() {
        return kind == Kind.UNFRAMED || kind == Kind.DIAGNOSTIC || (decoded != null && decoded.hasProblem());
    }

    /**
     * What the live spy published on the stream bus for this entry, under the same key: a
     * {@link SpyMessage} for a frame, a {@link SpyDiagnostic} for a diagnostic or unframed bytes;
     * nothing for connection events and banners.
     */
    public Optional<StreamMessage> toStreamMessage() {
        return switch (kind) {
            case FRAME -> {
                Direction d = Objects.requireNonNull(dir); // a frame has both
                DecodedMessage message = Objects.requireNonNull(decoded);
                yield Optional.of(new StreamMessage(SpyStreams.messageKey(connection, d, message.header()),
                        timeNanos, new SpyMessage(connection, d, streamOffset, message)));
            }
            case UNFRAMED, DIAGNOSTIC -> {
                Direction d = dir;
                yield d == null ? Optional.empty()
                        : Optional.of(new StreamMessage(SpyStreams.diagnosticKey(connection, d), timeNanos,
                                new SpyDiagnostic(connection, d, streamOffset, text)));
            }
            case OPENED, CLOSED, BANNER, HOLD -> Optional.empty();
        };
    }

    /** Whether {@code other} is the same recorded entry (same place in the same stream). */
    public boolean samePlace(LogMessage other) {
        return other != null && timeNanos == other.timeNanos && connection.id() == other.connection.id()
                && dir == other.dir && streamOffset == other.streamOffset && kind == other.kind;
    }
}
