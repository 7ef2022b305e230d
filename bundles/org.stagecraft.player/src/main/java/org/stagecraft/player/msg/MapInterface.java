package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.DATA;
import static org.stagecraft.player.wire.MessageType.REQ;

import java.io.ByteArrayOutputStream;
import java.util.List;
import java.util.zip.DataFormatException;
import java.util.zip.Inflater;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Geometry.Segment;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Interface 42, "map": occupancy grids and vector maps (042_map.def). */
public final class MapInterface {
    public static final int CODE = 42;

    private MapInterface() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "map");
        r.register(CODE, DATA, 1, "INFO", Info::read);
        r.register(CODE, REQ, 1, "GET_INFO", Info::read);
        r.register(CODE, REQ, 2, "GET_DATA", Tile::read);
        r.register(CODE, REQ, 3, "GET_VECTOR", Vector::read);
    }

    /** player_map_info: grid scale [m/cell], size [cells] and the pose of cell (0,0). */
    public record Info(float scale, int width, int height, Pose2d origin) implements MessageBody {
        static Info read(XdrReader r) {
            return new Info(r.float32(), r.uint32(), r.uint32(), Pose2d.read(r));
        }

        @Override
        public void encode(XdrWriter w) {
            w.float32(scale).uint32(width).uint32(height);
            origin.encode(w);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float32("scale", scale);
            Xdr.u32(v, "width", width);
            Xdr.u32(v, "height", height);
            Xdr.struct(v, "origin", origin);
        }
    }

    /**
     * player_map_data: one tile of the grid. Player's map drivers zlib-compress the cells when built
     * with zlib, in which case {@code data} holds the compressed stream; {@link #cells()} gives the
     * cells either way.
     */
    public record Tile(int col, int row, int width, int height, int dataCount, int dataRange, ByteArray data)
            implements MessageBody {
        static Tile read(XdrReader r) {
            return new Tile(r.uint32(), r.uint32(), r.uint32(), r.uint32(), r.uint32(), r.int8(), Xdr.bytes(r));
        }

        /** Number of cells the tile covers, width x height (saturating on absurd sizes). */
        public long cellCount() {
            return Integer.toUnsignedLong(width) * Integer.toUnsignedLong(height);
        }

        /** True when the data is a zlib stream rather than one byte per cell. */
        public boolean compressed() {
            return data.size() != cellCount() && data.size() >= 2 && (data.unsigned(0) & 0x0F) == 8
                    && ((data.unsigned(0) << 8) | data.unsigned(1)) % 31 == 0;
        }

        /**
         * The occupancy of each cell, row by row (-1 free, 0 unknown, +1 occupied, scaled by
         * data_range), inflating the zlib stream if needed and never beyond width x height bytes.
         *
         * @throws DataFormatException if the compressed stream is corrupt or has the wrong length
         */
        public byte[] cells() throws DataFormatException {
            if (!compressed()) {
                return data.toArray();
            }
            long expected = cellCount();
            if (expected > org.stagecraft.player.wire.MessageHeader.MAX_PAYLOAD * 64L) {
                throw new DataFormatException("tile of " + expected + " cells is implausibly large");
            }
            Inflater inflater = new Inflater();
            try {
                inflater.setInput(data.raw());
                ByteArrayOutputStream out = new ByteArrayOutputStream((int) Math.min(expected, 1 << 20));
                byte[] buf = new byte[8192];
                while (!inflater.finished() && out.size() <= expected) {
                    int n = inflater.inflate(buf);
                    if (n == 0 && (inflater.needsInput() || inflater.needsDictionary())) {
                        throw new DataFormatException("zlib stream of map tile ends early");
                    }
                    out.write(buf, 0, n);
                }
                if (out.size() != expected) {
                    throw new DataFormatException("map tile inflates to " + out.size() + " cells, expected " + expected);
                }
                return out.toByteArray();
            } finally {
                inflater.end();
            }
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(col).uint32(row).uint32(width).uint32(height).uint32(dataCount).int8(dataRange);
            Xdr.bytes(w, data);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "col", col);
            Xdr.u32(v, "row", row);
            Xdr.u32(v, "width", width);
            Xdr.u32(v, "height", height);
            Xdr.u32(v, "data_count", dataCount);
            v.integer("data_range", dataRange);
            v.opaque("data", data.toArray());
        }
    }

    /** player_map_data_vector: a map as line segments. */
    public record Vector(float minx, float maxx, float miny, float maxy, int segmentsCount, List<Segment> segments)
            implements MessageBody {
        static Vector read(XdrReader r) {
            return new Vector(r.float32(), r.float32(), r.float32(), r.float32(), r.uint32(),
                    Xdr.structs(r, 32, Segment::read));
        }

        @Override
        public void encode(XdrWriter w) {
            w.float32(minx).float32(maxx).float32(miny).float32(maxy).uint32(segmentsCount);
            Xdr.structs(w, segments);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float32("minx", minx);
            v.float32("maxx", maxx);
            v.float32("miny", miny);
            v.float32("maxy", maxy);
            Xdr.u32(v, "segments_count", segmentsCount);
            Xdr.structs(v, "segments", segments);
        }
    }
}
