package org.stagecraft.scene;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/**
 * What a Robot View persists across workbench restarts: its layers and its camera, as lists of string
 * attributes. The view writes them into its IMemento (one child per layer, one for the camera); keeping
 * the format here lets it be tested without a workbench.
 */
public record ViewSetup(List<LayerSpec> layers, Map<String, String> camera) {
    /** Format version written with the setup; a reader ignores setups from a newer major version. */
    public static final int VERSION = 1;

    public ViewSetup {
        layers = List.copyOf(layers);
        camera = Map.copyOf(camera);
    }

    /** Reads layers back, skipping (and reporting) any that are malformed so one bad layer loses only itself. */
    public static ViewSetup read(List<Map<String, String>> layerAttributes, Map<String, String> camera,
            Consumer<String> problems) {
        List<LayerSpec> layers = new ArrayList<>();
        for (Map<String, String> a : layerAttributes) {
            try {
                layers.add(LayerSpec.fromAttributes(a));
            } catch (IllegalArgumentException e) {
                problems.accept("Robot View layer skipped: " + e.getMessage());
            }
        }
        return new ViewSetup(layers, camera == null ? Map.of() : camera);
    }

    public List<Map<String, String>> layerAttributes() {
        return layers.stream().map(LayerSpec::toAttributes).toList();
    }
}
