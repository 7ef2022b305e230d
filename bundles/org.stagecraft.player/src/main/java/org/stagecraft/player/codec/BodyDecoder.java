package org.stagecraft.player.codec;

import org.stagecraft.player.xdr.XdrReader;

/**
 * Decodes one payload layout. Implementations read the whole payload; an
 * {@link org.stagecraft.player.xdr.XdrException} (or any other failure) makes the payload stay raw
 * with a diagnostic, it never reaches the caller.
 */
@FunctionalInterface
public interface BodyDecoder {
    MessageBody decode(XdrReader in);
}
