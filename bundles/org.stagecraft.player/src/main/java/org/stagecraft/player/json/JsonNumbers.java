package org.stagecraft.player.json;

/**
 * How numbers are written as JSON text. Finite doubles are always exact (the shortest text that parses
 * back to the same double); what differs between uses is what JSON cannot hold (NaN, infinities) and
 * how a float32 is spelled.
 *
 * @param nonFinite what NaN and the infinities become
 * @param float32 how a float32 is written
 */
public record JsonNumbers(NonFinite nonFinite, Float32 float32) {

    /** What NaN and the infinities, which JSON lacks, become. */
    public enum NonFinite {
        /** {@code null}: for channels whose JSON Schema allows numbers only where a value is known. */
        NULL,
        /** the strings {@code "NaN"}, {@code "Infinity"}, {@code "-Infinity"}: nothing is lost. */
        STRING
    }

    /** How a float32 is written. */
    public enum Float32 {
        /** the shortest text of that float ({@code 0.1}): what a reader expecting float32 reads back. */
        SHORTEST_FLOAT,
        /** the double it widens to ({@code 0.10000000149011612}): the same value read as float or double. */
        AS_DOUBLE
    }

    /** Player's messages on the MCAP export's JSON channels (they have a JSON Schema): null, shortest float. */
    public static final JsonNumbers SCHEMA = new JsonNumbers(NonFinite.NULL, Float32.SHORTEST_FLOAT);

    /** The command line's decoded events: nothing lost, every number read back exactly as a double. */
    public static final JsonNumbers LOSSLESS = new JsonNumbers(NonFinite.STRING, Float32.AS_DOUBLE);

    public JsonNumbers {
        if (nonFinite == null || float32 == null) {
            throw new IllegalArgumentException("JsonNumbers needs both choices");
        }
    }

    /** Appends a double's JSON text. */
    public void appendDouble(StringBuilder b, double v) {
        if (Double.isFinite(v)) {
            b.append(Double.toString(v));
        } else if (nonFinite == NonFinite.NULL) {
            b.append("null");
        } else {
            JsonText.string(b, Double.toString(v));
        }
    }

    /** Appends a float32's JSON text. */
    public void appendFloat(StringBuilder b, float v) {
        if (Float.isFinite(v) && float32 == Float32.SHORTEST_FLOAT) {
            b.append(Float.toString(v));
        } else {
            appendDouble(b, v);
        }
    }

    /** A double's JSON text. */
    public String text(double v) {
        StringBuilder b = new StringBuilder(24);
        appendDouble(b, v);
        return b.toString();
    }
}
