package org.stagecraft.views.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.ui.IMemento;
import org.stagecraft.scene.ViewSetup;

/**
 * A Robot View's {@link ViewSetup} in its IMemento: a {@code camera} child and one {@code layer} child per
 * layer, each with the string attributes of the scene's persistence format, plus a format version.
 */
public final class ViewMemento {
    static final String VERSION = "robotViewVersion", CAMERA = "camera", LAYER = "layer";

    private ViewMemento() {
    }

    public static void write(IMemento m, ViewSetup setup) {
        m.putInteger(VERSION, ViewSetup.VERSION);
        IMemento camera = m.createChild(CAMERA);
        setup.camera().forEach(camera::putString);
        for (Map<String, String> layer : setup.layerAttributes()) {
            IMemento l = m.createChild(LAYER);
            layer.forEach(l::putString);
        }
    }

    /** The setup, or null if the memento holds none (or one from a newer, incompatible version). */
    public static @Nullable ViewSetup read(IMemento m, Consumer<String> problems) {
        Integer version = m.getInteger(VERSION);
        if (version == null) {
            return null;
        }
        if (version > ViewSetup.VERSION) {
            problems.accept("Robot View setup of format " + version + " is newer than this version reads ("
                    + ViewSetup.VERSION + "): starting with the default layers");
            return null;
        }
        IMemento c = m.getChild(CAMERA);
        List<Map<String, String>> layers = new ArrayList<>();
        for (IMemento l : m.getChildren(LAYER)) {
            layers.add(attributes(l));
        }
        return ViewSetup.read(layers, c == null ? Map.of() : attributes(c), problems);
    }

    private static Map<String, String> attributes(IMemento m) {
        Map<String, String> a = new LinkedHashMap<>();
        for (String k : m.getAttributeKeys()) {
            a.put(k, m.getString(k));
        }
        return a;
    }
}
