#!/usr/bin/env python3
"""Checks docs/architecture.md against the bundles as built (standard library only).

1. The bundle graph: the `A --> B` edges of the ```mermaid block under "The bundle graph" must be
   exactly the Require-Bundle edges between Stagecraft's own bundles (bundles/*/META-INF/MANIFEST.MF;
   a node name drops `org.stagecraft.` and writes `.` as `_`). An edge in one and not the other fails.
2. The rule: a bundle in the "Pure Java" table requires no `org.eclipse.*` bundle and imports no
   `org.eclipse.*` / `org.osgi.*` package (except `org.eclipse.jdt.annotation` with
   `resolution:=optional`: the null annotations, compile time only; "Null analysis"); every bundle
   of bundles/ is in one of the two tables.
3. API discipline (docs/architecture.md, "API discipline"): a package named `*.internal` is exported
   only with `x-internal:=true` or `x-friends:=`; and no bundle's main code (bundles/*/src/main) or
   plug-in test bundle (tests/* with a manifest) imports a class of another bundle's package that is
   x-internal, or x-friends without naming it. (Tycho's build does not report such an access for
   test sources, PDE does; this check makes it fail everywhere.)

Exit status 1 with every disagreement named. `--self-test` first checks that a doc with an edge
missing, an edge too many, and a pure bundle requiring Eclipse is each rejected.

usage: check-architecture.py [--self-test] [REPO_ROOT]
"""
import re
import sys
from pathlib import Path

PREFIX = "org.stagecraft."


def manifest_headers(text):
    """The main section's headers, continuation lines (starting with one space) joined."""
    headers, name = {}, None
    for line in text.splitlines():
        if line.startswith(" ") and name:
            headers[name] += line[1:]
        elif ":" in line:
            name, value = line.split(":", 1)
            headers[name] = value.strip()
        elif not line.strip():
            break
    return headers


def clauses(value):
    """Splits a header value at top-level commas (not inside quotes)."""
    out, cur, quoted = [], "", False
    for ch in value or "":
        if ch == '"':
            quoted = not quoted
        if ch == "," and not quoted:
            out.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        out.append(cur.strip())
    return out


def read_bundles(root):
    """{symbolic name: headers} of every bundle under bundles/."""
    bundles = {}
    for mf in sorted((root / "bundles").glob("*/META-INF/MANIFEST.MF")):
        h = manifest_headers(mf.read_text(encoding="utf-8"))
        bundles[h["Bundle-SymbolicName"].split(";")[0].strip()] = h
    return bundles


def read_test_bundles(root):
    """{symbolic name: (headers, bundle dir)} of every test bundle under tests/ that has a manifest."""
    out = {}
    for mf in sorted((root / "tests").glob("*/META-INF/MANIFEST.MF")):
        h = manifest_headers(mf.read_text(encoding="utf-8"))
        out[h["Bundle-SymbolicName"].split(";")[0].strip()] = (h, mf.parent.parent)
    return out


def restricted_exports(bundles):
    """{package: (owner, friends or None for x-internal)} of the packages exported as not API."""
    out = {}
    for name, h in bundles.items():
        for c in clauses(h.get("Export-Package")):
            pkg = c.split(";")[0].strip()
            friends = re.search(r'x-friends:="([^"]*)"', c)
            if friends:
                out[pkg] = (name, {f.strip() for f in friends.group(1).split(",")})
            elif "x-internal:=true" in c:
                out[pkg] = (name, set())
    return out


IMPORT = re.compile(r"^import\s+(?:static\s+)?((?:[a-z_][\w]*\.)+)[A-Z]", re.M)


def access_problems(restricted, users):
    """users: [(importer symbolic name, java file)]; every import of a restricted package not allowed."""
    problems = []
    for importer, java in users:
        for m in IMPORT.finditer(java.read_text(encoding="utf-8", errors="replace")):
            pkg = m.group(1).rstrip(".")
            if pkg in restricted:
                owner, friends = restricted[pkg]
                if owner != importer and importer not in friends:
                    problems.append(f"{java}: {importer} uses {pkg}, which {owner} exports only to "
                                    + (", ".join(sorted(friends)) if friends else "itself (x-internal)"))
    return problems


def users_of(root, bundles, test_bundles):
    users = []
    for mf in sorted((root / "bundles").glob("*/META-INF/MANIFEST.MF")):
        name = manifest_headers(mf.read_text(encoding="utf-8"))["Bundle-SymbolicName"].split(";")[0].strip()
        users += [(name, j) for j in sorted((mf.parent.parent / "src" / "main").rglob("*.java"))]
    for name, (_, directory) in test_bundles.items():
        users += [(name, j) for j in sorted((directory / "src").rglob("*.java"))]
    return users


def node(symbolic_name):
    return symbolic_name[len(PREFIX):].replace(".", "_")


def manifest_edges(bundles):
    edges = set()
    for name, h in bundles.items():
        for c in clauses(h.get("Require-Bundle")):
            target = c.split(";")[0].strip()
            if target in bundles:
                edges.add((node(name), node(target)))
    return edges


def section(doc, heading):
    start = doc.index(heading)
    nxt = re.search(r"^#{1,3} ", doc[start + len(heading):], re.M)
    return doc[start: start + len(heading) + nxt.start()] if nxt else doc[start:]


def doc_edges(doc):
    graph = section(doc, "### The bundle graph")
    block = re.search(r"```mermaid\n(.*?)```", graph, re.S)
    if not block:
        raise ValueError("docs/architecture.md: no ```mermaid block under '### The bundle graph'")
    return set(re.findall(r"^\s*(\w+)\s*-->\s*(\w+)\s*$", block.group(1), re.M))


