package org.stagecraft.replay.ui.internal;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.util.Hashtable;

import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.QualifiedName;
import org.eclipse.core.runtime.content.IContentDescription;
import org.eclipse.core.runtime.content.ITextContentDescriber;
import org.eclipse.core.runtime.IExecutableExtension;

/**
 * Recognises a text log by its first line, so a common extension ({@code .log}, {@code .jsonl}) opens in
 * the Session Log editor only when the file really is one: a Player writelog file starts with
 * {@code "## Player version"}, a recorded trace's header line holds {@code "format":"player-trace"}.
 * Parameters (plugin.xml): {@code startsWith} or {@code contains} (compared without whitespace).
 */
public final class HeaderDescriber implements ITextContentDescriber, IExecutableExtension {
    /** More than any header line we look for; a file whose first line is longer is not ours. */
    static final int MAX_LINE = 4096;

    private String startsWith;
    private String contains;

    public HeaderDescriber() {
    }

    /** For tests and plain use. */
    public HeaderDescriber(String startsWith, String contains) {
        this.startsWith = startsWith;
        this.contains = contains == null ? null : contains.replaceAll("\\s", "");
    }

    @Override
    public void setInitializationData(IConfigurationElement config, String property, Object data) {
        if (data instanceof Hashtable<?, ?> parameters) {
            startsWith = (String) parameters.get("startsWith");
            String c = (String) parameters.get("contains");
            contains = c == null ? null : c.replaceAll("\\s", "");
        }
    }

    @Override
    public int describe(InputStream contents, IContentDescription description) throws IOException {
        return describe(new InputStreamReader(contents, StandardCharsets.UTF_8), description);
    }

    @Override
    public int describe(Reader contents, IContentDescription description) throws IOException {
        return matches(firstLine(contents)) ? VALID : INVALID;
    }

    /** Whether a file starting with {@code line} is of this type. */
    public boolean matches(String line) {
        if (line == null) {
            return false;
        }
        if (startsWith != null && !line.startsWith(startsWith)) {
            return false;
        }
        return contains == null || line.replaceAll("\\s", "").contains(contains);
    }

    private static String firstLine(Reader in) throws IOException {
        BufferedReader r = new BufferedReader(in, MAX_LINE);
        char[] buf = new char[MAX_LINE];
        int n = 0;
        while (n < MAX_LINE) {
            int c = r.read();
            if (c < 0 || c == '\n' || c == '\r') {
                break;
            }
            buf[n++] = (char) c;
        }
        return new String(buf, 0, n).replace("\uFEFF", "");
    }

    @Override
    public QualifiedName[] getSupportedOptions() {
        return new QualifiedName[0];
    }
}
