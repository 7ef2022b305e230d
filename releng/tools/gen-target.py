#!/usr/bin/env python3
"""Generate releng/org.stagecraft.target/org.stagecraft.target.target from Maven Central.

The target platform of Stagecraft is made of `type="Maven"` locations only (no p2 site is
reachable from our build machines).  Eclipse's POMs on Maven Central name the *lowest*
version of every OSGi range as the dependency version, so letting Tycho resolve them
transitively mixes several Eclipse releases.  This script walks the POMs itself, starting
from ROOTS, and writes one explicit version per artifact:

  * org.eclipse.*, org.ow2.asm, org.osgi: the newest release on Central (= one Eclipse release);
  * any other third-party artifact: the highest version some POM of the closure asks for;
  * roots without an explicit version: the newest release.

Every chosen jar is downloaded and inspected.  Jars that are OSGi bundles go into the
"Eclipse Platform" location (includeDependencyDepth="none", missingManifest="error"); plain
jars need a rule in WRAP and get a location of their own with bnd instructions; plain jars
without a rule stop the script.  Then a small static check runs: every mandatory
Require-Bundle, Fragment-Host and Import-Package of the set must be satisfied by the set
(or by the JDK).

Only the Python 3 standard library is used.  Downloads are cached (--cache).

    python3 releng/tools/gen-target.py                 # (re)write the .target
    python3 releng/tools/gen-target.py --check         # resolve + check only, print the set
"""

import argparse
import functools
import hashlib
import io
import os
import re
import sys
import time
import urllib.error
import urllib.request
import xml.etree.ElementTree as ET
import zipfile
from collections import defaultdict

CENTRAL = "https://repo.maven.apache.org/maven2"
HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_OUT = os.path.join(HERE, "..", "org.stagecraft.target", "org.stagecraft.target.target")

P = "org.eclipse.platform"

# ---------------------------------------------------------------------------------------
# Roots.  (groupId, artifactId[, version]).  Things that no POM declares but a running
# workbench needs (capabilities, services, themes, SWT fragment...) must be listed here.
# ---------------------------------------------------------------------------------------
ROOTS = [
    # core
    (P, "org.eclipse.osgi"),
    (P, "org.eclipse.core.runtime"),
    (P, "org.eclipse.core.resources"),
    (P, "org.eclipse.core.filesystem"),
    (P, "org.eclipse.core.expressions"),
    (P, "org.eclipse.core.variables"),
    (P, "org.eclipse.core.externaltools"),
    (P, "org.eclipse.core.commands"),
    (P, "org.eclipse.core.contenttype"),
    (P, "org.eclipse.core.jobs"),
    # equinox runtime pieces
    (P, "org.eclipse.equinox.launcher"),
    (P, "org.eclipse.equinox.launcher.gtk.linux.x86_64"),
    (P, "org.eclipse.equinox.event"),
    (P, "org.eclipse.equinox.simpleconfigurator"),
    (P, "org.eclipse.equinox.app"),
    (P, "org.eclipse.equinox.common"),
    (P, "org.eclipse.equinox.registry"),
    (P, "org.eclipse.equinox.preferences"),
    # SWT (the gtk fragment is normally pulled by SWT's p2.inf, which Tycho ignores here)
    (P, "org.eclipse.swt"),
    (P, "org.eclipse.swt.gtk.linux.x86_64"),
    (P, "org.eclipse.swt.svg"),  # provides eclipse.swt;image.format=svg
    # UI
    (P, "org.eclipse.jface"),
    (P, "org.eclipse.jface.text"),
    (P, "org.eclipse.text"),
    (P, "org.eclipse.ui"),
    (P, "org.eclipse.ui.workbench"),
    (P, "org.eclipse.ui.workbench.texteditor"),
    (P, "org.eclipse.ui.ide"),
    (P, "org.eclipse.ui.ide.application"),
    (P, "org.eclipse.ui.views"),
    (P, "org.eclipse.ui.navigator"),
    (P, "org.eclipse.ui.navigator.resources"),  # Project Explorer
    (P, "org.eclipse.ui.console"),
    (P, "org.eclipse.ui.editors"),
    (P, "org.eclipse.ui.forms"),
    (P, "org.eclipse.ui.themes"),
    (P, "org.eclipse.ui.externaltools"),
    # debug / launching
    (P, "org.eclipse.debug.core"),
    (P, "org.eclipse.debug.ui"),
    # what PyDev needs beyond the above (users install it from its update site; the PyDev test tier
    # installs it from the archived update site in ../shared/third-party)
    (P, "org.eclipse.search"),
    # p2 UI: Help > Install New Software / Installation Details / Available Software Sites, and the
    # director, engine, touchpoints and transport behind them (no features on Central: bundles)
    (P, "org.eclipse.equinox.p2.ui"),
    (P, "org.eclipse.equinox.p2.ui.sdk"),
    (P, "org.eclipse.equinox.p2.operations"),
    (P, "org.eclipse.equinox.p2.director"),
    (P, "org.eclipse.equinox.p2.engine"),
    (P, "org.eclipse.equinox.p2.garbagecollector"),
    (P, "org.eclipse.equinox.p2.touchpoint.eclipse"),
    (P, "org.eclipse.equinox.p2.touchpoint.natives"),
    (P, "org.eclipse.equinox.p2.transport.ecf"),
    (P, "org.eclipse.equinox.p2.updatechecker"),
    (P, "org.eclipse.equinox.simpleconfigurator.manipulator"),
    (P, "org.eclipse.equinox.frameworkadmin.equinox"),
    (P, "org.eclipse.osgi.compatibility.state"),
    # ECF file transfer for p2's transport (its POM leaves out what ECF needs; ECF's own URLConnection provider does http(s))
    ("org.eclipse.ecf", "org.eclipse.ecf.identity"),
    (P, "org.eclipse.equinox.concurrent"),
    # e4 runtime
    (P, "org.eclipse.e4.core.di"),
    (P, "org.eclipse.e4.core.di.extensions"),
    (P, "org.eclipse.e4.core.di.extensions.supplier"),
    (P, "org.eclipse.e4.core.contexts"),
    (P, "org.eclipse.e4.core.services"),
    (P, "org.eclipse.e4.core.commands"),
    (P, "org.eclipse.e4.ui.di"),
    (P, "org.eclipse.e4.ui.services"),
    (P, "org.eclipse.e4.ui.model.workbench"),
    (P, "org.eclipse.e4.ui.workbench"),
    (P, "org.eclipse.e4.ui.workbench.swt"),
    (P, "org.eclipse.e4.ui.workbench.renderers.swt"),
    (P, "org.eclipse.e4.ui.workbench.addons.swt"),
    (P, "org.eclipse.e4.ui.workbench3"),
    (P, "org.eclipse.e4.ui.css.core"),
    (P, "org.eclipse.e4.ui.css.swt"),
    (P, "org.eclipse.e4.ui.css.swt.theme"),
    (P, "org.eclipse.e4.ui.bindings"),
    (P, "org.eclipse.e4.ui.widgets"),
    (P, "org.eclipse.e4.emf.xpath"),
    # declarative services + service loader mediator
    ("org.apache.felix", "org.apache.felix.scr"),
    ("org.apache.aries.spifly", "org.apache.aries.spifly.dynamic.bundle"),
    ("org.ow2.asm", "asm"),
    ("org.ow2.asm", "asm-commons"),
    ("org.ow2.asm", "asm-tree"),
    ("org.ow2.asm", "asm-util"),
    ("org.ow2.asm", "asm-analysis"),
    # OSGi service APIs
    ("org.osgi", "org.osgi.service.component"),
    ("org.osgi", "org.osgi.service.event"),
    ("org.osgi", "org.osgi.service.prefs"),
    ("org.osgi", "org.osgi.service.cm"),
    ("org.osgi", "org.osgi.service.metatype"),
    ("org.osgi", "org.osgi.util.promise"),
    ("org.osgi", "org.osgi.util.function"),
]

