package org.stagecraft.player.json;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.StringWriter;
import java.util.Base64;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;

import com.google.gson.stream.JsonWriter;

/**
 * The one JSON writer keeps both outputs it replaced: the command line's (written through Gson before,
 * so Gson is the oracle here) and the MCAP export's (PlayerJson's own text: null for what JSON lacks,
 * a float32 as the shortest text of that float).
 */
class JsonFieldWriterTest {

    /** A body with every kind of field, including the numbers JSON cannot hold. */
    private static final MessageBody EVERY_KIND = new MessageBody() {
        @Override
        public void encode(org.stagecraft.player.xdr.XdrWriter out) {
            throw new UnsupportedOperationException("only described here");
        }

        @Override
        public void describe(FieldVisitor v) {
            v.integer("count", -4294967296L);
            v.float32("f", 0.1f);
            v.float32("fnan", Float.NaN);
            v.float32("finf", Float.NEGATIVE_INFINITY);
            v.float64("d", 1e10);
            v.float64("dsmall", 5e-324);
            v.float64("dnan", Double.NaN);
            v.float64("dinf", Double.POSITIVE_INFINITY);
            v.text("name", "a\"b\\c\t\b\n\r\f\u0001\u001f\u2028\u2029é<>&=' end");
            v.text("none", null);
            v.opaque("bytes", new byte[] { 0, 1, (byte) 0xff });
            v.beginStruct("pose");
            v.float64("px", -0.0);
            v.endStruct();
            v.beginList("ranges");
            v.float32(null, 1.5f);
            v.float32(null, Float.POSITIVE_INFINITY);
            v.beginStruct(null);
            v.integer("i", 7);
            v.endStruct();
            v.endList();
            v.beginList("empty");
            v.endList();
        }
    };

    @Test
    void losslessIsExactlyWhatTheCommandLineWroteThroughGson() throws IOException {
        assertEquals(throughGson(EVERY_KIND), JsonFieldWriter.object(EVERY_KIND, JsonNumbers.LOSSLESS));
    }

    @Test
    void everyCharacterIsEscapedAsGsonEscapesIt() throws IOException {
        StringBuilder all = new StringBuilder();
        for (char c = 0; c < 0x3000; c++) {
            all.append(c);
        }
        StringWriter text = new StringWriter();
        try (JsonWriter out = new JsonWriter(text)) {
            out.value(all.toString());
        }
        StringBuilder ours = new StringBuilder();
        JsonText.string(ours, all.toString());
        assertEquals(text.toString(), ours.toString());
    }

    @Test
    void schemaWritesNullForWhatJsonLacksAndFloatsAsTheirShortestText() {
        assertEquals("{\"count\":-4294967296,\"f\":0.1,\"fnan\":null,\"finf\":null,\"d\":1.0E10,\"dsmall\":4.9E-324,"
                + "\"dnan\":null,\"dinf\":null,"
                + "\"name\":\"a\\\"b\\\\c\\t\\b\\n\\r\\f\\u0001\\u001f\\u2028\\u2029é<>&=' end\",\"none\":null,"
                + "\"bytes\":\"AAH/\",\"pose\":{\"px\":-0.0},\"ranges\":[1.5,null,{\"i\":7}],\"empty\":[]}",
                JsonFieldWriter.object(EVERY_KIND, JsonNumbers.SCHEMA));
    }

    @Test
    void fieldsContinueAnObjectTheCallerOpened() {
        StringBuilder b = new StringBuilder("{\"header\":{}");
        new JsonFieldWriter(b, JsonNumbers.SCHEMA, true).integer("x", 1);
        assertEquals("{\"header\":{},\"x\":1", b.toString());
    }

    @Test
    void losslessNumbersAreStringsWhereJsonHasNone() {
        assertEquals("\"NaN\"", JsonNumbers.LOSSLESS.text(Double.NaN));
        assertEquals("\"-Infinity\"", JsonNumbers.LOSSLESS.text(Double.NEGATIVE_INFINITY));
        assertEquals("null", JsonNumbers.SCHEMA.text(Double.POSITIVE_INFINITY));
        assertEquals("0.25", JsonNumbers.LOSSLESS.text(0.25));
    }

    /** What the command line's JsonFields did: Gson's JsonWriter, non-finite as strings, floats widened. */
    private static String throughGson(MessageBody body) throws IOException {
        StringWriter text = new StringWriter();
        try (JsonWriter out = new JsonWriter(text)) {
            out.beginObject();
            body.describe(new FieldVisitor() {
                private JsonWriter name(String n) throws IOException {
                    return n == null ? out : out.name(n);
                }

                private void number(double v) throws IOException {
                    if (Double.isNaN(v) || Double.isInfinite(v)) {
                        out.value(Double.toString(v));
                    } else {
                        out.value(v);
                    }
                }

                @Override
                public void integer(String n, long v) {
                    run(() -> name(n).value(v));
                }

                @Override
                public void float32(String n, float v) {
                    float64(n, v);
                }

                @Override
                public void float64(String n, double v) {
                    run(() -> {
                        name(n);
                        number(v);
                        return out;
                    });
                }

                @Override
                public void text(String n, String v) {
                    run(() -> name(n).value(v));
                }

                @Override
                public void opaque(String n, byte[] v) {
                    text(n, Base64.getEncoder().encodeToString(v));
                }

                @Override
                public void beginStruct(String n) {
                    run(() -> name(n).beginObject());
                }

                @Override
                public void endStruct() {
                    run(out::endObject);
                }

                @Override
                public void beginList(String n) {
                    run(() -> name(n).beginArray());
                }

                @Override
                public void endList() {
                    run(out::endArray);
                }
            });
            out.endObject();
        }
        return text.toString();
    }

    private interface Io {
        JsonWriter run() throws IOException;
    }

    private static void run(Io io) {
        try {
            io.run();
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
