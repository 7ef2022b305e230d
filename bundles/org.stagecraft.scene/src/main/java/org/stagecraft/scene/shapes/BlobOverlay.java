package org.stagecraft.scene.shapes;

/**
 * Where the blobfinder's camera image goes in the view: a small inset in the top-right corner, at most a
 * quarter of the view wide, keeping the image's aspect ratio. Blob rectangles are mapped from image pixels
 * (y down) into this inset in window coordinates (y up).
 */
public record BlobOverlay(double left, double bottom, double scale, int imageWidth, int imageHeight) {
    public static final int MARGIN = 8;

    public static BlobOverlay layout(int imageWidth, int imageHeight, int viewWidth, int viewHeight) {
        int iw = Math.max(1, imageWidth), ih = Math.max(1, imageHeight);
        double scale = Math.min(viewWidth / 4.0 / iw, viewHeight / 4.0 / ih);
        double w = iw * scale, h = ih * scale;
        return new BlobOverlay(viewWidth - MARGIN - w, viewHeight - MARGIN - h, scale, iw, ih);
    }

    public double x(double imageX) {
        return left + imageX * scale;
    }

    public double y(double imageY) {
        return bottom + (imageHeight - imageY) * scale;
    }

    public double right() {
        return x(imageWidth);
    }

    public double top() {
        return y(0);
    }
}
