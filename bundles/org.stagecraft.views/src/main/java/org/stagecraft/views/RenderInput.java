package org.stagecraft.views;

import java.util.List;

import org.stagecraft.scene.Camera;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.WorldModel;
import org.stagecraft.streams.StreamMessage;

/**
 * What a renderer gets at the start of a frame.
 *
 * @param latest      the newest message of each stream the layer's pattern matches, in key order
 * @param unseen      every message since the last frame, for renderers whose policy is lossless (else empty)
 * @param dataVersion changes whenever {@code latest} does
 * @param world       robot poses and sensor mounts; {@code world.version()} changes with them
 * @param camera      the view's camera (already centred on a followed robot)
 */
public record RenderInput(LayerSpec layer, List<StreamMessage> latest, List<StreamMessage> unseen, long dataVersion,
        WorldModel world, Camera camera) {
}
