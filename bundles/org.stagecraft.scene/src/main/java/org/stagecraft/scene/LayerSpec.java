package org.stagecraft.scene;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.streams.StreamPattern;

/**
 * One visualisation layer of a Robot View: which renderer draws it, which streams feed it (a pattern,
 * wildcards allowed), and how it looks. Layers are drawn in ascending {@code order}, each blended over
 * what is below it with its {@code alpha}.
 *
 * @param id       unique within the view
 * @param rgb      colour as 0xRRGGBB
 * @param alpha    opacity 0..1
 */
public record LayerSpec(String id, String rendererId, String name, StreamPattern pattern, boolean visible, int rgb,
        double alpha, int order) {

    public LayerSpec {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(rendererId, "rendererId");
        Objects.requireNonNull(pattern, "pattern");
        name = name == null || name.isBlank() ? id : name;
        rgb &= 0xFFFFFF;
        alpha = Double.isFinite(alpha) ? Math.max(0, Math.min(1, alpha)) : 1;
    }

    public LayerSpec visible(boolean v) {
        return new LayerSpec(id, rendererId, name, pattern, v, rgb, alpha, order);
    }

    public LayerSpec colour(int newRgb, double newAlpha) {
        return new LayerSpec(id, rendererId, name, pattern, visible, newRgb, newAlpha, order);
    }

    public LayerSpec order(int newOrder) {
        return new LayerSpec(id, rendererId, name, pattern, visible, rgb, alpha, newOrder);
    }

    public LayerSpec pattern(StreamPattern newPattern) {
        return new LayerSpec(id, rendererId, name, newPattern, visible, rgb, alpha, order);
    }

    public float red() {
        return ((rgb >> 16) & 0xFF) / 255f;
    }

    public float green() {
        return ((rgb >> 8) & 0xFF) / 255f;
    }

    public float blue() {
        return (rgb & 0xFF) / 255f;
    }

    /** The layer as string attributes; {@link #fromAttributes} reads them back. */
    public Map<String, String> toAttributes() {
        Map<String, String> a = new LinkedHashMap<>();
        a.put("id", id);
        a.put("renderer", rendererId);
        a.put("name", name);
        a.put("pattern", pattern.toString());
        a.put("visible", Boolean.toString(visible));
        a.put("colour", String.format("#%06X", rgb));
        a.put("alpha", Double.toString(alpha));
        a.put("order", Integer.toString(order));
        return a;
    }

    /** @throws IllegalArgumentException naming the attribute that is missing or malformed */
    public static LayerSpec fromAttributes(Map<String, String> a) {
        String colour = required(a, "colour");
        if (!colour.matches("#[0-9a-fA-F]{6}")) {
            throw new IllegalArgumentException("colour '" + colour + "' is not #RRGGBB");
        }
        try {
            return new LayerSpec(required(a, "id"), required(a, "renderer"), a.get("name"),
                    StreamPattern.parse(required(a, "pattern")), Boolean.parseBoolean(required(a, "visible")),
                    Integer.parseInt(colour.substring(1), 16), Double.parseDouble(required(a, "alpha")),
                    Integer.parseInt(required(a, "order")));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("layer " + a.get("id") + ": " + e.getMessage(), e);
        }
    }

    private static String required(Map<String, String> a, String key) {
        @Nullable String v = a.get(key);
        if (v == null) {
            throw new IllegalArgumentException("layer attribute '" + key + "' is missing");
        }
        return v;
    }
}
