package org.stagecraft.replay.writelog;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Position2d;

/** position2d: odometry state (1:1) and the geometry reply (4:1). */
final class PositionText implements PayloadText {

    @Override
    public @Nullable String cannotWrite(int type, int subtype, MessageBody body) {
        if (type == DATA && subtype == 1 && body instanceof Position2d.State) {
            return null;
        }
        if (type == RESP_ACK && subtype == 1 && body instanceof DeviceGeom) {
            return null;
        }
        return "writelog writes only position2d state and geometry";
    }

    @Override
    public void write(int type, int subtype, MessageBody body, TextOut out) {
        if (body instanceof Position2d.State s) {
            TextGeometry.pose2d(out, s.pos());
            TextGeometry.pose2d(out, s.vel());
            out.int32(s.stall());
        } else {
            TextGeometry.planarGeom(out, (DeviceGeom) body);
        }
    }

    @Override
    public MessageBody read(int type, int subtype, Tokens in, LineNote note) throws WritelogSyntaxException {
        if (type == DATA && subtype == 1) {
            return new Position2d.State(TextGeometry.pose2d(in), TextGeometry.pose2d(in), in.int32("stall") & 0xFF);
        }
        if (type == RESP_ACK && subtype == 1) {
            return TextGeometry.planarGeom(in);
        }
        throw PayloadText.unknown("position2d", type, subtype);
    }
}
