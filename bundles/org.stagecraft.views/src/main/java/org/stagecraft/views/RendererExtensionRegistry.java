package org.stagecraft.views;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.IExtensionRegistry;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.streams.StreamPattern;

/**
 * Reads the {@value #EXTENSION_POINT} extension point: the renderers plug-ins contribute, each with the
 * stream pattern and colour a new layer of it starts with. A broken contribution (no id, a duplicate id, a
 * bad pattern or colour) is reported, naming the plug-in and the element, and skipped; a class that cannot
 * be created is reported when a layer asks for it.
 */
public final class RendererExtensionRegistry {
    public static final String EXTENSION_POINT = "org.stagecraft.views.renderers";
    private static final String BUNDLE = "org.stagecraft.views";

    /** One contribution; {@link #create()} makes a renderer instance for one layer. */
    public record Contribution(String id, String name, String contributor, StreamPattern defaultPattern, int rgb,
            double alpha, IConfigurationElement element) {
        public Contribution {
            Objects.requireNonNull(id, "id");
        }

        /** @throws CoreException if the class cannot be created or is no StreamRenderer */
        public StreamRenderer create() throws CoreException {
            Object o = element.createExecutableExtension("class");
            if (o instanceof StreamRenderer r) {
                return r;
            }
            throw new CoreException(Status.error("plug-in " + contributor + ", extension " + EXTENSION_POINT
                    + ", renderer '" + id + "': class " + element.getAttribute("class") + " does not extend "
                    + StreamRenderer.class.getName()));
        }

        /** A layer of this renderer with its defaults. */
        public LayerSpec layer(String layerId, int order) {
            return new LayerSpec(layerId, id, name, defaultPattern, true, rgb, alpha, order);
        }
    }

    private RendererExtensionRegistry() {
    }

    /** Every valid contribution by id, in registry order. */
    public static Map<String, Contribution> load(IExtensionRegistry extensions, Consumer<IStatus> problems) {
        Map<String, Contribution> loaded = new LinkedHashMap<>();
        Set<String> ids = new HashSet<>();
        for (IConfigurationElement e : extensions.getConfigurationElementsFor(EXTENSION_POINT)) {
            String where = "plug-in " + e.getContributor().getName() + ", extension " + EXTENSION_POINT + ", element <"
                    + e.getName() + ">";
            try {
                if (!"renderer".equals(e.getName())) {
                    throw new IllegalArgumentException("unknown element");
                }
                String id = trimmed(e.getAttribute("id"));
                if (id == null) {
                    throw new IllegalArgumentException("renderer has no id");
                }
                where += " id '" + id + "'";
                if (!ids.add(id)) {
                    throw new IllegalArgumentException("another renderer already has id '" + id + "'");
                }
                if (trimmed(e.getAttribute("class")) == null) {
                    throw new IllegalArgumentException("renderer has no class");
                }
                String name = trimmed(e.getAttribute("name"));
                String pattern = trimmed(e.getAttribute("defaultPattern"));
                String colour = trimmed(e.getAttribute("defaultColour"));
                String alpha = trimmed(e.getAttribute("defaultAlpha"));
                int rgb = colour == null ? 0x808080 : parseColour(colour);
                loaded.put(id, new Contribution(id, name == null ? id : name, e.getContributor().getName(),
                        pattern == null ? StreamPattern.any() : StreamPattern.parse(pattern), rgb,
                        alpha == null ? 1 : Double.parseDouble(alpha), e));
            } catch (IllegalArgumentException ex) {
                problems.accept(Status.error(where + ": " + ex.getMessage(), ex));
            }
        }
        return loaded;
    }

    /** As {@link #load(IExtensionRegistry, Consumer)} with the platform's registry; problems go to the Error Log. */
    public static Map<String, Contribution> load() {
        ILog log = ILog.of(Platform.getBundle(BUNDLE));
        return load(Platform.getExtensionRegistry(), log::log);
    }

    /** Renderer instances for {@code layers}; a layer whose renderer is missing or broken is reported and left out. */
    public static List<Map.Entry<LayerSpec, StreamRenderer>> instantiate(List<LayerSpec> layers,
            Map<String, Contribution> contributions, Consumer<IStatus> problems) {
        List<Map.Entry<LayerSpec, StreamRenderer>> out = new ArrayList<>();
        for (LayerSpec l : layers) {
            Contribution c = contributions.get(l.rendererId());
            if (c == null) {
                problems.accept(Status.warning("Robot View layer '" + l.name() + "': no renderer '" + l.rendererId()
                        + "' is installed"));
                continue;
            }
            try {
                out.add(Map.entry(l, c.create()));
            } catch (CoreException | RuntimeException | LinkageError ex) {
                problems.accept(Status.error("Robot View layer '" + l.name() + "': renderer '" + l.rendererId()
                        + "' cannot be created: " + ex.getMessage(), ex));
            }
        }
        return out;
    }

    private static int parseColour(String s) {
        if (!s.matches("#[0-9a-fA-F]{6}")) {
            throw new IllegalArgumentException("defaultColour '" + s + "' is not #RRGGBB");
        }
        return Integer.parseInt(s.substring(1), 16);
    }

    private static String trimmed(String s) {
        return s == null || s.isBlank() ? null : s.trim();
    }
}
