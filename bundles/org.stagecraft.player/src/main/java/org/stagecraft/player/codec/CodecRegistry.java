package org.stagecraft.player.codec;

import java.util.Map;
import java.util.ServiceLoader;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicReferenceArray;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.xdr.XdrException;

/**
 * Which payload layout belongs to which (interface, message type, subtype), and the names of
 * interfaces and subtypes. Replies (ACK/NACK) share the layout of their request. Universal
 * requests (capabilities, properties) are valid on every interface. Registration may happen at
 * any time (plug-ins arrive late); lookups are lock-free.
 */
public final class CodecRegistry {

    /** A registered layout: Player's subtype name (e.g. "GET_GEOM") and its decoder. */
    public record Layout(String subtypeName, BodyDecoder decoder) {
    }

    private static final int KINDS = 6;
    private static final int SUBTYPES = 256;

    private final AtomicReferenceArray<Layout[]> byInterface = new AtomicReferenceArray<>(65536);
    private final AtomicReferenceArray<Layout> universal = new AtomicReferenceArray<>(KINDS * SUBTYPES);
    private final Map<Integer, String> interfaceNames = new TreeMap<>();

    /** An empty registry. */
    public CodecRegistry() {
    }

    /**
     * A registry with Player's standard interfaces and every {@link CodecContribution} that
     * {@link ServiceLoader} finds next to this bundle (plain-Java registration).
     */
    public static CodecRegistry standard() {
        CodecRegistry r = new CodecRegistry();
        new org.stagecraft.player.msg.StandardInterfaces().contributeTo(r);
        for (CodecContribution c : ServiceLoader.load(CodecContribution.class, CodecRegistry.class.getClassLoader())) {
            r.add(c);
        }
        return r;
    }

    public CodecRegistry add(CodecContribution contribution) {
        contribution.contributeTo(this);
        return this;
    }

    public synchronized void registerInterface(int code, String name) {
        checkCode(code);
        interfaceNames.put(code, name);
    }

    /** @return the interface name (e.g. "laser"), or null if unknown */
    public synchronized @Nullable String interfaceName(int code) {
        return interfaceNames.get(code);
    }

    /** @return the interface code for a name, or -1 */
    public synchronized int interfaceCode(String name) {
        for (Map.Entry<Integer, String> e : interfaceNames.entrySet()) {
            if (e.getValue().equals(name)) {
                return e.getKey();
            }
        }
        return -1;
    }

    public synchronized Map<Integer, String> interfaces() {
        return Map.copyOf(interfaceNames);
    }

    /**
     * Registers a layout. {@code kind} is DATA, CMD, REQ (covers the replies too) or SYNCH.
     * A later registration for the same key replaces the earlier one, so plug-ins can override.
     */
    public synchronized void register(int interf, MessageType kind, int subtype, String subtypeName, BodyDecoder decoder) {
        checkCode(interf);
        Layout @Nullable [] table = byInterface.get(interf);
        Layout[] copy = table == null ? new Layout[KINDS * SUBTYPES] : table.clone();
        copy[slot(kind, subtype)] = new Layout(subtypeName, decoder);
        byInterface.set(interf, copy);
    }

    /** Registers a message Player defines without payload; a payload there is reported, not decoded. */
    public void registerEmpty(int interf, MessageType kind, int subtype, String subtypeName) {
        register(interf, kind, subtype, subtypeName, in -> {
            throw new XdrException(0, subtypeName + " is defined without payload");
        });
    }

    /** Registers a request layout valid on every interface. */
    public void registerUniversal(MessageType kind, int subtype, String subtypeName, BodyDecoder decoder) {
        universal.set(slot(kind, subtype), new Layout(subtypeName, decoder));
    }

    /** @return the layout for a header's (interface, type, subtype), or null */
    public @Nullable Layout lookup(int interf, int type, int subtype) {
        MessageType t = MessageType.of(type);
        if (t == null || interf < 0 || interf > 0xFFFF || subtype < 0 || subtype > 0xFF) {
            return null;
        }
        int slot = slot(t.layoutKind(), subtype);
        Layout @Nullable [] table = byInterface.get(interf);
        Layout l = table == null ? null : table[slot];
        if (l != null) {
            return l;
        }
        return universal.get(slot);
    }

    /** The subtype's name for display, e.g. "GET_GEOM", or the number as text when unknown. */
    public String subtypeName(int interf, int type, int subtype) {
        Layout l = lookup(interf, type, subtype);
        return l != null ? l.subtypeName() : Integer.toString(subtype);
    }

    private static int slot(MessageType kind, int subtype) {
        if (subtype < 0 || subtype > 0xFF) {
            throw new IllegalArgumentException("subtype " + subtype + " is not 0..255");
        }
        return (kind.code() - 1) * SUBTYPES + subtype;
    }

    private static void checkCode(int code) {
        if (code < 0 || code > 0xFFFF) {
            throw new IllegalArgumentException("interface code " + code + " is not 0..65535");
        }
    }
}
