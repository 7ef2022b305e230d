package org.stagecraft.views.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.stagecraft.views.FramePixels;

/**
 * Issue 24, item 5 (the clipped label): the robot hold's text over the robots fits a narrow Robot View,
 * wrapped into lines, instead of being cut off at the view's edge ("HELD (suspended in th").
 */
class HoldOverlayTest {
    private static final int W = 180, H = 160;
    private static final String TEXT = "HELD (suspended in the debugger)";
    private static GlHarness gl;

    @BeforeAll
    static void shell() {
        gl = new GlHarness(W, H);
    }

    @AfterAll
    static void close() {
        gl.close();
    }

    @Test
    void theHoldTextFitsANarrowViewOnMoreLines() throws Exception {
        RecordedScene rec = new RecordedScene(150);
        rec.camera.viewport(W, H);
        rec.hideAll();
        rec.scene.overlay(TEXT);
        FramePixels f = gl.frame(rec.scene);
        int red = RobotViewWorkbenchTest.HELD_TEXT;
        assertTrue(f.count(red, 3) >= 10, "the text is drawn: " + f.count(red, 3) + " red pixels");
        int rightmost = -1;
        int lines = 0; // runs of rows with red in them, separated by rows without
        boolean previous = false;
        for (int row = 0; row < H; row++) {
            boolean any = false;
            for (int column = 0; column < W; column++) {
                if (FramePixels.close(red, f.rgb(column, row), 3)) {
                    rightmost = Math.max(rightmost, column);
                    any = true;
                }
            }
            lines += any && !previous ? 1 : 0;
            previous = any;
        }
        assertTrue(rightmost < W - 4, "the text ends inside the view, not at its edge: rightmost red column " + rightmost
                + " of " + W);
        assertTrue(lines >= 2, "on more than one line: " + lines);
        rec.scene.overlay(null);
        assertEquals(0, gl.frame(rec.scene).count(red, 3), "no overlay, no text");
    }
}
