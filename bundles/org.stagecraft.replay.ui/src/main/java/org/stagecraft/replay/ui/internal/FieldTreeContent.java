package org.stagecraft.replay.ui.internal;

import java.util.List;

import org.eclipse.jface.viewers.ITreeContentProvider;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.replay.fields.FieldTree;

/** Shows a decoded body's {@link FieldTree} in a tree viewer: the input is the body, rows are its fields. */
public final class FieldTreeContent implements ITreeContentProvider {

    /** The viewer's input for a body. */
    public static Object input(MessageBody body) {
        return FieldTree.of(body);
    }

    @Override
    public Object[] getElements(Object input) {
        return input instanceof FieldTree t ? t.children().toArray() : new Object[0];
    }

    @Override
    public Object[] getChildren(Object parent) {
        return parent instanceof FieldTree t ? t.children().toArray() : new Object[0];
    }

    @Override
    public Object getParent(Object element) {
        return null;
    }

    @Override
    public boolean hasChildren(Object element) {
        return element instanceof FieldTree t && !t.children().isEmpty();
    }

    public static String name(Object element) {
        return element instanceof FieldTree t ? t.name() : String.valueOf(element);
    }

    public static String value(Object element) {
        return element instanceof FieldTree t ? String.valueOf(t.value()) : "";
    }

    /** Names of the top-level fields (tests). */
    public static List<String> topNames(Object input) {
        return input instanceof FieldTree t ? t.children().stream().map(FieldTree::name).toList() : List.of();
    }
}
