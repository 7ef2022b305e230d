package org.stagecraft.foxglove;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import com.google.gson.Gson;
import org.eclipse.jdt.annotation.Nullable;

/**
 * The JSON Schemas of the Foxglove well-known schemas Stagecraft writes, generated from our own
 * description of their fields (Foxglove's documentation of each message type: names, JSON types,
 * nesting). Foxglove recognises a channel by the schema's name alone; the schema text is what other
 * tools (and the tests) read. The official schema files are not shipped: tests validate every
 * exported message against them where they lie beside the checkout, and check that each
 * description here has the same members and types as its official file.
 */
public final class FoxgloveSchemas {
    public static final String LASER_SCAN = "foxglove.LaserScan";
    public static final String FRAME_TRANSFORM = "foxglove.FrameTransform";
    public static final String POSE_IN_FRAME = "foxglove.PoseInFrame";
    public static final String POSES_IN_FRAME = "foxglove.PosesInFrame";
    public static final String SCENE_UPDATE = "foxglove.SceneUpdate";
    public static final String GRID = "foxglove.Grid";
    public static final String LOG = "foxglove.Log";

    /** Every schema this class describes, by name. */
    public static final List<String> NAMES = List.of(LASER_SCAN, FRAME_TRANSFORM, POSE_IN_FRAME, POSES_IN_FRAME,
            SCENE_UPDATE, GRID, LOG);

    private static final Map<String, String> TEXTS = new LinkedHashMap<>();

    static {
        for (String name : NAMES) {
            TEXTS.put(name, new Gson().toJson(describe(name)));
        }
    }

    private FoxgloveSchemas() {
    }

    /** The JSON Schema text of a schema in {@link #NAMES}. */
    public static String text(String name) {
        @Nullable String t = TEXTS.get(name);
        if (t == null) {
            throw new IllegalArgumentException("no description of the Foxglove schema " + name);
        }
        return t;
    }

    /** A JSON channel of one of these schemas. */
    public static FoxgloveChannel channel(String topic, String schemaName) {
        return FoxgloveChannel.json(topic, schemaName, text(schemaName));
    }

    /** The schema of {@code name} as a JSON object tree (maps and lists), for tests and tools. */
    public static Map<String, Object> describe(String name) {
        Map<String, Object> s = switch (name) {
            case LASER_SCAN -> object("timestamp", time(), "frame_id", string(), "pose", pose(), "start_angle", number(),
                    "end_angle", number(), "ranges", array(number()), "intensities", array(number()));
            case FRAME_TRANSFORM -> object("timestamp", time(), "parent_frame_id", string(), "child_frame_id", string(),
                    "translation", vector3(), "rotation", quaternion());
            case POSE_IN_FRAME -> object("timestamp", time(), "frame_id", string(), "pose", pose());
            case POSES_IN_FRAME -> object("timestamp", time(), "frame_id", string(), "poses", array(pose()));
            case SCENE_UPDATE -> object("deletions", array(object("timestamp", time(), "type", enumeration(0, 1),
                    "id", string())), "entities", array(sceneEntity()));
            case GRID -> object("timestamp", time(), "frame_id", string(), "pose", pose(), "column_count", integer(),
                    "cell_size", object("x", number(), "y", number()), "row_stride", integer(), "cell_stride", integer(),
                    "fields", array(object("name", string(), "offset", integer(), "type",
                            enumeration(0, 1, 2, 3, 4, 5, 6, 7, 8))),
                    "data", bytes());
            case LOG -> object("timestamp", time(), "level", enumeration(0, 1, 2, 3, 4, 5), "message", string(), "name",
                    string(), "file", string(), "line", integer());
            default -> throw new IllegalArgumentException("no description of the Foxglove schema " + name);
        };
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("$schema", "https://json-schema.org/draft/2020-12/schema");
        root.put("title", name);
        root.putAll(s);
        return root;
    }

    private static Map<String, Object> sceneEntity() {
        Map<String, Object> pose = pose();
        Map<String, Object> color = color();
        return object("timestamp", time(), "frame_id", string(), "id", string(), "lifetime", duration(),
                "frame_locked", bool(), "metadata", array(object("key", string(), "value", string())),
                "arrows", array(object("pose", pose, "shaft_length", number(), "shaft_diameter", number(),
                        "head_length", number(), "head_diameter", number(), "color", color)),
                "cubes", array(object("pose", pose, "size", vector3(), "color", color)),
                "spheres", array(object("pose", pose, "size", vector3(), "color", color)),
                "cylinders", array(object("pose", pose, "size", vector3(), "bottom_scale", number(), "top_scale",
                        number(), "color", color)),
                "lines", array(object("type", enumeration(0, 1, 2), "pose", pose, "thickness", number(),
                        "scale_invariant", bool(), "points", array(point3()), "color", color, "colors", array(color),
                        "indices", array(integer()))),
                "triangles", array(object("pose", pose, "points", array(point3()), "color", color, "colors",
                        array(color), "indices", array(integer()))),
                "texts", array(object("pose", pose, "billboard", bool(), "font_size", number(), "scale_invariant",
                        bool(), "color", color, "text", string())),
                "models", array(object("pose", pose, "scale", vector3(), "color", color, "override_color", bool(),
                        "url", string(), "media_type", string(), "data", bytes())));
    }

    private static Map<String, Object> object(Object... namesAndSchemas) {
        Map<String, Object> props = new LinkedHashMap<>();
        for (int i = 0; i < namesAndSchemas.length; i += 2) {
            props.put((String) namesAndSchemas[i], namesAndSchemas[i + 1]);
        }
        Map<String, Object> o = new LinkedHashMap<>();
        o.put("type", "object");
        o.put("properties", props);
        return o;
    }

    private static Map<String, Object> type(String t) {
        return Map.of("type", t);
    }

    private static Map<String, Object> number() {
        return type("number");
    }

    private static Map<String, Object> integer() {
        return type("integer");
    }

    private static Map<String, Object> string() {
        return type("string");
    }

    private static Map<String, Object> bool() {
        return type("boolean");
    }

    private static Map<String, Object> bytes() {
        return Map.of("type", "string", "contentEncoding", "base64");
    }

    private static Map<String, Object> array(Map<String, Object> items) {
        return Map.of("type", "array", "items", items);
    }

    private static Map<String, Object> enumeration(Integer... values) {
        return Map.of("type", "integer", "enum", List.of(values));
    }

    /** Foxglove's time: non-negative seconds and nanoseconds. */
    private static Map<String, Object> time() {
        Map<String, Object> o = object("sec", Map.of("type", "integer", "minimum", 0), "nsec",
                Map.of("type", "integer", "minimum", 0, "maximum", 999_999_999));
        o.put("title", "time");
        return o;
    }

    private static Map<String, Object> duration() {
        Map<String, Object> o = object("sec", integer(), "nsec",
                Map.of("type", "integer", "minimum", 0, "maximum", 999_999_999));
        o.put("title", "duration");
        return o;
    }

    private static Map<String, Object> vector3() {
        return object("x", number(), "y", number(), "z", number());
    }

    private static Map<String, Object> point3() {
        return vector3();
    }

    private static Map<String, Object> quaternion() {
        return object("x", number(), "y", number(), "z", number(), "w", number());
    }

    private static Map<String, Object> pose() {
        return object("position", vector3(), "orientation", quaternion());
    }

    private static Map<String, Object> color() {
        return object("r", number(), "g", number(), "b", number(), "a", number());
    }
}
