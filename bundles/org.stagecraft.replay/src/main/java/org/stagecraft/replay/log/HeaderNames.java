package org.stagecraft.replay.log;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;

/**
 * Player's names for what a message header says, for people: the interface ("laser"), the device
 * ("laser:0"), the message type ("DATA") and the subtype ("GET_GEOM"); the number where Player (or a
 * plug-in's codec) has no name. The one naming the packet inspector, the filters and every export use.
 */
public final class HeaderNames {
    private final CodecRegistry registry;

    public HeaderNames(CodecRegistry registry) {
        this.registry = registry;
    }

    public CodecRegistry registry() {
        return registry;
    }

    /** "laser", or "42" for an interface no codec names. */
    public String iface(int interf) {
        String n = registry.interfaceName(interf);
        return n != null ? n : Integer.toString(interf);
    }

    /** "laser:0": the interface and the device index. */
    public String device(int interf, int index) {
        return iface(interf) + ":" + index;
    }

    /** "DATA", "CMD", "REQ", "RESP_ACK", "SYNCH" or "RESP_NACK"; the number for any other code. */
    public static String type(int code) {
        MessageType t = MessageType.of(code);
        return t != null ? t.name() : Integer.toString(code);
    }

    /** Player's subtype name, e.g. "GET_GEOM", or the number when no layout names it. */
    public String subtype(MessageHeader h) {
        return registry.subtypeName(h.interf(), h.type(), h.subtype());
    }
}
