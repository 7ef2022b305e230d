package org.stagecraft.replay.export;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;

/** Player's names for what a header says, or the numbers when there is no name. */
final class Names {
    private Names() {
    }

    static String iface(CodecRegistry registry, int interf) {
        String n = registry.interfaceName(interf);
        return n != null ? n : Integer.toString(interf);
    }

    static String type(int type) {
        MessageType t = MessageType.of(type);
        return t != null ? t.name() : Integer.toString(type);
    }

    static String subtype(CodecRegistry registry, MessageHeader h) {
        return registry.subtypeName(h.interf(), h.type(), h.subtype());
    }
}
