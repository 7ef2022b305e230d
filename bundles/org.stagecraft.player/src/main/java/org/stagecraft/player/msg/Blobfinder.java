package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.DATA;
import static org.stagecraft.player.wire.MessageType.REQ;

import java.util.List;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Interface 7, "blobfinder": colour blobs in a camera image (007_blobfinder.def). */
public final class Blobfinder {
    public static final int CODE = 7;

    private Blobfinder() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "blobfinder");
        r.register(CODE, DATA, 1, "BLOBS", Blobs::read);
        r.register(CODE, REQ, 1, "SET_COLOR", ColorConfig::read);
        r.register(CODE, REQ, 2, "SET_IMAGER_PARAMS", ImagerConfig::read);
        r.register(CODE, REQ, 3, "GET_COLOR", ColorConfig::read);
    }

    /** player_blobfinder_blob: pixels in the image frame, colour as 0x00RRGGBB. */
    public record Blob(int id, int color, int area, int x, int y, int left, int right, int top, int bottom,
            float range) implements MessageBody {
        static final int XDR_SIZE = 40;

        static Blob read(XdrReader r) {
            return new Blob(r.uint32(), r.uint32(), r.uint32(), r.uint32(), r.uint32(), r.uint32(), r.uint32(),
                    r.uint32(), r.uint32(), r.float32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(id).uint32(color).uint32(area).uint32(x).uint32(y).uint32(left).uint32(right).uint32(top)
                    .uint32(bottom).float32(range);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "id", id);
            Xdr.u32(v, "color", color);
            Xdr.u32(v, "area", area);
            Xdr.u32(v, "x", x);
            Xdr.u32(v, "y", y);
            Xdr.u32(v, "left", left);
            Xdr.u32(v, "right", right);
            Xdr.u32(v, "top", top);
            Xdr.u32(v, "bottom", bottom);
            v.float32("range", range);
        }
    }

    /** player_blobfinder_data: image size and the detected blobs. */
    public record Blobs(int width, int height, int blobsCount, List<Blob> blobs) implements MessageBody {
        static Blobs read(XdrReader r) {
            return new Blobs(r.uint32(), r.uint32(), r.uint32(), Xdr.structs(r, Blob.XDR_SIZE, Blob::read));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(width).uint32(height).uint32(blobsCount);
            Xdr.structs(w, blobs);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "width", width);
            Xdr.u32(v, "height", height);
            Xdr.u32(v, "blobs_count", blobsCount);
            Xdr.structs(v, "blobs", blobs);
        }
    }

    /** player_blobfinder_color_config. */
    public record ColorConfig(int channel, int rmin, int rmax, int gmin, int gmax, int bmin, int bmax)
            implements MessageBody {
        static ColorConfig read(XdrReader r) {
            return new ColorConfig(r.uint32(), r.uint32(), r.uint32(), r.uint32(), r.uint32(), r.uint32(), r.uint32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(channel).uint32(rmin).uint32(rmax).uint32(gmin).uint32(gmax).uint32(bmin).uint32(bmax);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "channel", channel);
            Xdr.u32(v, "rmin", rmin);
            Xdr.u32(v, "rmax", rmax);
            Xdr.u32(v, "gmin", gmin);
            Xdr.u32(v, "gmax", gmax);
            Xdr.u32(v, "bmin", bmin);
            Xdr.u32(v, "bmax", bmax);
        }
    }

    /** player_blobfinder_imager_config; -1 leaves a value unchanged. */
    public record ImagerConfig(int brightness, int contrast, int colormode, int autogain) implements MessageBody {
        static ImagerConfig read(XdrReader r) {
            return new ImagerConfig(r.int32(), r.int32(), r.int32(), r.int32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.int32(brightness).int32(contrast).int32(colormode).int32(autogain);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.integer("brightness", brightness);
            v.integer("contrast", contrast);
            v.integer("colormode", colormode);
            v.integer("autogain", autogain);
        }
    }
}
