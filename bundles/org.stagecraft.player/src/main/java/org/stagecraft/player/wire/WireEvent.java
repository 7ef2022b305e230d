package org.stagecraft.player.wire;

import java.nio.charset.StandardCharsets;

/**
 * What the framer makes of a byte stream. Every input byte belongs to exactly one event, in order,
 * so concatenating {@link #bytes()} of all events gives back the stream unchanged.
 */
public sealed interface WireEvent {

    /** Byte offset of the event's first byte in its stream (connection + direction). */
    long offset();

    /** The exact wire bytes this event covers (a fresh copy). */
    byte[] bytes();

    /** The 32-byte ident a Player server sends first. */
    record Banner(long offset, byte[] raw) implements WireEvent {
        public Banner {
            raw = raw.clone();
        }

        /** The ident text without its NUL padding, e.g. "Player v.3.1.1-dev". */
        public String ident() {
            int end = 0;
            while (end < raw.length && raw[end] != 0) {
                end++;
            }
            return new String(raw, 0, end, StandardCharsets.ISO_8859_1);
        }

        @Override
        public byte[] bytes() {
            return raw.clone();
        }
    }

    /** One complete Player message: header and its undecoded XDR payload. */
    record Frame(long offset, MessageHeader header, byte[] payload) implements WireEvent {
        /** Frames are built by the framer with a private copy of the payload. */
        public Frame {
            if (payload.length != header.size()) {
                throw new IllegalArgumentException("payload length " + payload.length + " != header size " + header.size());
            }
        }

        /** A fresh copy of the payload. */
        @Override
        public byte[] payload() {
            return payload.clone();
        }

        /** The payload array itself, for decoders that only read it. Callers must not modify it. */
        public byte[] payloadUnsafe() {
            return payload;
        }

        public int wireSize() {
            return MessageHeader.SIZE + payload.length;
        }

        @Override
        public byte[] bytes() {
            org.stagecraft.player.xdr.XdrWriter w = new org.stagecraft.player.xdr.XdrWriter(wireSize());
            header.write(w);
            w.raw(payload, 0, payload.length);
            return w.toByteArray();
        }
    }

    /**
     * Bytes that are not part of any message: skipped while looking for the next plausible header
     * after corruption, or left over when the stream ended inside a message. Nothing is dropped;
     * the bytes are here with the reason.
     */
    record Unframed(long offset, byte[] raw, String reason) implements WireEvent {
        public Unframed {
            raw = raw.clone();
        }

        @Override
        public byte[] bytes() {
            return raw.clone();
        }

        public int length() {
            return raw.length;
        }
    }
}
