package org.stagecraft.demo.ui;

import org.stagecraft.views.FramePixels;

/**
 * Whether a Robot View drew data, from its pixels: the background, grid and labels are shades of
 * grey, while every data layer (laser blue, sonar green, robots red) has a colour.
 */
final class ViewPixels {
    /** Channels differing by more than this are a colour, not a grey (blending keeps greys grey). */
    private static final int CHROMA = 24;

    private ViewPixels() {
    }

    static int coloured(FramePixels frame) {
        int n = 0;
        for (int row = 0; row < frame.height(); row++) {
            for (int col = 0; col < frame.width(); col++) {
                int rgb = frame.rgb(col, row);
                int r = rgb >> 16 & 0xFF, g = rgb >> 8 & 0xFF, b = rgb & 0xFF;
                if (Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) > CHROMA) {
                    n++;
                }
            }
        }
        return n;
    }
}
