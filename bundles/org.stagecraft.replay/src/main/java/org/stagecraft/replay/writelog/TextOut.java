package org.stagecraft.replay.writelog;

/** Builds the payload text of one line: values separated by single spaces. */
final class TextOut {
    private final StringBuilder b;

    TextOut(StringBuilder b) {
        this.b = b;
    }

    private TextOut add(String s) {
        b.append(' ').append(s);
        return this;
    }

    TextOut float32(float v) {
        return add(NumberText.float32(v));
    }

    TextOut float64(double v) {
        return add(NumberText.float64(v));
    }

    TextOut int32(int v) {
        return add(Integer.toString(v));
    }

    TextOut uint32(int v) {
        return add(NumberText.uint32(v));
    }
}