# Groups whose newest release is taken whatever the POMs ask for.
NEWEST_GROUPS = ("org.eclipse.", "org.ow2.asm", "org.osgi")
# Exact version pins (override everything), "groupId:artifactId" -> version.
PINS = {}
# Dependencies never followed ("groupId:artifactId"); compile-time only or not needed.
SKIP = {
    "org.osgi:osgi.annotation",
    "org.osgi:org.osgi.annotation.versioning",
    "org.osgi:org.osgi.annotation.bundle",
    "org.osgi:org.osgi.service.component.annotations",
    "org.osgi:org.osgi.service.metatype.annotations",
    "com.google.code.findbugs:jsr305",
    "org.codehaus.mojo:animal-sniffer-annotations",  # declared by felix-parent, compile-time only
    "org.apache.xmlgraphics:batik-shared-resources",  # no classes (license files only)
}

# Plain jars that Eclipse needs, wrapped with generated manifests.  bsn = the Orbit name
# Eclipse bundles use in Require-Bundle; imports = what must be mandatory (Tycho drops
# optional dependencies when it computes test runtimes and products).
WRAP = {
    "org.apache.xmlgraphics:batik-css": dict(
        bsn="org.apache.batik.css",
        imports="org.apache.batik.*,org.w3c.css.sac.*,org.w3c.dom.*"),
    "org.apache.xmlgraphics:batik-util": dict(
        bsn="org.apache.batik.util",
        imports="org.apache.batik.*"),
    "org.apache.xmlgraphics:batik-i18n": dict(bsn="org.apache.batik.i18n", imports=""),
    "org.apache.xmlgraphics:batik-constants": dict(bsn="org.apache.batik.constants", imports=""),
    "org.apache.xmlgraphics:xmlgraphics-commons": dict(
        bsn="org.apache.xmlgraphics",
        imports="org.apache.commons.io.*,org.apache.commons.logging.*;resolution:=optional"),
    "xml-apis:xml-apis-ext": dict(bsn="org.w3c.css.sac", imports=""),
}

# JDK packages (never need an exporter in the target).
JDK_PACKAGE_PREFIXES = ("java.", "javax.", "org.w3c.dom", "org.xml.sax", "org.ietf.jgss",
                        "sun.", "com.sun.", "jdk.", "org.omg.")


