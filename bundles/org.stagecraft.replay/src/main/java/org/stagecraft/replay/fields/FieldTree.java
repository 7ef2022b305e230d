package org.stagecraft.replay.fields;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;

import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;

/** STAND-IN for the lead's FieldTree (replay-ui branch only; replaced by main's on merge). */
public record FieldTree(String name, Kind kind, String value, List<FieldTree> children) {
    public enum Kind {
        STRUCT, LIST, INTEGER, FLOAT, TEXT, OPAQUE
    }

    public static FieldTree of(MessageBody body) {
        Deque<List<FieldTree>> stack = new ArrayDeque<>();
        Deque<String[]> names = new ArrayDeque<>();
        stack.push(new ArrayList<>());
        body.describe(new FieldVisitor() {
            int index() {
                return stack.peek().size();
            }

            String n(String name) {
                return name != null ? name : "[" + index() + "]";
            }

            void leaf(String name, Kind k, String v) {
                stack.peek().add(new FieldTree(n(name), k, v, List.of()));
            }

            public void integer(String name, long value) {
                leaf(name, Kind.INTEGER, Long.toString(value));
            }

            public void float32(String name, float value) {
                leaf(name, Kind.FLOAT, Float.toString(value));
            }

            public void float64(String name, double value) {
                leaf(name, Kind.FLOAT, Double.toString(value));
            }

            public void text(String name, String value) {
                leaf(name, Kind.TEXT, value);
            }

            public void opaque(String name, byte[] value) {
                leaf(name, Kind.OPAQUE, value.length + " bytes");
            }

            public void beginStruct(String name) {
                names.push(new String[] { n(name), "S" });
                stack.push(new ArrayList<>());
            }

            public void endStruct() {
                end();
            }

            public void beginList(String name) {
                names.push(new String[] { n(name), "L" });
                stack.push(new ArrayList<>());
            }

            public void endList() {
                end();
            }

            void end() {
                List<FieldTree> c = stack.pop();
                String[] n = names.pop();
                boolean list = n[1].equals("L");
                stack.peek().add(new FieldTree(n[0], list ? Kind.LIST : Kind.STRUCT, list ? c.size() + " items" : "", List.copyOf(c)));
            }
        });
        return new FieldTree("body", Kind.STRUCT, "", List.copyOf(stack.pop()));
    }
}
