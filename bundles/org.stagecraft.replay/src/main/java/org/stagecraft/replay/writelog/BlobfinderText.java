package org.stagecraft.replay.writelog;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Blobfinder;

/** blobfinder: image size and blobs (1:1): id, colour, area, centre, bounding box and range per blob. */
final class BlobfinderText implements PayloadText {

    @Override
    public @Nullable String cannotWrite(int type, int subtype, MessageBody body) {
        return type == DATA && subtype == 1 && body instanceof Blobfinder.Blobs ? null
                : "writelog writes only blobfinder blobs";
    }

    @Override
    public void write(int type, int subtype, MessageBody body, TextOut out) {
        Blobfinder.Blobs d = (Blobfinder.Blobs) body;
        out.uint32(d.width()).uint32(d.height()).uint32(d.blobs().size());
        for (Blobfinder.Blob b : d.blobs()) {
            out.uint32(b.id()).uint32(b.color()).uint32(b.area()).uint32(b.x()).uint32(b.y()).uint32(b.left())
                    .uint32(b.right()).uint32(b.top()).uint32(b.bottom()).float32(b.range());
        }
    }

    @Override
    public MessageBody read(int type, int subtype, Tokens in, LineNote note) throws WritelogSyntaxException {
        if (type != DATA) {
            throw PayloadText.unknown("blobfinder", type, subtype);
        }
        int width = in.int32("width");
        int height = in.int32("height");
        int n = in.count("blobs_count", 10);
        List<Blobfinder.Blob> blobs = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            blobs.add(new Blobfinder.Blob(in.int32("id"), in.int32("color"), in.int32("area"), in.int32("x"),
                    in.int32("y"), in.int32("left"), in.int32("right"), in.int32("top"), in.int32("bottom"),
                    in.float32("range")));
        }
        return new Blobfinder.Blobs(width, height, n, blobs);
    }
}