# ---------------------------------------------------------------------------------------
# HTTP with a cache
# ---------------------------------------------------------------------------------------
class Fetcher:
    def __init__(self, cache, offline=False):
        self.cache = cache
        self.offline = offline
        os.makedirs(cache, exist_ok=True)

    def get(self, path, volatile=False):
        """Bytes of CENTRAL/path, or None on 404."""
        key = hashlib.sha1(path.encode()).hexdigest()
        fn = os.path.join(self.cache, key[:2], key)
        miss = fn + ".404"
        if os.path.exists(fn) and not (volatile and not self.offline and time.time() - os.path.getmtime(fn) > 3600):
            with open(fn, "rb") as f:
                return f.read()
        if os.path.exists(miss) and not volatile:
            return None
        if self.offline:
            raise SystemExit("offline and not cached: " + path)
        url = CENTRAL + "/" + path
        for attempt in range(4):
            try:
                with urllib.request.urlopen(url, timeout=60) as r:
                    data = r.read()
                break
            except urllib.error.HTTPError as e:
                if e.code == 404:
                    os.makedirs(os.path.dirname(fn), exist_ok=True)
                    open(miss, "w").close()
                    return None
                err = e
            except (urllib.error.URLError, OSError) as e:
                err = e
            time.sleep(1 + 2 * attempt)
        else:
            raise SystemExit("cannot fetch %s: %s" % (url, err))
        os.makedirs(os.path.dirname(fn), exist_ok=True)
        with open(fn + ".tmp", "wb") as f:
            f.write(data)
        os.replace(fn + ".tmp", fn)
        return data


def gpath(g):
    return g.replace(".", "/")


# ---------------------------------------------------------------------------------------
# Versions
# ---------------------------------------------------------------------------------------
PRERELEASE = re.compile(r"(alpha|beta|rc|cr|snapshot|preview|milestone|ea\b|[.-]m\d)", re.I)


def vkey(v):
    parts = re.split(r"[.\-_]", v)
    key = []
    for p in parts:
        if p.isdigit():
            key.append((1, int(p), ""))
        else:
            m = re.match(r"(\d+)(.*)", p)
            if m:
                key.append((1, int(m.group(1)), ""))
                key.append((0, 0, m.group(2).lower()))
            else:
                key.append((0, 0, p.lower()))
    return key


def is_release(v):
    return not PRERELEASE.search(v)


class Central:
    def __init__(self, fetcher):
        self.f = fetcher
        self.models = {}

    @functools.lru_cache(maxsize=None)
    def versions(self, g, a):
        data = self.f.get("%s/%s/maven-metadata.xml" % (gpath(g), a), volatile=True)
        if data is None:
            raise SystemExit("not on Central: %s:%s" % (g, a))
        root = ET.fromstring(data)
        return [e.text.strip() for e in root.iter("version")]

    def newest(self, g, a, major=None):
        vs = [v for v in self.versions(g, a) if is_release(v)]
        if major is not None:
            vs = [v for v in vs if v.split(".")[0] == str(major)]
        if not vs:
            raise SystemExit("no release of %s:%s" % (g, a))
        return max(vs, key=vkey)

    def pom(self, g, a, v):
        data = self.f.get("%s/%s/%s/%s-%s.pom" % (gpath(g), a, v, a, v))
        if data is None:
            raise SystemExit("POM missing on Central: %s:%s:%s" % (g, a, v))
        return strip_ns(ET.fromstring(data))

    def jar(self, g, a, v, classifier=None):
        suffix = "-" + classifier if classifier else ""
        return self.f.get("%s/%s/%s/%s-%s%s.jar" % (gpath(g), a, v, a, v, suffix))

    def model(self, g, a, v):
        k = (g, a, v)
        if k not in self.models:
            self.models[k] = Model(self, g, a, v)
        return self.models[k]


def strip_ns(root):
    for e in root.iter():
        if isinstance(e.tag, str) and "}" in e.tag:
            e.tag = e.tag.split("}", 1)[1]
    return root


def text(e, tag, default=None):
    c = e.find(tag)
    return c.text.strip() if c is not None and c.text is not None else default


# ---------------------------------------------------------------------------------------
# A small POM model: parents, properties, dependencyManagement (incl. import), OS profiles
# ---------------------------------------------------------------------------------------
class Dep:
    __slots__ = ("g", "a", "v", "scope", "optional", "classifier", "type", "exclusions")

    def __init__(self, e):
        self.g = text(e, "groupId")
        self.a = text(e, "artifactId")
        self.v = text(e, "version")
        self.scope = text(e, "scope")
        self.optional = text(e, "optional", "false")
        self.classifier = text(e, "classifier")
        self.type = text(e, "type")
        self.exclusions = set()
        ex = e.find("exclusions")
        if ex is not None:
            for x in ex.findall("exclusion"):
                self.exclusions.add("%s:%s" % (text(x, "groupId", "*"), text(x, "artifactId", "*")))


def profile_active(p, others_active):
    act = p.find("activation")
    if act is None:
        return False
    os_ = act.find("os")
    if os_ is not None:
        fam = (text(os_, "family") or "").lower()
        name = (text(os_, "name") or "").lower()
        arch = (text(os_, "arch") or "").lower()
        ok = True
        if fam:
            ok &= (fam.lstrip("!") in ("unix", "linux")) != fam.startswith("!")
        if name:
            ok &= (name.lstrip("!") == "linux") != name.startswith("!")
        if arch:
            ok &= (arch.lstrip("!") in ("amd64", "x86_64")) != arch.startswith("!")
        return ok
    jdk = text(act, "jdk")
    if jdk:
        m = re.match(r"[\[(]\s*([\d.]*)\s*,\s*([\d.]*)\s*[)\]]", jdk)
        if m:
            lo = int(m.group(1).split(".")[-1] if m.group(1).startswith("1.") else (m.group(1) or "0").split(".")[0])
            hi = m.group(2)
            hi = int(hi.split(".")[-1] if hi.startswith("1.") else hi.split(".")[0]) if hi else 999
            return lo <= 21 < hi or (lo <= 21 and jdk.endswith("]") and hi == 21)
        return jdk.lstrip("!").startswith("21") != jdk.startswith("!")
    prop = act.find("property")
    if prop is not None:
        name = text(prop, "name", "")
        return name.startswith("!") and text(prop, "value") is None
    if (text(act, "activeByDefault") or "") == "true":
        return not others_active
    return False


