package org.stagecraft.foxglove;

import java.util.Base64;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;

/**
 * Builds the JSON of each Foxglove message the scene writes. Every message carries the capture time
 * as its {@code timestamp}: Foxglove looks transforms up by a message's timestamp, so all of them
 * must be on the same (wall) clock; Player's own header timestamp (Stage's simulation time) stays in
 * Player's decoded channels.
 */
final class FoxgloveMessages {
    /** Log levels of foxglove.Log. */
    static final int INFO = 2, WARNING = 3, ERROR = 4;

    private FoxgloveMessages() {
    }

    static byte[] frameTransform(long t, String parent, String child, double x, double y, double z, double yaw) {
        JsonOut j = new JsonOut().begin().time("timestamp", t).string("parent_frame_id", parent)
                .string("child_frame_id", child);
        j.vector("translation", x, y, z).yaw("rotation", yaw);
        return j.end().bytes();
    }

    static byte[] poseInFrame(long t, String frame, double x, double y, double yaw) {
        return new JsonOut().begin().time("timestamp", t).string("frame_id", frame).pose("pose", x, y, 0, yaw).end()
                .bytes();
    }

    /** @param trail x, y, yaw of each pose, oldest first */
    static byte[] posesInFrame(long t, String frame, List<double[]> trail) {
        JsonOut j = new JsonOut().begin().time("timestamp", t).string("frame_id", frame).beginArray("poses");
        for (double[] p : trail) {
            j.poseElement(p[0], p[1], 0, p[2]);
        }
        return j.endArray().end().bytes();
    }

    /** A planar scan at the origin of {@code frame}, beams equally spaced from start to end angle. */
    static byte[] laserScan(long t, String frame, double startAngle, double endAngle, float @Nullable [] ranges, double @Nullable [] dranges,
            int[] intensities) {
        JsonOut j = new JsonOut().begin().time("timestamp", t).string("frame_id", frame).pose("pose", 0, 0, 0, 0)
                .number("start_angle", startAngle).number("end_angle", endAngle).beginArray("ranges");
        if (ranges != null) {
            for (float r : ranges) {
                j.element(r);
            }
        } else {
            for (double r : dranges) {
                j.element(r);
            }
        }
        j.endArray().beginArray("intensities");
        for (int i : intensities) {
            j.element(i);
        }
        return j.endArray().end().bytes();
    }

    static byte[] log(long t, int level, String name, String message) {
        return new JsonOut().begin().time("timestamp", t).integer("level", level).string("message", message)
                .string("name", name).string("file", "").integer("line", 0).end().bytes();
    }

    /**
     * An occupancy grid: one signed byte per cell, the ROS convention Foxglove's costmap colouring
     * knows (0 free, 100 occupied, -1 unknown), rows from the origin cell upwards.
     */
    static byte[] grid(long t, String frame, double originX, double originY, double originYaw, double cellSize,
            int columns, byte[] cells) {
        JsonOut j = new JsonOut().begin().time("timestamp", t).string("frame_id", frame)
                .pose("pose", originX, originY, 0, originYaw).integer("column_count", columns);
        j.beginObject("cell_size").number("x", cellSize).number("y", cellSize).end();
        j.integer("row_stride", columns).integer("cell_stride", 1).beginArray("fields").beginElement()
                .string("name", "occupancy").integer("offset", 0).integer("type", 2 /* INT8 */).end().endArray();
        return j.string("data", Base64.getEncoder().encodeToString(cells)).end().bytes();
    }

    /** A scene update replacing one entity. */
    static final class Entity {
        private final JsonOut j = new JsonOut();
        private @Nullable String open;
        private final java.util.Set<String> done = new java.util.HashSet<>();

        Entity(long t, String frame, String id) {
            j.begin().beginArray("deletions").endArray().beginArray("entities").beginElement().time("timestamp", t)
                    .string("frame_id", frame).string("id", id).duration("lifetime", 0).bool("frame_locked", true)
                    .beginArray("metadata").endArray();
        }

        private JsonOut in(String primitives) {
            if (!primitives.equals(open)) {
                if (!done.add(primitives)) {
                    // a second array of one kind would be a duplicate JSON member
                    throw new IllegalStateException(primitives + " must be added together, before other primitives");
                }
                if (open != null) {
                    j.endArray();
                }
                j.beginArray(primitives);
                open = primitives;
            }
            return j;
        }

        /** A box centred at (x, y, z), turned by yaw. Primitives of one kind are added one after the other. */
        Entity cube(double x, double y, double z, double yaw, double sx, double sy, double sz, double[] rgba) {
            in("cubes").beginElement().pose("pose", x, y, z, yaw).vector("size", sx, sy, sz)
                    .color("color", rgba[0], rgba[1], rgba[2], rgba[3]).end();
            return this;
        }

        /** Triangles (x, y pairs, three points each) in the plane z = 0. */
        Entity triangles(double[] xy, int count, double[] rgba) {
            in("triangles").beginElement().pose("pose", 0, 0, 0, 0).beginArray("points");
            for (int i = 0; i + 1 < count; i += 2) {
                j.point(xy[i], xy[i + 1], 0);
            }
            j.endArray().color("color", rgba[0], rgba[1], rgba[2], rgba[3]).beginArray("colors").endArray()
                    .beginArray("indices").endArray().end();
            return this;
        }

        Entity text(double x, double y, double z, String text, double[] rgba) {
            in("texts").beginElement().pose("pose", x, y, z, 0).bool("billboard", true).number("font_size", 12)
                    .bool("scale_invariant", true).color("color", rgba[0], rgba[1], rgba[2], rgba[3])
                    .string("text", text).end();
            return this;
        }

        byte[] bytes() {
            if (open != null) {
                j.endArray();
            }
            return j.end().endArray().end().bytes();
        }
    }
}
