package org.stagecraft.replay.writelog;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Bumper;
import org.stagecraft.player.msg.ByteArray;

/**
 * bumper: states (1:1), geometry as data (1:2) and as the geometry reply (4:1): x, y, yaw, length and
 * radius per bumper. Player's writelog writes these; its readlog has no bumper reader and ignores them.
 */
final class BumperText implements PayloadText {

    @Override
    public @Nullable String cannotWrite(int type, int subtype, MessageBody body) {
        if (type == DATA && subtype == 1 && body instanceof Bumper.State) {
            return null;
        }
        if ((type == DATA && subtype == 2 || type == RESP_ACK && subtype == 1) && body instanceof Bumper.Geom) {
            return null;
        }
        return "writelog writes only bumper states and geometry";
    }

    @Override
    public void write(int type, int subtype, MessageBody body, TextOut out) {
        if (body instanceof Bumper.State s) {
            out.uint32(s.bumpers().size());
            for (int i = 0; i < s.bumpers().size(); i++) {
                out.int32(s.bumpers().unsigned(i));
            }
        } else {
            Bumper.Geom g = (Bumper.Geom) body;
            out.uint32(g.bumperDef().size());
            for (Bumper.Define d : g.bumperDef()) {
                TextGeometry.planar(out, d.pose());
                out.float32(d.length()).float32(d.radius());
            }
        }
    }

    @Override
    public MessageBody read(int type, int subtype, Tokens in, LineNote note) throws WritelogSyntaxException {
        if (type == DATA && subtype == 1) {
            int n = in.count("bumpers_count", 1);
            byte[] b = new byte[n];
            for (int i = 0; i < n; i++) {
                b[i] = (byte) in.int32("bumper " + i);
            }
            return new Bumper.State(n, ByteArray.of(b));
        }
        if (type == DATA && subtype == 2 || type == RESP_ACK && subtype == 1) {
            int n = in.count("bumper_def_count", 5);
            List<Bumper.Define> defs = new ArrayList<>(n);
            for (int i = 0; i < n; i++) {
                defs.add(new Bumper.Define(TextGeometry.planar(in), in.float32("length"), in.float32("radius")));
            }
            return new Bumper.Geom(n, defs);
        }
        throw PayloadText.unknown("bumper", type, subtype);
    }
}