class Model:
    def __init__(self, central, g, a, v):
        pom = central.pom(g, a, v)
        self.parent = None
        pe = pom.find("parent")
        if pe is not None:
            self.parent = central.model(text(pe, "groupId"), text(pe, "artifactId"), text(pe, "version"))
        self.g = text(pom, "groupId") or (self.parent.g if self.parent else g)
        self.a = a
        self.v = text(pom, "version") or (self.parent.v if self.parent else v)
        self.packaging = text(pom, "packaging", "jar")
        self.props = dict(self.parent.props) if self.parent else {}
        pr = pom.find("properties")
        if pr is not None:
            for e in pr:
                if isinstance(e.tag, str):
                    self.props[e.tag] = (e.text or "").strip()
        self.props.update({"project.groupId": self.g, "pom.groupId": self.g, "groupId": self.g,
                           "project.artifactId": a, "project.version": self.v, "pom.version": self.v,
                           "version": self.v})
        if self.parent:
            self.props["project.parent.version"] = self.parent.v
            self.props["project.parent.groupId"] = self.parent.g

        # profiles
        profiles = pom.findall("profiles/profile")
        explicit = [p for p in profiles if profile_active(p, True) and
                    text(p.find("activation"), "activeByDefault") != "true"]
        active = [p for p in profiles if profile_active(p, bool(explicit))]
        for p in active:
            pr = p.find("properties")
            if pr is not None:
                for e in pr:
                    if isinstance(e.tag, str):
                        self.props[e.tag] = (e.text or "").strip()

        self.dm = dict(self.parent.dm) if self.parent else {}
        dm_elems = pom.findall("dependencyManagement/dependencies/dependency")
        for p in active:
            dm_elems += p.findall("dependencyManagement/dependencies/dependency")
        imports = []
        for e in dm_elems:
            d = self.interp_dep(Dep(e))
            if d.scope == "import" and (d.type or "") == "pom":
                imports.append(d)
            else:
                self.dm["%s:%s" % (d.g, d.a)] = d
        for d in imports:
            bom = central.model(d.g, d.a, d.v)
            for k, bd in bom.dm.items():
                self.dm.setdefault(k, bd)

        self.deps = {}
        if self.parent:
            self.deps.update(self.parent.deps)
        dep_elems = pom.findall("dependencies/dependency")
        for p in active:
            dep_elems += p.findall("dependencies/dependency")
        for e in dep_elems:
            d = self.interp_dep(Dep(e))
            m = self.dm.get("%s:%s" % (d.g, d.a))
            if m is not None:
                d.v = d.v or m.v
                d.scope = d.scope or m.scope
                d.exclusions |= m.exclusions
            d.scope = d.scope or "compile"
            self.deps["%s:%s:%s" % (d.g, d.a, d.classifier or "")] = d

    def interp(self, s, depth=0):
        if s is None or "${" not in s or depth > 10:
            return s
        return self.interp(re.sub(r"\$\{([^}]+)\}", lambda m: self.props.get(m.group(1), m.group(0)), s), depth + 1)

    def interp_dep(self, d):
        for f in ("g", "a", "v", "scope", "optional", "classifier", "type"):
            setattr(d, f, self.interp(getattr(d, f)))
        if d.v and d.v.startswith("["):  # a range: take its lower bound
            d.v = d.v.strip("[]()").split(",")[0].strip() or None
        return d


# ---------------------------------------------------------------------------------------
# Manifest inspection
# ---------------------------------------------------------------------------------------
def read_manifest(jarbytes):
    with zipfile.ZipFile(io.BytesIO(jarbytes)) as z:
        try:
            raw = z.read("META-INF/MANIFEST.MF").decode("utf-8", "replace")
        except KeyError:
            raw = ""
        pkgs = set()
        for n in z.namelist():
            if n.endswith(".class") and "/" in n and not n.startswith("META-INF/"):
                pkgs.add(n.rsplit("/", 1)[0].replace("/", "."))
    headers = {}
    cur = None
    for line in raw.splitlines():
        if line.startswith(" ") and cur:
            headers[cur] += line[1:]
        elif ":" in line:
            cur, val = line.split(":", 1)
            headers[cur] = val.strip()
        elif not line.strip():
            if headers:
                break  # main section only
    return headers, pkgs