def table_bundles(doc, heading):
    """The bundles named in the first column of the table that follows the line `heading`."""
    rows, started = [], False
    for line in doc[doc.index(heading):].splitlines()[1:]:
        if line.startswith("|"):
            started = True
            rows.append(line)
        elif started or (line.strip() and not line.startswith("|")):
            break
    return set(re.findall(r"^\| `(org\.stagecraft\.[\w.]+)` \|", "\n".join(rows), re.M))


# The JDT null annotations (docs/architecture.md, "Null analysis") have CLASS retention: nothing
# needs them at run time, so a pure-Java bundle may import their package, optionally.
COMPILE_TIME_ONLY_PACKAGES = {"org.eclipse.jdt.annotation"}


def compile_time_only(clause):
    """Whether an Import-Package clause is an optional import of an annotation-only package."""
    parts = [p.strip() for p in clause.split(";")]
    return parts[0] in COMPILE_TIME_ONLY_PACKAGES and "resolution:=optional" in parts[1:]


def check(doc, bundles):
    problems = []
    built, drawn = manifest_edges(bundles), doc_edges(doc)
    for a, b in sorted(built - drawn):
        problems.append(f"edge {a} --> {b} is in the manifests but not in the doc's graph")
    for a, b in sorted(drawn - built):
        problems.append(f"edge {a} --> {b} is in the doc's graph but not in the manifests")
    pure = table_bundles(doc, "Pure Java:")
    eclipse = table_bundles(doc, "Eclipse bundles (thin")
    for name in sorted(set(bundles) - pure - eclipse):
        problems.append(f"{name} is in neither the pure-Java nor the Eclipse table")
    for name in sorted(pure & eclipse):
        problems.append(f"{name} is in both tables")
    for name in sorted(pure & set(bundles)):
        h = bundles[name]
        for c in clauses(h.get("Require-Bundle")):
            if c.startswith("org.eclipse."):
                problems.append(f"{name} is pure Java but requires {c.split(';')[0]}")
        for c in clauses(h.get("Import-Package")):
            if c.startswith(("org.eclipse.", "org.osgi.")) and not compile_time_only(c):
                problems.append(f"{name} is pure Java but imports {c.split(';')[0]}")
    for name, h in sorted(bundles.items()):
        for c in clauses(h.get("Export-Package")):
            pkg = c.split(";")[0].strip()
            if pkg.endswith(".internal") and "x-internal:=true" not in c and "x-friends:=" not in c:
                problems.append(f"{name} exports {pkg} without x-internal or x-friends")
    return problems


def self_test(doc, bundles):
    first = re.search(r"^(\s*\w+\s*-->\s*\w+\s*)$", section(doc, "### The bundle graph"), re.M).group(1)
    cases = {
        "an edge missing from the doc": doc.replace(first + "\n", "", 1),
        "an edge too many in the doc": doc.replace(first, first + "\n  player --> mcap", 1),
    }
    for what, bad in cases.items():
        if not check(bad, bundles):
            return f"self-test: a doc with {what} was accepted"
    pure_name = sorted(table_bundles(doc, "Pure Java:") & set(bundles))[0]
    tampered = dict(bundles)
    tampered[pure_name] = dict(bundles[pure_name])
    tampered[pure_name]["Require-Bundle"] = "org.eclipse.core.runtime," + bundles[pure_name].get("Require-Bundle", "")
    if not any("requires org.eclipse.core.runtime" in p for p in check(doc, tampered)):
        return "self-test: a pure-Java bundle requiring org.eclipse.core.runtime was accepted"
    tampered[pure_name] = dict(bundles[pure_name])
    tampered[pure_name]["Import-Package"] = "org.eclipse.jdt.annotation"   # not optional: needed at run time
    if not any("imports org.eclipse.jdt.annotation" in p for p in check(doc, tampered)):
        return "self-test: a pure-Java bundle importing org.eclipse.jdt.annotation (mandatory) was accepted"
    if restricted_exports_self_test():
        return restricted_exports_self_test()
    return None


def restricted_exports_self_test():
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        java = Path(d) / "Uses.java"
        java.write_text("package a;\nimport org.stagecraft.x.internal.Thing;\nimport org.stagecraft.y.Open;\n")
        restricted = {"org.stagecraft.x.internal": ("org.stagecraft.x", {"org.stagecraft.x.tests"})}
        if not access_problems(restricted, [("org.stagecraft.other", java)]):
            return "self-test: a non-friend's use of an x-friends package was accepted"
        if access_problems(restricted, [("org.stagecraft.x.tests", java)]):
            return "self-test: a friend's use of an x-friends package was refused"
    return None


def main(argv):
    args = [a for a in argv if a != "--self-test"]
    root = Path(args[0]) if args else Path(__file__).resolve().parents[2]
    doc = (root / "docs" / "architecture.md").read_text(encoding="utf-8")
    bundles = read_bundles(root)
    if "--self-test" in argv:
        failure = self_test(doc, bundles)
        if failure:
            print(failure, file=sys.stderr)
            return 1
    problems = check(doc, bundles)
    restricted = restricted_exports(bundles)
    problems += access_problems(restricted, users_of(root, bundles, read_test_bundles(root)))
    for p in problems:
        print(f"docs/architecture.md disagrees with the bundles: {p}", file=sys.stderr)
    if not problems:
        print(f"docs/architecture.md: bundle graph ({len(manifest_edges(bundles))} edges, {len(bundles)} bundles), "
              "the pure-Java rule and the x-internal/x-friends exports agree with the manifests and the code")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
