package org.stagecraft.foxglove.player;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.json.JsonText;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;

/**
 * A JSON Schema for the JSON {@link PlayerJson} writes for one stream, built from every message of the
 * stream so that each of them validates: one stream can carry several layouts (a NACK with and
 * without a body, lists of different element shapes), so the schemas of its messages are merged
 * into their union. Objects have every member any message had and require those all of them had;
 * list items are the union of every element; integers and floats together are numbers; a float
 * that was NaN or infinite (null in the JSON) adds null; a value that was of different kinds is
 * {@code anyOf} them.
 */
public final class PlayerJsonSchema {
    private PlayerJsonSchema() {
    }

    /** The schema of one value, or of several merged. */
    public static final class Node {
        /**
         * "integer", "number", "null" (a NaN or infinity, which JSON writes as null), "string",
         * "bytes", "object", "array", in the order first met.
         */
        private final Set<String> kinds = new LinkedHashSet<>();
        private final Map<String, Node> properties = new LinkedHashMap<>();
        /** Members every merged object had; null until an object has been merged. */
        private @Nullable Set<String> required;
        /** The union of all list elements seen; null when every list was empty. */
        private @Nullable Node items;

        private static Node of(String kind) {
            Node n = new Node();
            n.kinds.add(kind);
            return n;
        }

        /** Merges {@code other} into this node; returns this. */
        public Node merge(@Nullable Node other) {
            if (other == null) {
                return this;
            }
            kinds.addAll(other.kinds);
            for (Map.Entry<String, Node> e : other.properties.entrySet()) {
                @Nullable Node mine = properties.get(e.getKey());
                if (mine == null) {
                    properties.put(e.getKey(), e.getValue().copy());
                } else {
                    mine.merge(e.getValue());
                }
            }
            if (other.required != null) {
                if (required == null) {
                    required = new LinkedHashSet<>(other.required);
                } else {
                    required.retainAll(other.required);
                }
            }
            if (other.items != null) {
                items = items == null ? other.items.copy() : items.merge(other.items);
            }
            return this;
        }

        private Node copy() {
            return new Node().merge(this);
        }

        private void member(String name, Node value) {
            kinds.add("object");
            if (required == null) {
                required = new LinkedHashSet<>();
            }
            @Nullable Node mine = properties.get(name);
            if (mine == null) {
                properties.put(name, value);
            } else {
                mine.merge(value);
            }
            required.add(name);
        }

        private void element(Node value) {
            items = items == null ? value : items.merge(value);
        }

        private void write(StringBuilder b) {
            List<String> ks = kinds.contains("number") ? kinds.stream().filter(k -> !k.equals("integer")).toList()
                    : List.copyOf(kinds);
            if (ks.size() == 1) {
                writeKind(b, ks.get(0));
                return;
            }
            b.append("{\"anyOf\":[");
            for (int i = 0; i < ks.size(); i++) {
                if (i > 0) {
                    b.append(',');
                }
                writeKind(b, ks.get(i));
            }
            b.append("]}");
        }

        private void writeKind(StringBuilder b, String kind) {
            switch (kind) {
                case "bytes" -> b.append("{\"type\":\"string\",\"contentEncoding\":\"base64\"}");
                case "object" -> {
                    b.append("{\"type\":\"object\",\"properties\":{");
                    int i = 0;
                    for (Map.Entry<String, Node> e : properties.entrySet()) {
                        if (i++ > 0) {
                            b.append(',');
                        }
                        JsonText.string(b, e.getKey());
                        b.append(':');
                        e.getValue().write(b);
                    }
                    b.append("},\"required\":[");
                    i = 0;
                    for (String r : required == null ? Set.<String>of() : required) {
                        if (i++ > 0) {
                            b.append(',');
                        }
                        JsonText.string(b, r);
                    }
                    b.append("]}");
                }
                case "array" -> {
                    b.append("{\"type\":\"array\",\"items\":");
                    if (items == null) {
                        b.append("{}");
                    } else {
                        items.write(b);
                    }
                    b.append('}');
                }
                default -> b.append("{\"type\":\"").append(kind).append("\"}");
            }
        }
    }

    /** The schema of one message: its header and its body's fields. */
    public static Node of(MessageBody body) {
        Node header = Node.of("object");
        header.member("timestamp", Node.of("number"));
        header.member("seq", Node.of("integer"));
        header.member("host", Node.of("integer"));
        header.member("robot", Node.of("integer"));
        Node root = Node.of("object");
        root.member("header", header);
        Builder b = new Builder(root);
        body.describe(b);
        return root;
    }

    /** The schema text for a stream whose messages' schemas were merged into {@code node}. */
    public static String text(String title, Node node) {
        StringBuilder b = new StringBuilder(1024);
        b.append("{\"$schema\":\"https://json-schema.org/draft/2020-12/schema\",\"title\":");
        JsonText.string(b, title);
        b.append(',');
        StringBuilder body = new StringBuilder();
        node.write(body);
        b.append(body, 1, body.length()); // the root object's members follow the title
        return b.toString();
    }

    /** One message's schema, as the body describes its fields. */
    private static final class Builder implements FieldVisitor {
        private final Deque<Node> open = new ArrayDeque<>();
        private final Deque<String> names = new ArrayDeque<>();

        Builder(Node root) {
            open.push(root);
        }

        private void add(@Nullable String name, Node value) {
            Node parent = open.peek();
            if (parent.kinds.contains("array") && parent.properties.isEmpty() && parent.kinds.size() == 1) {
                parent.element(value);
            } else {
                parent.member(Objects.requireNonNull(name), value); // names are null only inside lists
            }
        }

        @Override
        public void integer(@Nullable String name, long value) {
            add(name, Node.of("integer"));
        }

        @Override
        public void float32(@Nullable String name, float value) {
            add(name, Node.of(Float.isFinite(value) ? "number" : "null"));
        }

        @Override
        public void float64(@Nullable String name, double value) {
            add(name, Node.of(Double.isFinite(value) ? "number" : "null"));
        }

        @Override
        public void text(@Nullable String name, String value) {
            add(name, Node.of("string"));
        }

        @Override
        public void opaque(@Nullable String name, byte[] value) {
            add(name, Node.of("bytes"));
        }

        @Override
        public void beginStruct(@Nullable String name) {
            Node n = Node.of("object");
            n.required = new LinkedHashSet<>();
            names.push(name == null ? "" : name);
            open.push(n);
        }

        @Override
        public void endStruct() {
            Node n = open.pop();
            add(names.pop(), n);
        }

        @Override
        public void beginList(@Nullable String name) {
            names.push(name == null ? "" : name);
            open.push(Node.of("array"));
        }

        @Override
        public void endList() {
            Node n = open.pop();
            add(names.pop(), n);
        }
    }
}