def split_clauses(header):
    """Split an OSGi header at top-level commas, then each clause at top-level semicolons."""
    out, buf, quoted = [], "", False
    for ch in header or "":
        if ch == '"':
            quoted = not quoted
        if ch == "," and not quoted:
            out.append(buf)
            buf = ""
        else:
            buf += ch
    if buf.strip():
        out.append(buf)
    clauses = []
    for c in out:
        parts, buf, quoted = [], "", False
        for ch in c:
            if ch == '"':
                quoted = not quoted
            if ch == ";" and not quoted:
                parts.append(buf.strip())
                buf = ""
            else:
                buf += ch
        parts.append(buf.strip())
        names = [p for p in parts if "=" not in p]
        attrs = {}
        for p in parts:
            if "=" in p:
                k, val = p.split("=", 1)
                attrs[k.strip().rstrip(":")] = val.strip().strip('"')
        clauses.append((names, attrs))
    return clauses


def bsn_of(headers):
    v = headers.get("Bundle-SymbolicName")
    return v.split(";")[0].strip() if v else None


# ---------------------------------------------------------------------------------------
# Closure
# ---------------------------------------------------------------------------------------
def resolve(central, roots, log):
    root_versions = {}
    for r in roots:
        g, a = r[0], r[1]
        root_versions["%s:%s" % (g, a)] = r[2] if len(r) > 2 else central.newest(g, a)

    def choose(ga, asked):
        if ga in PINS:
            return PINS[ga]
        g, a = ga.split(":")
        if ga in root_versions:
            return root_versions[ga]
        if g.startswith(NEWEST_GROUPS):
            return central.newest(g, a)
        return max(asked, key=vkey)

    chosen = {}
    for rnd in range(10):
        asked = defaultdict(set)
        via = {}
        for ga, v in root_versions.items():
            asked[ga].add(v)
            via[ga] = "root"
        seen = set()
        queue = [(ga, frozenset()) for ga in root_versions]
        while queue:
            ga, excl = queue.pop(0)
            if (ga, excl) in seen:
                continue
            seen.add((ga, excl))
            v = chosen.get(ga) or choose(ga, asked[ga])
            g, a = ga.split(":")
            m = central.model(g, a, v)
            for d in m.deps.values():
                dga = "%s:%s" % (d.g, d.a)
                if d.scope not in ("compile", "runtime") or d.optional == "true":
                    continue
                if (d.type or "jar") not in ("jar", "bundle", "eclipse-plugin") or d.classifier:
                    continue
                if dga in SKIP or dga in excl or ("%s:*" % d.g) in excl or "*:*" in excl:
                    continue
                if not d.v:
                    log("warning: no version for %s in %s:%s" % (dga, ga, v))
                    continue
                asked[dga].add(d.v)
                via.setdefault(dga, "%s:%s" % (ga, v))
                queue.append((dga, excl | frozenset(d.exclusions)))
        new = {ga: choose(ga, vs) for ga, vs in asked.items()}
        if new == chosen:
            break
        chosen = new
        log("round %d: %d artifacts" % (rnd + 1, len(chosen)))
    else:
        raise SystemExit("version choice does not converge")
    return chosen, asked, via


JAVA_EE_BSN = "system.bundle"


def check(bundles, log):
    """bundles: list of dicts with bsn, headers, pkgs, wrapped(imports). Report unsatisfied requirements."""
    by_bsn = {b["bsn"]: b for b in bundles}
    exported = set()
    for b in bundles:
        for names, _ in split_clauses(b["headers"].get("Export-Package")):
            exported.update(names)
        if b.get("wrap"):
            exported.update(b["pkgs"])
    exported.update(["org.osgi.framework", "org.osgi.service.log"])  # system bundle extras
    provided = set()
    for b in bundles:
        for names, attrs in split_clauses(b["headers"].get("Provide-Capability")):
            for ns in names:
                provided.add((ns, attrs.get(ns)))
    provided.add(("osgi.service", None))
    problems = []
    for b in bundles:
        h = b["headers"]
        for names, attrs in split_clauses(h.get("Require-Bundle")):
            if attrs.get("resolution") == "optional":
                continue
            for n in names:
                if n not in by_bsn and n != JAVA_EE_BSN:
                    problems.append("%s: Require-Bundle %s" % (b["bsn"], n))
        for names, attrs in split_clauses(h.get("Fragment-Host")):
            for n in names:
                if n not in by_bsn and n != JAVA_EE_BSN:
                    problems.append("%s: Fragment-Host %s" % (b["bsn"], n))
        for names, attrs in split_clauses(h.get("Import-Package")):
            if attrs.get("resolution") == "optional":
                continue
            for n in names:
                if n.startswith(JDK_PACKAGE_PREFIXES) or n in exported or "*" in n:
                    continue
                if b["bsn"] == "org.eclipse.osgi":
                    continue
                problems.append("%s: Import-Package %s" % (b["bsn"], n))
        for names, attrs in split_clauses(h.get("Require-Capability")):
            if attrs.get("resolution") == "optional":
                continue
            for ns in names:
                if ns in ("osgi.ee", "osgi.native"):
                    continue
                f = attrs.get("filter", "")
                m = re.search(r"\(%s=([^)]+)\)" % re.escape(ns), f)
                want = m.group(1) if m else None
                if not any(cns == ns and (want is None or cval == want) for cns, cval in provided):
                    problems.append("%s: Require-Capability %s %s" % (b["bsn"], ns, f))
    return problems


