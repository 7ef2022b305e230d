package org.stagecraft.replay.ui.internal;

import java.util.List;
import java.util.Locale;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.viewers.ITreeContentProvider;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.replay.fields.Field;
import org.stagecraft.replay.fields.FieldTree;

/** Shows a decoded body's {@link FieldTree} in a tree viewer: the input is the root field, rows are its fields. */
public final class FieldTreeContent implements ITreeContentProvider {

    /** The viewer's input for a body. */
    public static Object input(MessageBody body) {
        return FieldTree.of(body);
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public Object[] getElements(Object input) {
        return getChildren(input);
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public Object[] getChildren(Object parent) {
        if (!(parent instanceof Field f)) {
            return new Object[0];
        }
        // list elements have no name: show their index
        Object[] out = new Object[f.children().size()];
        for (int i = 0; i < out.length; i++) {
            Field c = f.children().get(i);
            out[i] = c.name() == null ? new Element(i, c) : c;
        }
        return out;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object getParent(Object element) {
        return null;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public boolean hasChildren(Object element) {
        Field f = field(element);
        return f != null && !f.children().isEmpty();
    }

    /** A list element with its index. */
    record Element(int index, Field field) {
    }

    /** The field a row shows (a list element's too), or null. */
    public static @Nullable Field fieldOf(@Nullable Object element) {
        return element == null ? null : field(element);
    }

    private static @Nullable Field field(Object element) {
        return element instanceof Element e ? e.field() : element instanceof Field f ? f : null;
    }

    public static @Nullable String name(Object element) {
        if (element instanceof Element e) {
            return "[" + e.index() + "]";
        }
        return element instanceof Field f ? f.name() : String.valueOf(element);
    }

    public static String value(Object element) {
        Field f = field(element);
        if (f == null) {
            return "";
        }
        return switch (f.kind()) {
            case LIST -> f.children().size() + " elements";
            case STRUCT -> "";
            case TEXT -> "\"" + f.value() + "\"";
            case OPAQUE -> ((byte[]) f.value()).length + " bytes";
            case FLOAT32, FLOAT64, INTEGER -> String.valueOf(f.value());
        } + kindSuffix(f);
    }

    private static String kindSuffix(Field f) {
        return f.kind().numeric() ? "  (" + f.kind().name().toLowerCase(Locale.ROOT) + ")" : "";
    }

    /** Names of the top-level fields (tests). */
    public static List<String> topNames(Object input) {
        return input instanceof Field f ? f.children().stream().map(c -> String.valueOf(c.name())).toList() : List.of();
    }
}
