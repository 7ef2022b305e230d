package org.stagecraft.core.codec;

import static org.stagecraft.core.extensions.ExtensionXml.ATT_CLASS;
import static org.stagecraft.core.extensions.ExtensionXml.ATT_CODE;
import static org.stagecraft.core.extensions.ExtensionXml.ATT_NAME;
import static org.stagecraft.core.extensions.ExtensionXml.EL_CODEC;
import static org.stagecraft.core.extensions.ExtensionXml.EL_INTERFACE;

import java.util.function.Consumer;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IExtensionRegistry;
import org.eclipse.core.runtime.IStatus;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.core.extensions.ExtensionReader;
import org.stagecraft.core.extensions.ExtensionXml;
import org.stagecraft.player.codec.CodecContribution;
import org.stagecraft.player.codec.CodecRegistry;

/**
 * Reads the {@value #EXTENSION_POINT} extension point: Player's standard interfaces plus every
 * plug-in's interfaces and decoders. A broken contribution is reported (naming the plug-in and
 * the element) and skipped; it never keeps the others from loading. The workbench's registry is
 * {@link Contributions#codecs()}.
 */
public final class DecoderExtensionRegistry {
    public static final String EXTENSION_POINT = ExtensionXml.DECODERS;

    private DecoderExtensionRegistry() {
    }

    /** The workbench-wide registry: {@link Contributions#workbench()}'s. */
    public static CodecRegistry get() {
        return Contributions.workbench().codecs();
    }

    /** Builds a registry from the given extension registry, reporting problems to {@code problems}. */
    public static CodecRegistry load(IExtensionRegistry extensions, Consumer<IStatus> problems) {
        CodecRegistry registry = CodecRegistry.standard();
        new ExtensionReader(EXTENSION_POINT, problems).read(extensions, e -> {
            switch (e.name()) {
                case EL_INTERFACE -> addInterface(registry, e);
                case EL_CODEC -> addCodec(registry, e);
                default -> throw new IllegalArgumentException("unknown element");
            }
        });
        return registry;
    }

    private static void addInterface(CodecRegistry registry, ExtensionReader.Element e) {
        String code = e.attribute(ATT_CODE);
        int value;
        try {
            value = Integer.parseInt(code == null ? "" : code);
        } catch (NumberFormatException ex) {
            throw new IllegalArgumentException("code '" + code + "' is not a number", ex);
        }
        String name = e.attribute(ATT_NAME);
        if (name == null) {
            throw new IllegalArgumentException("interface " + value + " has no name");
        }
        registry.registerInterface(value, name);
    }

    private static void addCodec(CodecRegistry registry, ExtensionReader.Element e) throws CoreException {
        registry.add(e.create(ATT_CLASS, CodecContribution.class));
    }
}