# ---------------------------------------------------------------------------------------
# Output
# ---------------------------------------------------------------------------------------
def esc(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def dep_xml(g, a, v, classifier=None, indent="        "):
    c = "<classifier>%s</classifier>" % classifier if classifier else ""
    return "%s<dependency><groupId>%s</groupId><artifactId>%s</artifactId><version>%s</version>%s<type>jar</type></dependency>" % (
        indent, g, a, v, c)


def instructions_xml(reference, lines, indent="      "):
    body = "\n".join(lines)
    return '%s<instructions reference="%s"><![CDATA[\n%s\n%s]]></instructions>' % (indent, reference, body, indent)


def wrap_lines(bsn, name, version, imports, extra=()):
    imp = (imports + ",*;resolution:=optional") if imports else "*;resolution:=optional"
    return [
        "Bundle-Name: %s (wrapped from Maven Central)" % name,
        "Bundle-SymbolicName: %s" % bsn,
        "version: ${version_cleanup;%s}" % version,
        "Bundle-Version: ${version}",
        "Import-Package: %s" % imp,
        "Export-Package: *;version=\"${version}\";-noimport:=true",
        "-noextraheaders: true",
        "-removeheaders: Bnd-LastModified,Tool,Created-By,Private-Package,Include-Resource",
    ] + list(extra)


# zstd for the chunks of the spy log (MCAP): an OSGi bundle as published, with the JNI libraries
# inside (Bundle-NativeCode, linux/amd64 among them).  Pinned: the log format must not move with it.
ZSTD_JNI_VERSION = "1.5.7-28"

# The live view over the Foxglove WebSocket protocol (org.stagecraft.foxglove.live): Java-WebSocket,
# an OSGi bundle as published (Bundle-SymbolicName "Java-WebSocket"), whose only dependency is
# slf4j-api [2.0,3) (already in the target for pty4j).  Pinned: the server is tested against it.
JAVA_WEBSOCKET_VERSION = "1.6.0"

# The JDT null annotations (@NonNullByDefault, @Nullable, @NonNull; docs/architecture.md, "Null
# analysis"): an OSGi bundle as published, exporting org.eclipse.jdt.annotation without a version
# (so bundles import it without a range), with no dependencies.  Compile time only: the annotations
# have CLASS retention, bundles import the package with resolution:=optional, and neither the feature
# nor the product includes the bundle.  Pinned: the compiler's null analysis is tuned against it.
JDT_ANNOTATION_VERSION = "2.4.100"

JOGL_VERSION = "2.6.0"
# JOGL in OSGi.  Gluegen loads every JNI library (its own and JOGL's) with System.load/loadLibrary
# called from its own class JNILibLoaderBase, and the JVM binds a JNI library to the class loader of
# that caller: JOGL's native methods only link if JOGL's classes share gluegen's class loader.  So
# jogl-all and all natives jars are *fragments* of gluegen-rt (one class loader).  Gluegen's own
# lookup of "<name>-natives-<os>.jar" beside the class jar cannot work on bundle URLs; the natives
# fragments therefore declare Bundle-NativeCode, Equinox extracts the library the platform needs and
# gluegen's fallback System.loadLibrary finds it through the bundle class loader.
# (os, arch filter, Bundle-NativeCode attributes) per natives classifier; the library list is read
# from the jar on Central.
JOGL_NATIVES = [
    ("natives-linux-amd64", "(& (osgi.os=linux) (osgi.arch=x86_64))", "osname=Linux; processor=x86-64"),
    ("natives-windows-amd64", "(& (osgi.os=win32) (osgi.arch=x86_64))", "osname=Win32; processor=x86-64"),
    ("natives-macosx-universal", "(osgi.os=macosx)", "osname=MacOSX; processor=x86-64; processor=aarch64"),
]
JOGL_HOST = "org.jogamp.gluegen.rt"
JOGL = [
    # (groupId, artifactId, classifier, bsn, imports, extra headers)
    ("org.jogamp.gluegen", "gluegen-rt", None, JOGL_HOST, "", ["DynamicImport-Package: *"]),
    ("org.jogamp.jogl", "jogl-all", None, "org.jogamp.jogl.all",
     "!com.jogamp.*,!jogamp.*,org.eclipse.swt.*;resolution:=optional", ["Fragment-Host: " + JOGL_HOST]),
]
for _c, _filter, _attrs in JOGL_NATIVES:
    _suffix = _c[len("natives-"):].replace("-", ".")
    for _g, _a, _bsn in (("org.jogamp.gluegen", "gluegen-rt", "org.jogamp.gluegen.rt"),
                         ("org.jogamp.jogl", "jogl-all", "org.jogamp.jogl.all")):
        JOGL.append((_g, _a, _c, "%s.natives.%s" % (_bsn, _suffix), "",
                     ["Fragment-Host: " + JOGL_HOST, "Eclipse-PlatformFilter: " + _filter,
                      ("Bundle-NativeCode", _attrs)]))


# pty4j: Stagecraft runs tools (Player above all) on a pseudo-terminal, so that their C stdio is
# line-buffered and every line shows as it is written.  Pinned (with what it needs) like zstd-jni:
# tool supervision must not move with a regeneration.  pty4j and kotlin-stdlib are plain jars,
# wrapped here with mandatory imports for what they really use (Tycho drops optional ones from
# test runtimes and products); JNA is the platform's own (first location); slf4j-api is a bundle.
PTY4J_VERSION = "0.13.12"
KOTLIN_STDLIB_VERSION = "2.1.21"   # what pty4j 0.13.12's POM asks for
SLF4J_API_VERSION = "2.0.17"
PTY4J = [
    # (groupId, artifactId, version, bsn, mandatory imports)
    ("org.jetbrains.pty4j", "pty4j", PTY4J_VERSION, "org.jetbrains.pty4j",
     'com.sun.jna.*;version="[5.14,6)",kotlin.*,org.slf4j.*'),
    ("org.jetbrains.kotlin", "kotlin-stdlib", KOTLIN_STDLIB_VERSION, "org.jetbrains.kotlin.stdlib", ""),
]


def pty4j_locations():
    """The target's pty4j locations (no network needed: everything is pinned)."""
    out = []
    w = out.append
    for g, a, v, bsn, imports in PTY4J:
        w('    <location type="Maven" label="%s %s (wrapped as %s)" includeDependencyDepth="none" '
          'includeDependencyScopes="compile" includeSource="false" missingManifest="generate">' % (a, v, bsn))
        w("      <dependencies>")
        w(dep_xml(g, a, v))
        w("      </dependencies>")
        w(instructions_xml("%s:%s::%s" % (g, a, v), wrap_lines(bsn, a, v, imports)))
        w("    </location>")
    # slf4j-api 2 requires a provider (osgi.serviceloader capability): slf4j-simple, so pty4j's
    # warnings reach the IDE's standard error rather than nowhere.
    w('    <location type="Maven" label="slf4j-api and slf4j-simple (for pty4j)" includeDependencyDepth="none" '
      'includeDependencyScopes="compile" includeSource="false" missingManifest="error">')
    w("      <dependencies>")
    w(dep_xml("org.slf4j", "slf4j-api", SLF4J_API_VERSION))
    w(dep_xml("org.slf4j", "slf4j-simple", SLF4J_API_VERSION))
    w("      </dependencies>")
    w("    </location>")
    return out


def native_code_header(central, g, a, c, attrs):
    """Bundle-NativeCode listing every library in the natives jar's natives/<platform>/ folder."""
    data = central.jar(g, a, JOGL_VERSION, c)
    if data is None:
        raise SystemExit("not on Central: %s:%s:%s:%s" % (g, a, c, JOGL_VERSION))
    with zipfile.ZipFile(io.BytesIO(data)) as z:
        libs = sorted(n for n in z.namelist()
                      if n.startswith("natives/") and not n.endswith("/")
                      and n.rsplit("/", 1)[1].endswith((".so", ".dll", ".dylib", ".jnilib")))
    if not libs:
        raise SystemExit("no native libraries in %s:%s:%s" % (g, a, c))
    return "Bundle-NativeCode: %s; %s" % ("; ".join(libs), attrs)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=DEFAULT_OUT)
    ap.add_argument("--cache", default=os.path.join(os.path.expanduser("~"), ".cache", "stagecraft-gen-target"))
    ap.add_argument("--offline", action="store_true", help="use the cache only")
    ap.add_argument("--check", action="store_true", help="do not write, only resolve, check and print")
    ap.add_argument("--no-jogl", action="store_true", help="leave the JOGL location out")
    args = ap.parse_args()
    log = lambda s: print(s, file=sys.stderr)

    central = Central(Fetcher(args.cache, args.offline))
    chosen, asked, via = resolve(central, ROOTS, log)

    osgi, wrapped, bundles, dropped = [], [], [], []
    for ga in sorted(chosen):
        g, a = ga.split(":")
        v = chosen[ga]
        m = central.model(g, a, v)
        if m.packaging == "pom":
            dropped.append("%s:%s (packaging pom)" % (ga, v))
            continue
        data = central.jar(g, a, v)
        if data is None:
            raise SystemExit("jar missing on Central: %s:%s" % (ga, v))
        headers, pkgs = read_manifest(data)
        bsn = bsn_of(headers)
        if bsn:
            osgi.append((g, a, v, bsn))
            bundles.append(dict(bsn=bsn, headers=headers, pkgs=pkgs))
        elif ga in WRAP:
            rule = WRAP[ga]
            wrapped.append((g, a, v, rule))
            imports = rule["imports"].replace("${version}", re.sub(r"[^0-9.].*$", "", v))
            hdrs = {"Import-Package": imports}
            bundles.append(dict(bsn=rule["bsn"], headers=hdrs, pkgs=pkgs, wrap=True))
        else:
            raise SystemExit("%s:%s is not an OSGi bundle and has no WRAP rule (needed by %s)" % (ga, v, via.get(ga)))

    problems = check(bundles, log)
    eclipse_ui = chosen.get("org.eclipse.platform:org.eclipse.ui")
    jdt_hint = central.newest("org.eclipse.jdt", "org.eclipse.jdt.core")
    log("%d OSGi bundles, %d wrapped jars; org.eclipse.ui %s, newest jdt.core %s"
        % (len(osgi), len(wrapped), eclipse_ui, jdt_hint))
    for d in dropped:
        log("skipped " + d)
    for p in problems:
        log("UNSATISFIED " + p)
    if args.check:
        for g, a, v, bsn in osgi:
            print("%s:%s:%s  %s" % (g, a, v, bsn))
        for g, a, v, rule in wrapped:
            print("%s:%s:%s  %s (wrapped)" % (g, a, v, rule["bsn"]))
    if problems:
        raise SystemExit("%d unsatisfied requirements" % len(problems))
    if args.check:
        return

    gson = central.newest("com.google.code.gson", "gson", major=2)
    jupiter = central.newest("org.junit.jupiter", "junit-jupiter-api", major=5)
    platform = central.newest("org.junit.platform", "junit-platform-launcher", major=1)

    out = []
    w = out.append
    w('<?xml version="1.0" encoding="UTF-8" standalone="no"?>')
    w('<?pde version="3.8"?>')
    w("<!-- GENERATED by releng/tools/gen-target.py from Maven Central: do not edit by hand, edit the")
    w("     script and run `python3 releng/tools/gen-target.py`.  Only type=\"Maven\" locations: the build")
    w("     must not need any p2 site.  Eclipse Platform release: org.eclipse.ui %s (Eclipse 4.41). -->" % eclipse_ui)
    w('<target name="Stagecraft (Eclipse Platform from Maven Central)" sequenceNumber="1">')
    w("  <locations>")
    w('    <location type="Maven" label="Eclipse Platform (Maven Central)" includeDependencyDepth="none" '
      'includeDependencyScopes="compile" includeSource="false" missingManifest="error">')
    w("      <dependencies>")
    for g, a, v, bsn in osgi:
        w(dep_xml(g, a, v))
    w("      </dependencies>")
    w("    </location>")
    for g, a, v, rule in wrapped:
        ref = "%s:%s::%s" % (g, a, v)
        w('    <location type="Maven" label="%s %s (wrapped as %s)" includeDependencyDepth="none" '
          'includeDependencyScopes="compile" includeSource="false" missingManifest="generate">' % (a, v, rule["bsn"]))
        w("      <dependencies>")
        w(dep_xml(g, a, v))
        w("      </dependencies>")
        imports = rule["imports"].replace("${version}", re.sub(r"[^0-9.].*$", "", v))
        w(instructions_xml(ref, wrap_lines(rule["bsn"], a, v, imports)))
        w("    </location>")
    w('    <location type="Maven" label="JUnit 5" includeDependencyDepth="infinite" '
      'includeDependencyScopes="compile,runtime" includeSource="false" missingManifest="error">')
    w("      <dependencies>")
    for g, a, v in [("org.junit.jupiter", "junit-jupiter-api", jupiter),
                    ("org.junit.jupiter", "junit-jupiter-engine", jupiter),
                    ("org.junit.jupiter", "junit-jupiter-params", jupiter),
                    ("org.junit.platform", "junit-platform-launcher", platform),
                    ("org.junit.platform", "junit-platform-suite", platform)]:
        w(dep_xml(g, a, v))
    w("      </dependencies>")
    w("    </location>")
    w('    <location type="Maven" label="Gson" includeDependencyDepth="none" '
      'includeDependencyScopes="compile" includeSource="false" missingManifest="error">')
    w("      <dependencies>")
    w(dep_xml("com.google.code.gson", "gson", gson))
    w("      </dependencies>")
    w("    </location>")
    w('    <location type="Maven" label="zstd-jni" includeDependencyDepth="none" '
      'includeDependencyScopes="compile" includeSource="false" missingManifest="error">')
    w("      <dependencies>")
    w(dep_xml("com.github.luben", "zstd-jni", ZSTD_JNI_VERSION))
    w("      </dependencies>")
    w("    </location>")
    w('    <location type="Maven" label="Java-WebSocket (the Foxglove live server)" includeDependencyDepth="none" '
      'includeDependencyScopes="compile" includeSource="false" missingManifest="error">')
    w("      <dependencies>")
    w(dep_xml("org.java-websocket", "Java-WebSocket", JAVA_WEBSOCKET_VERSION))
    w("      </dependencies>")
    w("    </location>")
    w('    <location type="Maven" label="JDT null annotations (compile time only)" includeDependencyDepth="none" '
      'includeDependencyScopes="compile" includeSource="false" missingManifest="error">')
    w("      <dependencies>")
    w(dep_xml("org.eclipse.jdt", "org.eclipse.jdt.annotation", JDT_ANNOTATION_VERSION))
    w("      </dependencies>")
    w("    </location>")
    out.extend(pty4j_locations())
    if not args.no_jogl:
        w('    <location type="Maven" label="JOGL %s (wrapped, natives as fragments)" includeDependencyDepth="none" '
          'includeDependencyScopes="compile" includeSource="false" missingManifest="generate">' % JOGL_VERSION)
        w("      <dependencies>")
        for g, a, c, bsn, imports, extra in JOGL:
            w(dep_xml(g, a, JOGL_VERSION, c))
        w("      </dependencies>")
        for g, a, c, bsn, imports, extra in JOGL:
            ref = "%s:%s:%s:%s" % (g, a, c or "", JOGL_VERSION)
            extra = [native_code_header(central, g, a, c, x[1]) if isinstance(x, tuple) else x for x in extra]
            w(instructions_xml(ref, wrap_lines(bsn, a + (" " + c if c else ""), JOGL_VERSION, imports, extra)))
        w("      <exclude>antlr:antlr:2.7.7</exclude>")
        w("    </location>")
    w("  </locations>")
    w("  <targetJRE path=\"org.eclipse.jdt.launching.JRE_CONTAINER/org.eclipse.jdt.internal.debug.ui.launcher.StandardVMType/JavaSE-21\"/>")
    w("</target>")
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w") as f:
        f.write("\n".join(out) + "\n")
    log("wrote %s (gson %s, JUnit %s/%s)" % (os.path.relpath(args.out), gson, jupiter, platform))


if __name__ == "__main__":
    main()
