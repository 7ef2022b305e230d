package org.stagecraft.player.xdr;

/**
 * A payload does not fit the XDR layout being read. Carries the byte offset inside the payload so
 * diagnostics can point at it. Decoders turn it into a diagnostic; it never escapes the codec API.
 */
public final class XdrException extends RuntimeException {
    private static final long serialVersionUID = 1L;
    private final int offset;

    public XdrException(int offset, String reason) {
        super(reason + " at payload offset " + offset, null, false, false);
        this.offset = offset;
    }

    public int offset() {
        return offset;
    }
}
