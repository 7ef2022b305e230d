package org.stagecraft.core.extensions;

import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;

import org.eclipse.core.runtime.IExtensionRegistry;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.core.codec.DecoderExtensionRegistry;
import org.stagecraft.core.streams.StreamProcessorExtensionRegistry;
import org.stagecraft.core.streams.StreamProcessorExtensionRegistry.Descriptor;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamProcessors;

/**
 * The one host of what plug-ins contribute to the running system: the workbench's codec registry
 * (Player's standard interfaces plus every {@value ExtensionXml#DECODERS} contribution) and its
 * stream processors ({@value ExtensionXml#STREAM_PROCESSORS}). Every place that decodes or publishes
 * takes them from here: a Robot Session's spy decodes with {@link #codecs()}, the Session Log editor
 * opens, inspects, plots and exports logs with it, and the workbench bus and every replay bus run
 * {@link #startProcessors(StreamBus) the processors}. Contributions are read once, when first asked
 * for; a broken one is reported (to the Error Log for {@link #workbench()}) and left out.
 */
public final class Contributions {
    private static final String BUNDLE = "org.stagecraft.core";
    private static @Nullable Contributions workbench;

    private final CodecRegistry codecs;
    private final List<Descriptor> processors;
    private final Consumer<IStatus> problems;

    private Contributions(CodecRegistry codecs, List<Descriptor> processors, Consumer<IStatus> problems) {
        this.codecs = codecs;
        this.processors = List.copyOf(processors);
        this.problems = problems;
    }

    /** The running workbench's contributions, read on first use; problems go to the Error Log. */
    public static synchronized Contributions workbench() {
        Contributions w = workbench;
        if (w == null) {
            ILog log = ILog.of(Platform.getBundle(BUNDLE));
            w = load(Platform.getExtensionRegistry(), log::log);
            workbench = w;
        }
        return w;
    }

    /** Reads the contributions of {@code extensions}; every problem, now or when processors start, goes to {@code problems}. */
    public static Contributions load(IExtensionRegistry extensions, Consumer<IStatus> problems) {
        Objects.requireNonNull(problems, "problems");
        return new Contributions(DecoderExtensionRegistry.load(extensions, problems),
                StreamProcessorExtensionRegistry.descriptors(extensions, problems), problems);
    }

    /** Player's standard interfaces and every contributed interface and decoder; thread-safe, shared. */
    public CodecRegistry codecs() {
        return codecs;
    }

    /** A decoder over {@link #codecs()}. */
    public PlayerDecoder decoder() {
        return new PlayerDecoder(codecs);
    }

    /** The contributed processors that loaded, in registry order. */
    public List<Descriptor> processors() {
        return processors;
    }

    /**
     * Starts a new instance of every contributed processor on {@code bus}; one that cannot be created or
     * whose start throws is reported and skipped. Stop them with {@link StreamProcessors#stopAll()}
     * before (or when) the bus closes.
     */
    public StreamProcessors startProcessors(StreamBus bus) {
        return StreamProcessorExtensionRegistry.start(bus, processors, problems);
    }
}
