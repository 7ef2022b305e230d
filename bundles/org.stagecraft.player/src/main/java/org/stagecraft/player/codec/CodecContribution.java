package org.stagecraft.player.codec;

/**
 * Adds interfaces and payload decoders to a {@link CodecRegistry}. Found through
 * {@link java.util.ServiceLoader} in plain Java and through the {@code org.stagecraft.core.decoders}
 * extension point in Eclipse.
 */
public interface CodecContribution {
    void contributeTo(CodecRegistry registry);
}
