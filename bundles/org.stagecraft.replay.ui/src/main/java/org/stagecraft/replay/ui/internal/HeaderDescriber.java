package org.stagecraft.replay.ui.internal;

import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Hashtable;
import java.util.Optional;

import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.IExecutableExtension;
import org.eclipse.core.runtime.QualifiedName;
import org.eclipse.core.runtime.content.IContentDescription;
import org.eclipse.core.runtime.content.ITextContentDescriber;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.log.LogFormat;
import org.stagecraft.replay.log.SessionLogs;

/**
 * Recognises a log by its first bytes, so a common extension ({@code .log}, {@code .jsonl}) opens in the
 * Session Log editor exactly when the core can open the file: the describer asks
 * {@link SessionLogs#formatOf(byte[])} (the rule {@link SessionLogs#open} uses) rather than keeping a
 * rule of its own. Parameter (plugin.xml): {@code format}, the {@link LogFormat} name the content type
 * stands for.
 */
public final class HeaderDescriber implements ITextContentDescriber, IExecutableExtension {
    private @Nullable LogFormat format;

    public HeaderDescriber() {
    }

    /** For tests and plain use. */
    public HeaderDescriber(LogFormat format) {
        this.format = format;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void setInitializationData(IConfigurationElement config, String property, Object data) {
        if (data instanceof Hashtable<?, ?> parameters && parameters.get("format") instanceof String f) {
            format = LogFormat.valueOf(f);
        }
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public int describe(InputStream contents, IContentDescription description) throws IOException {
        return matches(contents.readNBytes(SessionLogs.HEAD)) ? VALID : INVALID;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public int describe(Reader contents, IContentDescription description) throws IOException {
        // the formats are UTF-8 (traces) or ASCII (writelog): the characters' UTF-8 bytes are the file's
        char[] chars = new char[SessionLogs.HEAD];
        int n = 0;
        for (int r; n < chars.length && (r = contents.read(chars, n, chars.length - n)) >= 0;) {
            n += r;
        }
        byte[] bytes = new String(chars, 0, n).getBytes(StandardCharsets.UTF_8);
        return matches(Arrays.copyOf(bytes, Math.min(bytes.length, SessionLogs.HEAD))) ? VALID : INVALID;
    }

    /** Whether a file starting with {@code head} is of this describer's format. */
    public boolean matches(byte[] head) {
        Optional<LogFormat> f = SessionLogs.formatOf(head);
        return format != null && f.isPresent() && f.get() == format;
    }

    @Override
    public QualifiedName[] getSupportedOptions() {
        return new QualifiedName[0];
    }
}
