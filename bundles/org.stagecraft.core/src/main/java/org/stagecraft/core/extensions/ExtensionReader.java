package org.stagecraft.core.extensions;

import java.util.HashSet;
import java.util.Set;
import java.util.function.Consumer;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.IExtensionRegistry;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.jdt.annotation.Nullable;

/**
 * Reads the elements of one extension point for a registry, the same way for all four of
 * Stagecraft's: each element is handed to the registry's {@link Handler}; whatever a handler throws
 * (a missing or duplicate id, a class that cannot be created or has the wrong type, a bad value)
 * becomes one error naming the plug-in, the extension point, the element and its id, and the next
 * element is read. A broken contribution never keeps the others from loading. An id is taken only by
 * a contribution that loaded, so a broken one never blocks a good one's id.
 */
public final class ExtensionReader {
    /** Reads one element; throws to report it as broken. */
    @FunctionalInterface
    public interface Handler {
        void read(Element element) throws CoreException;
    }

    private final String point;
    private final Consumer<IStatus> problems;
    private final Set<String> ids = new HashSet<>();

    /**
     * @param point    the extension point's full id, e.g. {@link ExtensionXml#DECODERS}
     * @param problems told about every broken contribution (e.g. the Error Log)
     */
    public ExtensionReader(String point, Consumer<IStatus> problems) {
        this.point = point;
        this.problems = problems;
    }

    /** Hands every element of the point, in registry order, to {@code handler}. */
    public void read(IExtensionRegistry extensions, Handler handler) {
        for (IConfigurationElement e : extensions.getConfigurationElementsFor(point)) {
            Element element = new Element(e);
            try {
                handler.read(element);
                if (element.id != null) {
                    ids.add(element.id);
                }
            } catch (CoreException | RuntimeException | LinkageError ex) {
                problems.accept(Status.error(element.where() + ": " + ex.getMessage(), ex));
            }
        }
    }

    /** Reports a problem with a contribution found after reading (e.g. a processor whose start failed). */
    public static IStatus problem(String point, String contributor, String element, String id, String message, Throwable cause) {
        return Status.error(where(contributor, point, element, id) + ": " + message, cause);
    }

    private static String where(String contributor, String point, String element, @Nullable String id) {
        return "plug-in " + contributor + ", extension " + point + ", element <" + element + ">"
                + (id == null ? "" : " id '" + id + "'");
    }

    /** One element being read: its attributes, trimmed, and what it names. */
    public final class Element {
        private final IConfigurationElement raw;
        private @Nullable String id;

        private Element(IConfigurationElement raw) {
            this.raw = raw;
        }

        /** The element's name, e.g. {@link ExtensionXml#EL_PROCESSOR}. */
        public String name() {
            return raw.getName();
        }

        /** The contributing plug-in's id. */
        public String contributor() {
            return raw.getContributor().getName();
        }

        /** The platform's element, for creating more instances later. */
        public IConfigurationElement raw() {
            return raw;
        }

        /** The id once {@link #id(String)} read it, else null. */
        public @Nullable String idOrNull() {
            return id;
        }

        /** "plug-in P, extension X, element &lt;E&gt; id 'I'": where a problem is. */
        public String where() {
            return ExtensionReader.where(contributor(), point, name(), id);
        }

        /** @throws IllegalArgumentException "unknown element" unless the element is named {@code expected} */
        public void expect(String expected) {
            if (!expected.equals(name())) {
                throw new IllegalArgumentException("unknown element");
            }
        }

        /** The attribute, trimmed; null when absent or blank. */
        public @Nullable String attribute(String attribute) {
            String s = raw.getAttribute(attribute);
            return s == null || s.isBlank() ? null : s.trim();
        }

        /** The attribute as {@link #attribute(String)}, or {@code otherwise} when it is absent. */
        public String attribute(String attribute, String otherwise) {
            String s = attribute(attribute);
            return s == null ? otherwise : s;
        }

        /** @throws IllegalArgumentException "E has no A" when the attribute is absent or blank */
        public String required(String attribute) {
            String s = attribute(attribute);
            if (s == null) {
                throw new IllegalArgumentException(name() + " has no " + attribute);
            }
            return s;
        }

        /**
         * The element's {@link ExtensionXml#ATT_ID}, unique among the contributions that loaded.
         *
         * @param kind what the id names in a message, e.g. "processor"
         * @throws IllegalArgumentException when it is missing or another contribution has it
         */
        public String id(String kind) {
            String s = required(ExtensionXml.ATT_ID);
            id = s;
            if (ids.contains(s)) {
                throw new IllegalArgumentException("another " + kind + " already has id '" + s + "'");
            }
            return s;
        }

        /**
         * A new instance of the class the {@code attribute} names, which must be a {@code type}.
         *
         * @throws CoreException when the platform cannot create it
         * @throws IllegalArgumentException "class C does not implement T" when it is of another type
         */
        public <T> T create(String attribute, Class<T> type) throws CoreException {
            return ExtensionReader.create(raw, attribute, type);
        }
    }

    /** As {@link Element#create(String, Class)}, for an element kept from an earlier reading. */
    public static <T> T create(IConfigurationElement raw, String attribute, Class<T> type) throws CoreException {
        Object o = raw.createExecutableExtension(attribute);
        if (!type.isInstance(o)) {
            throw new IllegalArgumentException("class " + raw.getAttribute(attribute) + " does not "
                    + (type.isInterface() ? "implement " : "extend ") + type.getName());
        }
        return type.cast(o);
    }
}
