package org.stagecraft.player.codec;

/**
 * Why a payload stayed raw although a decoder exists for it.
 *
 * @param payloadOffset byte offset inside the payload where decoding stopped, or -1 if unknown
 * @param reason        a sentence naming the layout and what did not fit
 */
public record DecodeProblem(int payloadOffset, String reason) {
}
