package org.stagecraft.replay.fields;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;

/**
 * A test over one decoded message, written in the field language of the Plot view: field paths
 * ({@link FieldPath}: {@code pos.px}, {@code ranges[3]}, {@code min(ranges)}, {@code count(poses)}),
 * numbers with optional units ({@code 0.3}, {@code 30 cm}, {@code 15 deg}, {@code 0.2 m/s}; see
 * {@link Unit}), arithmetic ({@code + - * /}, {@code abs(...)}), comparisons ({@code < <= > >= == !=}),
 * {@code any(path)} / {@code all(path)} (some / every number there is non-zero, e.g. {@code any(bumpers)})
 * and {@code and}, {@code or}, {@code not} (also {@code && || !}) with parentheses.
 *
 * <p>Numbers are compared in Player's SI units: a unit converts the number written before the test runs,
 * and a unit of another dimension than the field's (an angle against a range) is refused when the text is
 * read. A path that a message does not have gives no value, and a comparison without a value is false.
 * A number written beside a float32 value (most ranges) is compared at float32 precision, so
 * {@code ranges[1] == 0.287} holds for the 0.287 Player sent.
 * Thread-safe once parsed.
 */
public final class Condition {

    /**
     * The outcome of a test, with why for people ({@code "min(ranges) = 0.287 m < 0.3 m"}) and the concrete
     * fields that decided it when it holds ({@link FieldPath#decidingFields}: {@code ranges[147]}; for
     * {@code any(bumpers)} the pressed {@code bumpers[i]}), for a view to mark.
     */
    public record Verdict(boolean holds, String explanation, List<String> decidingFields) {
        public Verdict {
            decidingFields = List.copyOf(decidingFields);
        }
    }

    private final String text;
    private final Node root;

    private Condition(String text, Node root) {
        this.text = text;
        this.root = root;
    }

    /** @throws ConditionException saying what is wrong and at which character */
    public static Condition parse(String text) {
        String t = text == null ? "" : text;
        Parser p = new Parser(t);
        Node n = p.parse();
        return new Condition(t.strip(), n);
    }

    public String text() {
        return text;
    }

    public Verdict test(MessageBody body) {
        return test(FieldTree.of(body));
    }

    public Verdict test(Field root) {
        Eval e = new Eval(root);
        boolean holds = e.truth(this.root);
        if (!holds) {
            return new Verdict(false, "", List.of());
        }
        List<String> deciding = new ArrayList<>();
        e.deciding(this.root, deciding);
        return new Verdict(true, e.explain(this.root), deciding.stream().distinct().toList());
    }

    @Override
    public String toString() {
        return text;
    }

    // ---- the tree -------------------------------------------------------------------------------

    private sealed interface Node permits Literal, Path, AnyAll, Abs, Negate, Arith, Compare, Logic, Not, Bool {
    }

    /** A number as written, already in SI units. */
    private record Literal(double value, String written, @Nullable Dimension dimension) implements Node {
    }

    private record Path(FieldPath path, String written, @Nullable Dimension dimension) implements Node {
    }

    private record AnyAll(FieldPath path, boolean all, String written) implements Node {
    }

    private record Abs(Node of, String written) implements Node {
    }

    private record Negate(Node of, String written) implements Node {
    }

    private record Arith(char op, Node left, Node right, String written) implements Node {
    }

    private record Compare(String op, Node left, Node right) implements Node {
    }

    private record Logic(boolean and, Node left, Node right) implements Node {
    }

    private record Not(Node of) implements Node {
    }

    private record Bool(boolean value) implements Node {
    }

    private static boolean isTest(Node n) {
        return n instanceof Compare || n instanceof Logic || n instanceof Not || n instanceof Bool || n instanceof AnyAll;
    }

    private static @Nullable Dimension dimension(Node n) {
        return switch (n) {
            case Literal l -> l.dimension();
            case Path p -> p.dimension();
            case Abs a -> dimension(a.of());
            case Negate m -> dimension(m.of());
            case Arith a -> a.op() == '+' || a.op() == '-' ? (dimension(a.left()) != null ? dimension(a.left()) : dimension(a.right())) : null;
            default -> null;
        };
    }

