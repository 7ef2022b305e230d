package org.stagecraft.core.streams;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
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
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamProcessor;
import org.stagecraft.streams.StreamProcessors;

/**
 * Reads the {@value #EXTENSION_POINT} extension point: the stream processors plug-ins contribute. A
 * broken contribution (no id, a duplicate id, a class that cannot be created or is no
 * {@link StreamProcessor}, a processor whose {@code start} throws) is reported, naming the plug-in and
 * the element, and skipped; it never keeps the others from loading.
 */
public final class StreamProcessorExtensionRegistry {
    public static final String EXTENSION_POINT = "org.stagecraft.core.streamProcessors";
    private static final String BUNDLE = "org.stagecraft.core";

    /** One loaded contribution: a new processor instance, not started yet. */
    public record Contribution(String id, String name, String contributor, StreamProcessor processor) {
        public Contribution {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(processor, "processor");
        }
    }

    private StreamProcessorExtensionRegistry() {
    }

    /** Loads every contribution (new instances each call), reporting problems to {@code problems}. */
    public static List<Contribution> load(IExtensionRegistry extensions, Consumer<IStatus> problems) {
        List<Contribution> loaded = new ArrayList<>();
        Set<String> ids = new HashSet<>();
        for (IConfigurationElement e : extensions.getConfigurationElementsFor(EXTENSION_POINT)) {
            String where = where(e);
            try {
                if (!"processor".equals(e.getName())) {
                    problems.accept(error(where + ": unknown element", null));
                    continue;
                }
                String id = trimmed(e.getAttribute("id"));
                if (id == null) {
                    throw new IllegalArgumentException("processor has no id");
                }
                where = where + " id '" + id + "'";
                if (!ids.add(id)) {
                    throw new IllegalArgumentException("another processor already has id '" + id + "'");
                }
                String name = trimmed(e.getAttribute("name"));
                Object o = e.createExecutableExtension("class");
                if (!(o instanceof StreamProcessor p)) {
                    ids.remove(id);
                    throw new IllegalArgumentException("class " + e.getAttribute("class") + " does not implement "
                            + StreamProcessor.class.getName());
                }
                loaded.add(new Contribution(id, name == null ? id : name, e.getContributor().getName(), p));
            } catch (CoreException | RuntimeException | LinkageError ex) {
                problems.accept(error(where + ": " + ex.getMessage(), ex));
            }
        }
        return loaded;
    }

    /**
     * Loads every contribution and starts it on {@code bus} under its id; a processor whose start throws is
     * reported and skipped. The caller stops them with {@link StreamProcessors#stopAll()}.
     */
    public static StreamProcessors startAll(StreamBus bus, IExtensionRegistry extensions, Consumer<IStatus> problems) {
        StreamProcessors processors = new StreamProcessors(bus);
        for (Contribution c : load(extensions, problems)) {
            try {
                processors.start(c.id(), c.processor());
            } catch (RuntimeException | LinkageError ex) {
                problems.accept(error("plug-in " + c.contributor() + ", extension " + EXTENSION_POINT
                        + ", element <processor> id '" + c.id() + "': start failed: " + ex, ex));
            }
        }
        return processors;
    }

    /** As {@link #startAll(StreamBus, IExtensionRegistry, Consumer)} with the platform's registry; problems go to the Error Log. */
    public static StreamProcessors startAll(StreamBus bus) {
        ILog log = ILog.of(Platform.getBundle(BUNDLE));
        return startAll(bus, Platform.getExtensionRegistry(), log::log);
    }

    private static String where(IConfigurationElement e) {
        return "plug-in " + e.getContributor().getName() + ", extension " + EXTENSION_POINT + ", element <"
                + e.getName() + ">";
    }

    private static String trimmed(String s) {
        return s == null || s.isBlank() ? null : s.trim();
    }

    private static IStatus error(String message, Throwable cause) {
        return Status.error(message, cause);
    }
}
