package org.stagecraft.replay.fields;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.OptionalDouble;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;

/**
 * A number picked out of a decoded body, for plots and analysis. The text is a dotted path of
 * Player's field names with list indexes — {@code pos.px}, {@code ranges[3]}, {@code poses[2].px} —
 * or an aggregate over a list: {@code min(ranges)}, {@code max(ranges)}, {@code mean(ranges)},
 * {@code sum(ranges)}, {@code count(ranges)}. {@code [*]} takes every element, e.g.
 * {@code max(poses[*].px)}. A path that does not fit a body evaluates to nothing rather than failing,
 * since one plot series may see several kinds of message.
 */
public final class FieldPath {
    /** What to do with the numbers a path finds. */
    public enum Aggregate {
        NONE, MIN, MAX, MEAN, SUM, COUNT
    }

    private static final Pattern FUNCTION = Pattern.compile("\\s*(min|max|mean|sum|count)\\s*\\(\\s*(.*?)\\s*\\)\\s*");
    private static final Pattern SEGMENT = Pattern.compile("([A-Za-z_][A-Za-z0-9_]*)((?:\\[(?:\\d+|\\*)\\])*)");
    private static final Pattern INDEX = Pattern.compile("\\[(\\d+|\\*)\\]");
    private static final int ANY = -1;

    private record Step(String name, int[] indexes) {
    }

    private final String text;
    private final Aggregate aggregate;
    private final List<Step> steps;

    private FieldPath(String text, Aggregate aggregate, List<Step> steps) {
        this.text = text;
        this.aggregate = aggregate;
        this.steps = steps;
    }

    /** @throws IllegalArgumentException saying what is wrong with the text and where */
    public static FieldPath parse(String text) {
        if (text == null || text.isBlank()) {
            throw new IllegalArgumentException("empty field path");
        }
        Aggregate aggregate = Aggregate.NONE;
        String path = text.trim();
        Matcher fn = FUNCTION.matcher(text);
        if (fn.matches()) {
            aggregate = Aggregate.valueOf(fn.group(1).toUpperCase(Locale.ROOT));
            path = fn.group(2);
        }
        List<Step> steps = new ArrayList<>();
        int pos = 0;
        for (String seg : path.split("\\.", -1)) {
            Matcher m = SEGMENT.matcher(seg);
            if (!m.matches()) {
                throw new IllegalArgumentException("field path \"" + text + "\": \"" + seg + "\" at character "
                        + (pos + 1) + " is not a field name with optional [index]");
            }
            List<Integer> idx = new ArrayList<>();
            Matcher im = INDEX.matcher(m.group(2));
            while (im.find()) {
                idx.add(im.group(1).equals("*") ? ANY : Integer.parseInt(im.group(1)));
            }
            steps.add(new Step(m.group(1), idx.stream().mapToInt(Integer::intValue).toArray()));
            pos += seg.length() + 1;
        }
        if (aggregate == Aggregate.NONE && steps.stream().anyMatch(s -> contains(s.indexes(), ANY))) {
            throw new IllegalArgumentException("field path \"" + text
                    + "\": [*] takes many values; wrap it in min(), max(), mean(), sum() or count()");
        }
        return new FieldPath(text.trim(), aggregate, List.copyOf(steps));
    }

    private static boolean contains(int[] a, int v) {
        for (int x : a) {
            if (x == v) {
                return true;
            }
        }
        return false;
    }

    public Aggregate aggregate() {
        return aggregate;
    }

    /** The field names along the path, e.g. [pos, px] for {@code pos.px}. */
    public List<String> names() {
        return steps.stream().map(Step::name).toList();
    }

    /** The last field name, e.g. "ranges" for {@code min(ranges)}. */
    public String lastName() {
        return steps.get(steps.size() - 1).name();
    }

