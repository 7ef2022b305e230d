package org.stagecraft.tools.ui.registry;

import static org.stagecraft.core.extensions.ExtensionXml.ATT_CLASS;
import static org.stagecraft.core.extensions.ExtensionXml.ATT_NAME;
import static org.stagecraft.core.extensions.ExtensionXml.EL_TOOL_TYPE;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

import org.eclipse.core.runtime.IExtensionRegistry;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.stagecraft.core.extensions.ExtensionReader;
import org.stagecraft.core.extensions.ExtensionXml;
import org.stagecraft.tools.types.ToolType;

/**
 * Reads the {@value #EXTENSION_POINT} extension point. A broken contribution (no id, a duplicate id,
 * a class that cannot be created or is no {@link ToolType}) is reported, naming the plug-in and the
 * element, and skipped; it never keeps the others from loading.
 */
public final class ToolTypeExtensionRegistry {
    public static final String EXTENSION_POINT = ExtensionXml.TOOL_TYPES;
    private static final String BUNDLE = "org.stagecraft.tools.ui";

    /** One loaded contribution. */
    public record Contribution(String id, String name, String contributor, ToolType type) {
    }

    private ToolTypeExtensionRegistry() {
    }

    public static List<Contribution> load(IExtensionRegistry extensions, Consumer<IStatus> problems) {
        List<Contribution> loaded = new ArrayList<>();
        new ExtensionReader(EXTENSION_POINT, problems).read(extensions, e -> {
            e.expect(EL_TOOL_TYPE);
            String id = e.id("tool type");
            ToolType t = e.create(ATT_CLASS, ToolType.class);
            loaded.add(new Contribution(id, e.attribute(ATT_NAME, id), e.contributor(), t));
        });
        return loaded;
    }

    /** Every contribution of the running platform; problems go to the Error Log. */
    public static List<Contribution> load() {
        ILog log = ILog.of(Platform.getBundle(BUNDLE));
        return load(Platform.getExtensionRegistry(), log::log);
    }

    public static Optional<Contribution> find(String id) {
        return load().stream().filter(c -> c.id().equals(id)).findFirst();
    }
}
