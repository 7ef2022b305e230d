package org.stagecraft.core.codec;

import java.util.function.Consumer;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.IExtensionRegistry;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.stagecraft.player.codec.CodecContribution;
import org.stagecraft.player.codec.CodecRegistry;

/**
 * Reads the {@value #EXTENSION_POINT} extension point: Player's standard interfaces plus every
 * plug-in's interfaces and decoders. A broken contribution is reported (naming the plug-in and
 * the element) and skipped; it never keeps the others from loading.
 */
public final class DecoderExtensionRegistry {
    public static final String EXTENSION_POINT = "org.stagecraft.core.decoders";
    private static final String BUNDLE = "org.stagecraft.core";

    private static CodecRegistry shared;

    private DecoderExtensionRegistry() {
    }

    /** The workbench-wide registry, loaded on first use; problems go to the Error Log. */
    public static synchronized CodecRegistry get() {
        if (shared == null) {
            ILog log = ILog.of(Platform.getBundle(BUNDLE));
            shared = load(Platform.getExtensionRegistry(), log::log);
        }
        return shared;
    }

    /** Builds a registry from the given extension registry, reporting problems to {@code problems}. */
    public static CodecRegistry load(IExtensionRegistry extensions, Consumer<IStatus> problems) {
        CodecRegistry registry = CodecRegistry.standard();
        for (IConfigurationElement e : extensions.getConfigurationElementsFor(EXTENSION_POINT)) {
            String where = "plug-in " + e.getContributor().getName() + ", extension " + EXTENSION_POINT + ", element <"
                    + e.getName() + ">";
            try {
                switch (e.getName()) {
                    case "interface" -> addInterface(registry, e);
                    case "codec" -> addCodec(registry, e);
                    default -> problems.accept(error(where + ": unknown element", null));
                }
            } catch (CoreException | RuntimeException | LinkageError ex) {
                problems.accept(error(where + ": " + ex.getMessage(), ex));
            }
        }
        return registry;
    }

    private static void addInterface(CodecRegistry registry, IConfigurationElement e) {
        String code = e.getAttribute("code");
        String name = e.getAttribute("name");
        int value;
        try {
            value = Integer.parseInt(code == null ? "" : code.trim());
        } catch (NumberFormatException ex) {
            throw new IllegalArgumentException("code '" + code + "' is not a number", ex);
        }
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("interface " + value + " has no name");
        }
        registry.registerInterface(value, name.trim());
    }

    private static void addCodec(CodecRegistry registry, IConfigurationElement e) throws CoreException {
        Object o = e.createExecutableExtension("class");
        if (!(o instanceof CodecContribution c)) {
            throw new IllegalArgumentException("class " + e.getAttribute("class") + " does not implement "
                    + CodecContribution.class.getName());
        }
        registry.add(c);
    }

    private static IStatus error(String message, Throwable cause) {
        return Status.error(message, cause);
    }
}