    private static String written(Node n) {
        return switch (n) {
            case Literal l -> l.written();
            case Path p -> p.written();
            case AnyAll a -> a.written();
            case Abs a -> a.written();
            case Negate m -> m.written();
            case Arith a -> a.written();
            case Compare c -> written(c.left()) + " " + c.op() + " " + written(c.right());
            case Logic l -> written(l.left()) + (l.and() ? " and " : " or ") + written(l.right());
            case Not x -> "not " + written(x.of());
            case Bool b -> Boolean.toString(b.value());
        };
    }

    // ---- evaluation -----------------------------------------------------------------------------

    private static final class Eval {
        private final Field root;

        Eval(Field root) {
            this.root = root;
        }

        /** NaN when a path has no value in this message. */
        double number(Node n) {
            return switch (n) {
                case Literal l -> l.value();
                case Path p -> {
                    var v = p.path().evaluate(root);
                    yield v.isPresent() ? v.getAsDouble() : Double.NaN;
                }
                case Abs a -> Math.abs(number(a.of()));
                case Negate m -> -number(m.of());
                case Arith a -> {
                    double l = number(a.left());
                    double r = number(a.right());
                    yield switch (a.op()) {
                        case '+' -> l + r;
                        case '-' -> l - r;
                        case '*' -> l * r;
                        default -> l / r;
                    };
                }
                default -> throw new IllegalStateException("not a number: " + written(n));
            };
        }

        boolean truth(Node n) {
            return switch (n) {
                case Bool b -> b.value();
                case Not x -> !truth(x.of());
                case Logic l -> l.and() ? truth(l.left()) && truth(l.right()) : truth(l.left()) || truth(l.right());
                case AnyAll a -> {
                    double[] v = a.path().numbers(root);
                    if (v.length == 0) {
                        yield false;
                    }
                    boolean any = false;
                    boolean all = true;
                    for (double d : v) {
                        any |= d != 0;
                        all &= d != 0;
                    }
                    yield a.all() ? all : any;
                }
                case Compare c -> {
                    double l = number(c.left());
                    double r = number(c.right());
                    if (Double.isNaN(l) || Double.isNaN(r)) {
                        yield false; // a message without the field does not satisfy a test on it
                    }
                    // Player sends most ranges as float32: 0.287 written by the user is compared with 0.287f
                    if (c.right() instanceof Literal && isFloat32(l)) {
                        r = (float) r;
                    } else if (c.left() instanceof Literal && isFloat32(r)) {
                        l = (float) l;
                    }
                    yield switch (c.op()) {
                        case "<" -> l < r;
                        case "<=" -> l <= r;
                        case ">" -> l > r;
                        case ">=" -> l >= r;
                        case "==" -> l == r;
                        default -> l != r;
                    };
                }
                default -> throw new IllegalStateException("not a test: " + written(n));
            };
        }

        private static boolean isFloat32(double v) {
            return (double) (float) v == v;
        }

        /** Why a test that holds holds: the comparisons that decided it, with the values seen. */
        String explain(Node n) {
            return switch (n) {
                case Compare c -> show(c.left()) + " " + c.op() + " " + show(c.right());
                case Logic l when l.and() -> explain(l.left()) + " and " + explain(l.right());
                case Logic l -> truth(l.left()) ? explain(l.left()) : explain(l.right());
                case AnyAll a -> a.written() + " (" + countNonZero(a) + " of " + a.path().numbers(root).length + " non-zero)";
                default -> written(n);
            };
        }

        /** The fields the comparisons that {@link #explain} names read (see {@link Verdict#decidingFields}). */
        void deciding(Node n, List<String> out) {
            switch (n) {
                case Compare c -> {
                    deciding(c.left(), out);
                    deciding(c.right(), out);
                }
                case Logic l when l.and() -> {
                    deciding(l.left(), out);
                    deciding(l.right(), out);
                }
                case Logic l -> deciding(truth(l.left()) ? l.left() : l.right(), out);
                case AnyAll a -> out.addAll(a.all() ? a.path().decidingFields(root) : a.path().nonZeroFields(root));
                case Path p -> out.addAll(p.path().decidingFields(root));
                case Abs a -> deciding(a.of(), out);
                case Negate m -> deciding(m.of(), out);
                case Arith a -> {
                    deciding(a.left(), out);
                    deciding(a.right(), out);
                }
                default -> {
                    // literals, true/false and "not" decide through no field of the message
                }
            }
        }

