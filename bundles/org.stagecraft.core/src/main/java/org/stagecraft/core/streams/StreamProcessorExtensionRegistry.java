package org.stagecraft.core.streams;

import static org.stagecraft.core.extensions.ExtensionXml.ATT_CLASS;
import static org.stagecraft.core.extensions.ExtensionXml.ATT_NAME;
import static org.stagecraft.core.extensions.ExtensionXml.EL_PROCESSOR;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.IExtensionRegistry;
import org.eclipse.core.runtime.IStatus;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.core.extensions.ExtensionReader;
import org.stagecraft.core.extensions.ExtensionXml;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamProcessor;
import org.stagecraft.streams.StreamProcessors;

/**
 * Reads the {@value #EXTENSION_POINT} extension point: the stream processors plug-ins contribute. A
 * broken contribution (no id, a duplicate id, a class that cannot be created or is no
 * {@link StreamProcessor}, a processor whose {@code start} throws) is reported, naming the plug-in and
 * the element, and skipped; it never keeps the others from loading. The workbench runs them through
 * {@link Contributions#startProcessors(StreamBus)}.
 */
public final class StreamProcessorExtensionRegistry {
    public static final String EXTENSION_POINT = ExtensionXml.STREAM_PROCESSORS;

    /** One loaded contribution: a new processor instance, not started yet. */
    public record Contribution(String id, String name, String contributor, StreamProcessor processor) {
        public Contribution {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(processor, "processor");
        }
    }

    /**
     * A contribution that loaded once, kept to make a new instance for every bus it runs on (a
     * processor may keep state per bus).
     */
    public record Descriptor(String id, String name, String contributor, IConfigurationElement element) {
        public Descriptor {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(element, "element");
        }

        /** A new, unstarted instance. @throws CoreException if the platform cannot create it */
        public StreamProcessor newProcessor() throws CoreException {
            return ExtensionReader.create(element, ATT_CLASS, StreamProcessor.class);
        }
    }

    private StreamProcessorExtensionRegistry() {
    }

    /** Loads every contribution (new instances each call), reporting problems to {@code problems}. */
    public static List<Contribution> load(IExtensionRegistry extensions, Consumer<IStatus> problems) {
        List<Contribution> loaded = new ArrayList<>();
        read(extensions, problems, (d, p) -> loaded.add(new Contribution(d.id(), d.name(), d.contributor(), p)));
        return loaded;
    }

    /**
     * Every contribution whose class can be created and is a {@link StreamProcessor} (each is created once
     * to find out), reporting the others to {@code problems}.
     */
    public static List<Descriptor> descriptors(IExtensionRegistry extensions, Consumer<IStatus> problems) {
        List<Descriptor> loaded = new ArrayList<>();
        read(extensions, problems, (d, p) -> loaded.add(d));
        return loaded;
    }

    private interface Sink {
        void accept(Descriptor d, StreamProcessor created);
    }

    private static void read(IExtensionRegistry extensions, Consumer<IStatus> problems, Sink sink) {
        new ExtensionReader(EXTENSION_POINT, problems).read(extensions, e -> {
            e.expect(EL_PROCESSOR);
            String id = e.id(EL_PROCESSOR);
            StreamProcessor p = e.create(ATT_CLASS, StreamProcessor.class);
            sink.accept(new Descriptor(id, e.attribute(ATT_NAME, id), e.contributor(), e.raw()), p);
        });
    }

    /**
     * Loads every contribution and starts it on {@code bus} under its id; a processor whose start throws is
     * reported and skipped. The caller stops them with {@link StreamProcessors#stopAll()}.
     */
    public static StreamProcessors startAll(StreamBus bus, IExtensionRegistry extensions, Consumer<IStatus> problems) {
        return start(bus, descriptors(extensions, problems), problems);
    }

    /** As {@link #startAll(StreamBus, IExtensionRegistry, Consumer)} with the workbench's contributions. */
    public static StreamProcessors startAll(StreamBus bus) {
        return Contributions.workbench().startProcessors(bus);
    }

    /**
     * Starts a new instance of each of {@code descriptors} on {@code bus} under its id; one that cannot be
     * created or whose start throws is reported and skipped.
     */
    public static StreamProcessors start(StreamBus bus, List<Descriptor> descriptors, Consumer<IStatus> problems) {
        StreamProcessors processors = new StreamProcessors(bus);
        for (Descriptor d : descriptors) {
            try {
                processors.start(d.id(), d.newProcessor());
            } catch (CoreException | RuntimeException | LinkageError ex) {
                problems.accept(ExtensionReader.problem(EXTENSION_POINT, d.contributor(), EL_PROCESSOR, d.id(),
                        "start failed: " + ex, ex));
            }
        }
        return processors;
    }
}
