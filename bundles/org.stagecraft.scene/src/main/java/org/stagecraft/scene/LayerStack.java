package org.stagecraft.scene;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.eclipse.jdt.annotation.Nullable;

/** A view's layers, kept in draw order (ascending {@link LayerSpec#order()}, then insertion). */
public final class LayerStack {
    private final List<LayerSpec> layers = new CopyOnWriteArrayList<>();

    public LayerStack(List<LayerSpec> initial) {
        initial.forEach(this::put);
    }

    /** Adds the layer, or replaces the one with the same id. */
    public synchronized void put(LayerSpec l) {
        for (int i = 0; i < layers.size(); i++) {
            if (layers.get(i).id().equals(l.id())) {
                layers.set(i, l);
                sort();
                return;
            }
        }
        layers.add(l);
        sort();
    }

    public synchronized boolean remove(String id) {
        return layers.removeIf(l -> l.id().equals(id));
    }

    public @Nullable LayerSpec get(String id) {
        for (LayerSpec l : layers) {
            if (l.id().equals(id)) {
                return l;
            }
        }
        return null;
    }

    /** In draw order (bottom first). */
    public List<LayerSpec> inDrawOrder() {
        return List.copyOf(layers);
    }

    private void sort() {
        List<LayerSpec> sorted = new ArrayList<>(layers);
        sorted.sort(Comparator.comparingInt(LayerSpec::order)); // stable: equal orders keep insertion order
        layers.clear();
        layers.addAll(sorted);
    }
}