        private int countNonZero(AnyAll a) {
            int k = 0;
            for (double d : a.path().numbers(root)) {
                k += d != 0 ? 1 : 0;
            }
            return k;
        }

        /** A literal as written; anything computed as "text = value unit". */
        private String show(Node n) {
            if (n instanceof Literal l) {
                return l.written();
            }
            Dimension d = dimension(n);
            return written(n) + " = " + format(number(n)) + (d == null ? "" : " " + d.baseUnit());
        }
    }

    /** Four significant digits, no exponent for everyday magnitudes: 0.287, 1.571, 12.35. */
    static String format(double v) {
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            return Double.toString(v);
        }
        if (v == 0) {
            return "0";
        }
        BigDecimal b = new BigDecimal(v).round(new MathContext(4)).stripTrailingZeros();
        return Math.abs(v) >= 1e-4 && Math.abs(v) < 1e7 ? b.toPlainString() : b.toString();
    }

    // ---- reading --------------------------------------------------------------------------------

    private enum Kind {
        NUMBER, NAME, OP, OPEN, CLOSE, END
    }

    private record Token(Kind kind, String text, int pos, @Nullable Unit unit, int end) {
    }

    private static final Pattern NUMBER = Pattern.compile("(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");
    private static final Pattern UNIT = Pattern.compile(
            "\\s*(m/s|cm/s|mm/s|rad/s|deg/s|°/s|cm|mm|m|rad|degrees|degree|deg|°|ms|s)(?![A-Za-z0-9_])");
    private static final Pattern NAME = Pattern.compile(
            "[A-Za-z_][A-Za-z0-9_]*(\\[\\s*(\\d+|\\*)\\s*\\])*(\\.[A-Za-z_][A-Za-z0-9_]*(\\[\\s*(\\d+|\\*)\\s*\\])*)*");
    private static final List<String> OPS = List.of("<=", ">=", "==", "!=", "&&", "||", "<", ">", "=", "!", "+", "-", "*", "/");
    private static final List<String> AGGREGATES = List.of("min", "max", "mean", "sum", "count");

    private static final class Parser {
        private final String text;
        private final List<Token> tokens = new ArrayList<>();
        private int at;

        Parser(String text) {
            this.text = text;
            lex();
        }

        private void lex() {
            int i = 0;
            while (i < text.length()) {
                char c = text.charAt(i);
                if (Character.isWhitespace(c)) {
                    i++;
                    continue;
                }
                Matcher num = NUMBER.matcher(text).region(i, text.length());
                if (Character.isDigit(c) || c == '.' && num.lookingAt()) {
                    if (!num.lookingAt()) {
                        throw error(i, "'" + c + "' does not start a number or a field");
                    }
                    int end = num.end();
                    Unit unit = null;
                    Matcher u = UNIT.matcher(text).region(end, text.length());
                    if (u.lookingAt()) {
                        unit = Unit.of(u.group(1));
                        end = u.end();
                    } else {
                        int w = end;
                        while (w < text.length() && Character.isWhitespace(text.charAt(w))) {
                            w++;
                        }
                        Matcher word = NAME.matcher(text).region(w, text.length());
                        if (word.lookingAt() && !List.of("and", "or", "not").contains(word.group().toLowerCase(Locale.ROOT))) {
                            throw error(w, "'" + word.group() + "' after a number is not a unit (units: " + Unit.symbols() + ")");
                        }
                    }
                    tokens.add(new Token(Kind.NUMBER, num.group(), i, unit, end));
                    i = end;
                    continue;
                }
                if (Character.isLetter(c) || c == '_') {
                    Matcher m = NAME.matcher(text).region(i, text.length());
                    m.lookingAt();
                    tokens.add(new Token(Kind.NAME, m.group().replaceAll("\\s+", ""), i, null, m.end()));
                    i = m.end();
                    continue;
                }
                if (c == '(' || c == ')') {
                    tokens.add(new Token(c == '(' ? Kind.OPEN : Kind.CLOSE, String.valueOf(c), i, null, i + 1));
                    i++;
                    continue;
                }
                String op = null;
                for (String o : OPS) {
                    if (text.startsWith(o, i)) {
                        op = o;
                        break;
                    }
                }
                if (op == null) {
                    throw error(i, "'" + c + "' is not part of a condition (fields, numbers, < <= > >= == !=, + - * /, and, or, not, parentheses)");
                }
                tokens.add(new Token(Kind.OP, op, i, null, i + op.length()));
                i += op.length();
            }
            tokens.add(new Token(Kind.END, "", text.length(), null, text.length()));
        }

        Node parse() {
            if (tokens.size() == 1) {
                throw error(0, "the condition is empty: write a test such as min(ranges) < 0.3");
            }
            int start = peek().pos();
            Node n = or();
            if (peek().kind() != Kind.END) {
                Token t = peek();
                throw error(t.pos(), "unexpected '" + t.text() + "'" + (t.kind() == Kind.CLOSE ? " (no '(' to close)" : ""));
            }
            if (!isTest(n)) {
                throw error(start, "'" + written(n) + "' is a number, not a test: compare it, e.g. " + written(n) + " > 0");
            }
            return n;
        }

        private Token peek() {
            return tokens.get(at);
        }

        private Token next() {
            return tokens.get(at++);
        }

        private boolean word(String w) {
            Token t = peek();
            return t.kind() == Kind.NAME && t.text().equalsIgnoreCase(w);
        }

        private boolean op(String... ops) {
            Token t = peek();
            if (t.kind() != Kind.OP) {
                return false;
            }
            for (String o : ops) {
                if (t.text().equals(o)) {
                    return true;
                }
            }
            return false;
        }

        private Node or() {
            Node left = and();
            while (word("or") || op("||")) {
                Token t = next();
                Node right = and();
                left = new Logic(false, test(left, t), test(right, t));
            }
            return left;
        }

        private Node and() {
            Node left = not();
            while (word("and") || op("&&")) {
                Token t = next();
                Node right = not();
                left = new Logic(true, test(left, t), test(right, t));
            }
            return left;
        }

        private Node not() {
            if (word("not") || op("!")) {
                Token t = next();
                return new Not(test(not(), t));
            }
            return comparison();
        }

        private Node test(Node n, Token by) {
            if (!isTest(n)) {
                throw error(by.pos(), "'" + by.text() + "' joins tests, but '" + written(n) + "' is a number");
            }
            return n;
        }

        private Node comparison() {
            int leftAt = peek().pos();
            Node left = additive();
            if (op("<", "<=", ">", ">=", "==", "!=", "=")) {
                Token t = next();
                int rightAt = peek().pos();
                Node right = additive();
                number(left, leftAt, t);
                number(right, rightAt, t);
                sameDimension(left, right, rightAt);
                if (op("<", "<=", ">", ">=", "==", "!=", "=")) {
                    throw error(peek().pos(), "comparisons do not chain: join them with 'and'");
                }
                return new Compare(t.text().equals("=") ? "==" : t.text(), left, right);
            }
            return left;
        }

        private void number(Node n, int pos, Token by) {
            if (isTest(n)) {
                throw error(pos, "'" + by.text() + "' compares numbers, but '" + written(n) + "' is a test");
            }
        }

        private void sameDimension(Node left, Node right, int pos) {
            Dimension l = dimension(left);
            Dimension r = dimension(right);
            if (l != null && r != null && l != r) {
                throw error(pos, "'" + written(right) + "' is " + r.described() + ", but '" + written(left) + "' is "
                        + l.described() + " (in " + l.baseUnit() + ")");
            }
        }

        private Node additive() {
            int start = peek().pos();
            Node left = multiplicative();
            while (op("+", "-")) {
                Token t = next();
                int rightAt = peek().pos();
                Node right = multiplicative();
                number(left, start, t);
                number(right, rightAt, t);
                sameDimension(left, right, rightAt);
                left = new Arith(t.text().charAt(0), left, right, text.substring(start, tokens.get(at - 1).end()).strip());
            }
            return left;
        }

        private Node multiplicative() {
            int start = peek().pos();
            Node left = unary();
            while (op("*", "/")) {
                Token t = next();
                int rightAt = peek().pos();
                Node right = unary();
                number(left, start, t);
                number(right, rightAt, t);
                left = new Arith(t.text().charAt(0), left, right, text.substring(start, tokens.get(at - 1).end()).strip());
            }
            return left;
        }

        private Node unary() {
            if (op("-")) {
                Token t = next();
                Node of = unary();
                number(of, t.end(), t);
                return new Negate(of, text.substring(t.pos(), tokens.get(at - 1).end()).strip());
            }
            return primary();
        }

        private Node primary() {
            Token t = next();
            switch (t.kind()) {
                case NUMBER -> {
                    double v = Double.parseDouble(t.text());
                    Unit u = t.unit();
                    String written = text.substring(t.pos(), t.end()).strip();
                    return u == null ? new Literal(v, written, null) : new Literal(u.toBase(v), written, u.dimension());
                }
                case OPEN -> {
                    Node inner = or();
                    expect(Kind.CLOSE, "')' to close the '(' at character " + (t.pos() + 1));
                    return inner;
                }
                case NAME -> {
                    return name(t);
                }
                case END -> throw error(t.pos(), "the condition ends too early: a field or a number is missing");
                default -> throw error(t.pos(), "'" + t.text() + "' where a field or a number was expected");
            }
        }

        private Node name(Token t) {
            String w = t.text().toLowerCase(Locale.ROOT);
            if (w.equals("true") || w.equals("false")) {
                return new Bool(w.equals("true"));
            }
            if (w.equals("and") || w.equals("or") || w.equals("not")) {
                throw error(t.pos(), "'" + t.text() + "' where a field or a number was expected");
            }
            if (peek().kind() != Kind.OPEN) {
                FieldPath p = path(t.text(), t.pos(), false);
                return new Path(p, t.text(), Dimension.ofField(p));
            }
            Token open = next();
            if (w.equals("abs")) {
                int at0 = peek().pos();
                Node of = additive();
                number(of, at0, t);
                expect(Kind.CLOSE, "')' to close abs(");
                return new Abs(of, text.substring(t.pos(), tokens.get(at - 1).end()).strip());
            }
            boolean anyAll = w.equals("any") || w.equals("all");
            if (!anyAll && !AGGREGATES.contains(w)) {
                throw error(t.pos(), "no function is called '" + t.text() + "' (min, max, mean, sum, count, any, all, abs)");
            }
            Token arg = next();
            if (arg.kind() != Kind.NAME) {
                throw error(arg.pos(), w + "() takes a field, e.g. " + w + "(ranges)");
            }
            expect(Kind.CLOSE, "')' to close " + w + "(");
            String written = w + "(" + arg.text() + ")";
            if (anyAll) {
                return new AnyAll(path("count(" + arg.text() + ")", arg.pos(), true), w.equals("all"), written);
            }
            FieldPath p = path(written, open.pos() + 1, true);
            return new Path(p, written, Dimension.ofField(p));
        }

        private FieldPath path(String s, int pos, boolean aggregated) {
            try {
                return FieldPath.parse(s);
            } catch (IllegalArgumentException e) {
                throw error(pos, aggregated ? e.getMessage() : e.getMessage().replace("field path \"" + s + "\": ", "'" + s + "': "));
            }
        }

        private void expect(Kind kind, String what) {
            Token t = peek();
            if (t.kind() != kind) {
                throw error(t.pos(), (t.kind() == Kind.END ? "the condition ends" : "found '" + t.text() + "'") + ", expected " + what);
            }
            at++;
        }

        private ConditionException error(int pos, String reason) {
            return new ConditionException(text, pos, reason);
        }
    }
}
