package org.stagecraft.views.renderers;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.DataFormatException;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.MapInterface;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.Payloads;
import org.stagecraft.scene.shapes.OccupancyImage;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.RenderInput;
import org.stagecraft.views.StreamRenderer;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2;

/**
 * The occupancy grid of a map device (map GET_INFO and GET_DATA replies, zlib-compressed tiles inflated by
 * the codec) as one texture: occupied cells dark, free cells faint, unknown transparent. The map arrives
 * once and in pieces, so this renderer subscribes lossless and pastes every tile it is given.
 */
public class MapRenderer extends StreamRenderer {
    private @Nullable OccupancyImage image;
    private final List<MapInterface.Tile> early = new ArrayList<>();
    private int texture;
    private boolean uploaded;
    private @Nullable String problem;

    @Override
    public DeliveryPolicy deliveryPolicy() {
        return DeliveryPolicy.lossless(256);
    }

    @Override
    protected boolean acquire(RenderInput in) {
        boolean changed = false;
        for (StreamMessage m : in.unseen()) {
            MessageBody b = Payloads.body(m);
            if (b instanceof MapInterface.Info info && info.width() > 0 && info.height() > 0) {
                image = new OccupancyImage(info);
                for (MapInterface.Tile t : early) {
                    paste(t);
                }
                early.clear();
                changed = true;
            } else if (b instanceof MapInterface.Tile t) {
                if (image == null) {
                    early.add(t); // GET_DATA before GET_INFO: keep it until the map's size is known
                } else {
                    paste(t);
                    changed = true;
                }
            }
        }
        return changed;
    }

    private void paste(MapInterface.Tile t) {
        try {
            image.paste(t);
        } catch (DataFormatException e) {
            problem = e.getMessage();
        }
    }

    /** Why the last tile could not be shown, or null. */
    public @Nullable String problem() {
        return problem;
    }

    @Override
    protected void refresh(GL2 gl) {
        if (image == null) {
            return;
        }
        if (texture == 0) {
            int[] ids = new int[1];
            gl.glGenTextures(1, ids, 0);
            texture = ids[0];
        }
        gl.glBindTexture(GL.GL_TEXTURE_2D, texture);
        gl.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 1);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_S, GL.GL_CLAMP_TO_EDGE);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_T, GL.GL_CLAMP_TO_EDGE);
        MapInterface.Info info = image.info();
        gl.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_LUMINANCE_ALPHA, info.width(), info.height(), 0,
                GL.GL_LUMINANCE_ALPHA, GL.GL_UNSIGNED_BYTE, ByteBuffer.wrap(image.texels()));
        gl.glBindTexture(GL.GL_TEXTURE_2D, 0);
        uploaded = true;
    }

    @Override
    protected void render(GL2 gl, LayerSpec layer, RenderInput in) {
        if (!uploaded) {
            return;
        }
        gl.glEnable(GL.GL_TEXTURE_2D);
        gl.glBindTexture(GL.GL_TEXTURE_2D, texture);
        gl.glTexEnvi(GL2.GL_TEXTURE_ENV, GL2.GL_TEXTURE_ENV_MODE, GL2.GL_MODULATE);
        gl.glColor4f(1, 1, 1, (float) layer.alpha());
        gl.glBegin(GL2.GL_QUADS);
        gl.glTexCoord2f(0, 0);
        gl.glVertex2d(image.left(), image.bottom());
        gl.glTexCoord2f(1, 0);
        gl.glVertex2d(image.right(), image.bottom());
        gl.glTexCoord2f(1, 1);
        gl.glVertex2d(image.right(), image.top());
        gl.glTexCoord2f(0, 1);
        gl.glVertex2d(image.left(), image.top());
        gl.glEnd();
        gl.glBindTexture(GL.GL_TEXTURE_2D, 0);
        gl.glDisable(GL.GL_TEXTURE_2D);
    }

    @Override
    protected void dispose(GL2 gl) {
        if (texture != 0) {
            gl.glDeleteTextures(1, new int[] { texture }, 0);
            texture = 0;
        }
    }
}
