package org.stagecraft.tools.ui.registry;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.IExtensionRegistry;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.stagecraft.tools.types.ToolType;

/**
 * Reads the {@value #EXTENSION_POINT} extension point. A broken contribution (no id, a duplicate id,
 * a class that cannot be created or is no {@link ToolType}) is reported, naming the plug-in and the
 * element, and skipped; it never keeps the others from loading.
 */
public final class ToolTypeExtensionRegistry {
    public static final String EXTENSION_POINT = "org.stagecraft.tools.ui.toolTypes";
    private static final String BUNDLE = "org.stagecraft.tools.ui";

    /** One loaded contribution. */
    public record Contribution(String id, String name, String contributor, ToolType type) {
    }

    private ToolTypeExtensionRegistry() {
    }

    public static List<Contribution> load(IExtensionRegistry extensions, Consumer<IStatus> problems) {
        List<Contribution> loaded = new ArrayList<>();
        Set<String> ids = new HashSet<>();
        for (IConfigurationElement e : extensions.getConfigurationElementsFor(EXTENSION_POINT)) {
            String where = "plug-in " + e.getContributor().getName() + ", extension " + EXTENSION_POINT + ", element <"
                    + e.getName() + ">";
            try {
                if (!"toolType".equals(e.getName())) {
                    throw new IllegalArgumentException("unknown element");
                }
                String id = trimmed(e.getAttribute("id"));
                if (id == null) {
                    throw new IllegalArgumentException("toolType has no id");
                }
                where += " id '" + id + "'";
                if (ids.contains(id)) {
                    throw new IllegalArgumentException("another tool type already has id '" + id + "'");
                }
                Object o = e.createExecutableExtension("class");
                if (!(o instanceof ToolType t)) {
                    throw new IllegalArgumentException("class " + e.getAttribute("class") + " does not implement "
                            + ToolType.class.getName());
                }
                ids.add(id);
                String name = trimmed(e.getAttribute("name"));
                loaded.add(new Contribution(id, name == null ? id : name, e.getContributor().getName(), t));
            } catch (CoreException | RuntimeException | LinkageError ex) {
                problems.accept(Status.error(where + ": " + ex.getMessage(), ex));
            }
        }
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

    private static String trimmed(String s) {
        return s == null || s.isBlank() ? null : s.trim();
    }
}