    /**
     * Every number the path reaches in {@code root}, ignoring the aggregate: the field itself, or the
     * numeric elements of the lists it names ({@code bumpers}, {@code poses[*].px}); empty when the body
     * has no such field.
     */
    public double[] numbers(Field root) {
        List<Field> found = new ArrayList<>();
        resolve(root, 0, found);
        List<Double> values = new ArrayList<>();
        for (Field f : found) {
            numbers(f, values);
        }
        return values.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** The number this path picks out of {@code body}; empty when the body has no such numeric field. */
    public OptionalDouble evaluate(MessageBody body) {
        return evaluate(FieldTree.of(body));
    }

    /** As {@link #evaluate(MessageBody)}, on a tree already built (see {@link FieldTree#of}). */
    public OptionalDouble evaluate(Field root) {
        List<Field> found = new ArrayList<>();
        resolve(root, 0, found);
        if (aggregate == Aggregate.NONE) {
            return found.size() == 1 && found.get(0).kind().numeric() ? OptionalDouble.of(found.get(0).number())
                    : OptionalDouble.empty();
        }
        List<Double> values = new ArrayList<>();
        for (Field f : found) {
            numbers(f, values);
        }
        if (found.isEmpty()) {
            return OptionalDouble.empty();
        }
        return switch (aggregate) {
            case COUNT -> OptionalDouble.of(values.size());
            case SUM -> OptionalDouble.of(values.stream().mapToDouble(Double::doubleValue).sum());
            case MIN -> values.stream().mapToDouble(Double::doubleValue).min();
            case MAX -> values.stream().mapToDouble(Double::doubleValue).max();
            case MEAN -> values.stream().mapToDouble(Double::doubleValue).average();
            case NONE -> throw new AssertionError();
        };
    }

    /** Numbers directly in {@code f}: the field itself, or the numeric elements of a list. */
    private static void numbers(Field f, List<Double> out) {
        if (f.kind().numeric()) {
            out.add(f.number());
        } else if (f.kind() == Field.Kind.LIST) {
            for (Field c : f.children()) {
                if (c.kind().numeric()) {
                    out.add(c.number());
                }
            }
        }
    }

    private void resolve(Field at, int step, List<Field> out) {
        resolve(at, step, out, null, "");
    }

    /**
     * Collects the fields the path reaches; with {@code names} also each one's concrete path
     * ({@code poses[2].px}), built only then: plots evaluate paths on every message and need no names.
     */
    private void resolve(Field at, int step, List<Field> out, @Nullable List<String> names, String path) {
        if (step == steps.size()) {
            out.add(at);
            if (names != null) {
                names.add(path);
            }
            return;
        }
        if (at.kind() != Field.Kind.STRUCT) {
            return;
        }
        Step s = steps.get(step);
        Field f = at.member(s.name());
        if (f != null) {
            index(f, s.indexes(), 0, step, out, names, names == null ? "" : path.isEmpty() ? s.name() : path + "." + s.name());
        }
    }

    private void index(Field f, int[] indexes, int i, int step, List<Field> out, @Nullable List<String> names, String path) {
        if (i == indexes.length) {
            resolve(f, step + 1, out, names, path);
            return;
        }
        if (f.kind() != Field.Kind.LIST) {
            return;
        }
        if (indexes[i] == ANY) {
            for (int k = 0; k < f.children().size(); k++) {
                index(f.children().get(k), indexes, i + 1, step, out, names, names == null ? "" : path + "[" + k + "]");
            }
        } else if (indexes[i] < f.children().size()) {
            index(f.children().get(indexes[i]), indexes, i + 1, step, out, names, names == null ? "" : path + "[" + indexes[i] + "]");
        }
    }

    /**
     * The concrete fields that give this path its value in {@code root}, as paths — what a view marks when
     * a test on the path held (as Wireshark highlights the fields a display filter matched):
     * {@code ranges[3]} for itself; for {@code min(ranges)} and {@code max(ranges)} the element holding the
     * extreme ({@code ranges[147]}, the first of equals); for {@code mean}, {@code sum} and {@code count}
     * every field they read ({@code ranges}: the whole list). Empty when the body has no such field.
     */
    public List<String> decidingFields(Field root) {
        List<Field> found = new ArrayList<>();
        List<String> names = new ArrayList<>();
        resolve(root, 0, found, names, "");
        if (aggregate != Aggregate.MIN && aggregate != Aggregate.MAX) {
            return List.copyOf(names);
        }
        String best = null;
        double bestValue = Double.NaN;
        for (int k = 0; k < found.size(); k++) {
            Field f = found.get(k);
            List<Field> elements = f.kind() == Field.Kind.LIST ? f.children() : List.of(f);
            for (int e = 0; e < elements.size(); e++) {
                Field x = elements.get(e);
                if (!x.kind().numeric()) {
                    continue;
                }
                double v = x.number();
                if (best == null || (aggregate == Aggregate.MIN ? v < bestValue : v > bestValue)) {
                    best = f.kind() == Field.Kind.LIST ? names.get(k) + "[" + e + "]" : names.get(k);
                    bestValue = v;
                }
            }
        }
        return best == null ? List.of() : List.of(best);
    }

    /**
     * The elements of the path's list(s) whose number is non-zero, as paths ({@code bumpers[1]}): what
     * {@code any(bumpers)} found.
     */
    public List<String> nonZeroFields(Field root) {
        List<Field> found = new ArrayList<>();
        List<String> names = new ArrayList<>();
        resolve(root, 0, found, names, "");
        List<String> out = new ArrayList<>();
        for (int k = 0; k < found.size(); k++) {
            Field f = found.get(k);
            if (f.kind() == Field.Kind.LIST) {
                for (int e = 0; e < f.children().size(); e++) {
                    Field x = f.children().get(e);
                    if (x.kind().numeric() && x.number() != 0) {
                        out.add(names.get(k) + "[" + e + "]");
                    }
                }
            } else if (f.kind().numeric() && f.number() != 0) {
                out.add(names.get(k));
            }
        }
        return out;
    }

    /**
     * Paths worth offering for a body in a picker: every numeric field outside lists, and for each
     * list of numbers its minimum, maximum, mean and count (a laser scan's 361 ranges are one choice
     * each, not 361).
     */
    public static List<String> suggestions(MessageBody body) {
        List<String> out = new ArrayList<>();
        for (Field f : FieldTree.of(body).children()) {
            suggest(Objects.requireNonNull(f.name()), f, out); // the body's own fields have names
        }
        return out;
    }

    private static void suggest(String path, Field f, List<String> out) {
        switch (f.kind()) {
            case INTEGER, FLOAT32, FLOAT64 -> out.add(path);
            case STRUCT -> f.children().forEach(c -> suggest(path + "." + c.name(), c, out));
            case LIST -> {
                if (!f.children().isEmpty() && f.children().stream().allMatch(c -> c.kind().numeric())) {
                    for (String fn : List.of("min", "max", "mean", "count")) {
                        out.add(fn + "(" + path + ")");
                    }
                }
            }
            default -> {
                // text and opaque bytes are not plotted
            }
        }
    }

    @Override
    public String toString() {
        return text;
    }
}
