package org.stagecraft.scene.shapes;

import java.util.zip.DataFormatException;

import org.stagecraft.player.msg.MapInterface;

/**
 * A map (occupancy grid) as an image: one luminance-alpha texel per cell, occupied dark and opaque, free
 * light and faint, unknown transparent; placed in the world by the map's origin and scale. Tiles (GET_DATA
 * replies) are pasted in where they belong, so a map fetched in pieces fills in as they arrive.
 */
public final class OccupancyImage {
    private final MapInterface.Info info;
    private final byte[] texels; // 2 bytes per cell, row 0 = the row at the origin (bottom)

    public OccupancyImage(MapInterface.Info info) {
        this.info = info;
        if ((long) info.width() * info.height() > 64L * 1024 * 1024) {
            throw new IllegalArgumentException("map of " + info.width() + " x " + info.height() + " cells is too large");
        }
        this.texels = new byte[Math.max(0, info.width() * info.height() * 2)];
    }

    public MapInterface.Info info() {
        return info;
    }

    /** Pastes a GET_DATA tile. @throws DataFormatException if its zlib data is corrupt */
    public void paste(MapInterface.Tile tile) throws DataFormatException {
        byte[] cells = tile.cells();
        for (int r = 0; r < tile.height(); r++) {
            int y = tile.row() + r;
            if (y < 0 || y >= info.height()) {
                continue;
            }
            for (int c = 0; c < tile.width(); c++) {
                int x = tile.col() + c;
                if (x < 0 || x >= info.width()) {
                    continue;
                }
                int v = cells[r * tile.width() + c];
                int at = 2 * (y * info.width() + x);
                texels[at] = (byte) (v > 0 ? 0 : v < 0 ? 255 : 128);
                texels[at + 1] = (byte) (v > 0 ? 255 : v < 0 ? 40 : 0);
            }
        }
    }

    /** Luminance, alpha per cell, row by row from the bottom. */
    public byte[] texels() {
        return texels;
    }

    /** World x of the left edge of the map (the origin is the corner of cell (0,0)). */
    public double left() {
        return info.origin().px();
    }

    public double bottom() {
        return info.origin().py();
    }

    public double right() {
        return left() + info.width() * (double) info.scale();
    }

    public double top() {
        return bottom() + info.height() * (double) info.scale();
    }
}
