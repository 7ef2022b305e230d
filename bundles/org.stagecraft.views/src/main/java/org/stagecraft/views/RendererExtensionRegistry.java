package org.stagecraft.views;

import static org.stagecraft.core.extensions.ExtensionXml.ATT_CLASS;
import static org.stagecraft.core.extensions.ExtensionXml.ATT_DEFAULT_ALPHA;
import static org.stagecraft.core.extensions.ExtensionXml.ATT_DEFAULT_COLOUR;
import static org.stagecraft.core.extensions.ExtensionXml.ATT_DEFAULT_PATTERN;
import static org.stagecraft.core.extensions.ExtensionXml.ATT_NAME;
import static org.stagecraft.core.extensions.ExtensionXml.EL_RENDERER;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.IExtensionRegistry;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.core.extensions.ExtensionReader;
import org.stagecraft.core.extensions.ExtensionXml;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.streams.StreamPattern;

/**
 * Reads the {@value #EXTENSION_POINT} extension point: the renderers plug-ins contribute, each with the
 * stream pattern and colour a new layer of it starts with. A broken contribution (no id, a duplicate id, a
 * bad pattern or colour) is reported, naming the plug-in and the element, and skipped; a class that cannot
 * be created is reported when a layer asks for it.
 */
public final class RendererExtensionRegistry {
    public static final String EXTENSION_POINT = ExtensionXml.RENDERERS;
    private static final String BUNDLE = "org.stagecraft.views";

    /** One contribution; {@link #create()} makes a renderer instance for one layer. */
    public record Contribution(String id, String name, String contributor, StreamPattern defaultPattern, int rgb,
            double alpha, IConfigurationElement element) {
        public Contribution {
            Objects.requireNonNull(id, "id");
        }

        /** @throws CoreException if the class cannot be created or is no StreamRenderer */
        public StreamRenderer create() throws CoreException {
            try {
                return ExtensionReader.create(element, ATT_CLASS, StreamRenderer.class);
            } catch (IllegalArgumentException e) {
                throw new CoreException(Status.error("plug-in " + contributor + ", extension " + EXTENSION_POINT
                        + ", renderer '" + id + "': " + e.getMessage(), e));
            }
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
        new ExtensionReader(EXTENSION_POINT, problems).read(extensions, e -> {
            e.expect(EL_RENDERER);
            String id = e.id(EL_RENDERER);
            e.required(ATT_CLASS);
            String pattern = e.attribute(ATT_DEFAULT_PATTERN);
            String colour = e.attribute(ATT_DEFAULT_COLOUR);
            String alpha = e.attribute(ATT_DEFAULT_ALPHA);
            int rgb = colour == null ? 0x808080 : parseColour(colour);
            loaded.put(id, new Contribution(id, e.attribute(ATT_NAME, id), e.contributor(),
                    pattern == null ? StreamPattern.any() : StreamPattern.parse(pattern), rgb,
                    alpha == null ? 1 : Double.parseDouble(alpha), e.raw()));
        });
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
            @Nullable Contribution c = contributions.get(l.rendererId());
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
}
