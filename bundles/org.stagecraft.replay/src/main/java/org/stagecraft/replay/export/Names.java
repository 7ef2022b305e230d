package org.stagecraft.replay.export;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.replay.log.HeaderNames;

/**
 * The export's old entry to {@link HeaderNames}, kept only while {@code McapExport} (being reworked on
 * another branch) still calls it; it names nothing itself. Remove it once McapExport uses HeaderNames.
 */
final class Names {
    private Names() {
    }

    static String iface(CodecRegistry registry, int interf) {
        return new HeaderNames(registry).iface(interf);
    }

    static String type(int type) {
        return HeaderNames.type(type);
    }

    static String subtype(CodecRegistry registry, MessageHeader h) {
        return new HeaderNames(registry).subtype(h);
    }
}
