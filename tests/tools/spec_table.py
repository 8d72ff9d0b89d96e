#!/usr/bin/python3
"""The spec's input files (its "Input files" list: 154 Abaqus/Standard and 58 Abaqus/Explicit decks) against the
project's tests, and the table of docs/verification.md ("The spec's 212 decks at a glance") written from a ctest
run.

The list is read from the spec's text (/work/shared/spec/finite-sliding-coupled-temp-disp.txt, or $TSL_SPEC), or,
where the spec is not at hand, from tests/tools/spec_decks.txt: the spec's "Input files" section as this script
extracts it (`spec_table.py extract > tests/tools/spec_decks.txt`), checked against the spec whenever it is.
Each deck's element type, series, procedure and contact come from its heading and description lines, and the file
name (`_surf`: surface to surface, `_auglagr`: augmented Lagrange, `_post`: a POST OUTPUT analysis). Each maps to
the project's test names by the suite's naming (tests/verification/CMakeLists.txt, tests/explicit/CMakeLists.txt):
  Standard  sliding_<series>[_auglagr|_surf]_<type>_np1 / _np2 (+ _np2_pair_split, _np1_vs_np2); the spec's
            CAX8T-and-SAX2T decks (eia3tsl*) as <type> sax2t
  Explicit  explicit_spec_sliding_<series>_explicit_<kinematic|penalty>_<type>_np1 / _np2 (written at test time by
            make_decks.py --explicit-series), or explicit_sliding_... for the committed decks of jobs/verification
A deck's tests are its run tests (<name>_np<N>, which run the deck and its check script) and their companions
(<name>_np<N>_<what>, <name>_heat_equals_<type>). Decks the suite has no counterpart for are named in EXCEPTIONS
with the reason. Labels and ranks are ctest's (`ctest --show-only=json-v1`: LABELS, and the -n of the mpiexec
in the command).

usage:
  spec_table.py extract [--spec FILE]              the spec's "Input files" section, for spec_decks.txt
  spec_table.py bases                              every deck's candidate test names (CMake's `spec` label)
  spec_table.py check --build DIR [--spec FILE]    212 decks, 154 + 58, each mapped to registered tests with the
                                                   `spec` label or to an exception (the ctest test spec_table_mapping)
  spec_table.py table --build DIR [LOG ...] [--update DOC]
                                                   the table from the check lines in ctest logs (default:
                                                   DIR/Testing/Temporary/LastTest.log; a later log wins for a test it
                                                   holds), printed, or written between DOC's markers in place
  spec_table.py run --build DIR [-j N] [--update DOC] [-- CTEST-ARGS ...]
                                                   ctest -L spec -j N (default 2) in DIR, its log kept as
                                                   DIR/spec_run.log, then `table` from it
The check lines are tslcheck.py's: `name: value (expected E, [relative ]tolerance T) PASS|FAIL` and
`name: detail PASS|FAIL`.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SPEC = os.environ.get("TSL_SPEC", "/work/shared/spec/finite-sliding-coupled-temp-disp.txt")
EXTRACT = os.path.join(HERE, "spec_decks.txt")
BEGIN = "<!-- spec-table: begin (written by tests/tools/spec_table.py from a ctest run; do not edit by hand) -->"
END = "<!-- spec-table: end -->"

# The spec's decks without a counterpart in the suite, and why (each must name its reason).
EXCEPTIONS = {}

# The spec's decks whose counterpart carries a time-dependent film coefficient (the spec: "eia2tssc.inp illustrates the
# procedure to specify a time-dependent variation of the film coefficient"; make_decks.py --film-amplitude)
FILM_AMPLITUDE = {"eia2tssc"}

SERIES = {"Interface conductance tests": "conductance", "Interface radiation tests": "radiation",
          "Frictional heat generation tests": "friction"}


# ---------------------------------------------------------------------------------------------------------------
# The spec's list

def spec_section(lines):
    """The lines of the spec's "Input files" section (from that heading to the end), stripped, blank lines out."""
    lines = [l.strip() for l in lines]
    if "Input files" not in lines:
        raise SystemExit("no \"Input files\" heading: not the spec's text")
    return [l for l in lines[lines.index("Input files") + 1:] if l]


def read_section(spec=None):
    """The section from the spec if it is readable, else from the committed extract; and where it came from."""
    path = spec or SPEC
    if os.path.exists(path):
        return spec_section(open(path, encoding="utf-8").read().splitlines()), path
    if spec:
        raise SystemExit("%s: no such file" % spec)
    return [l for l in spec_section(open(EXTRACT, encoding="utf-8").read().splitlines()) if not l.startswith("#")], EXTRACT


def parse(section):
    """The decks of the section: dicts with name, types, series, procedure, contact (Standard: node to surface,
    surface to surface, augmented Lagrange; Explicit: kinematic, penalty), kind (run or post), note."""
    decks, procedure, series, constraint = [], None, None, None
    i = 0
    while i < len(section):
        line = section[i]
        m = re.match(r"Abaqus/(Standard|Explicit) input files$", line)
        if m:
            procedure, series, constraint = m.group(1), None, None
        elif line.endswith(":"):
            head, _, tail = line[:-1].partition(", ")
            if head not in SERIES:
                raise SystemExit("unknown series heading %r" % line)
            series = SERIES[head]
            constraint = {"": None, "kinematic mechanical contact": "kinematic", "penalty mechanical contact": "penalty"}[tail]
        elif line.endswith(".inp"):
            name = line[:-4]
            desc = section[i + 1] if i + 1 < len(section) else ""
            i += 1
            if procedure is None or series is None or (procedure == "Explicit") != (constraint is not None):
                raise SystemExit("%s: outside a procedure and series heading" % line)
            d = {"name": name, "procedure": procedure, "series": series, "description": desc, "kind": "run", "note": ""}
            m = re.match(r"(.+?) elements( using surface-to-surface contact)?\.$", desc)
            if m:
                d["types"] = [t.strip() for t in m.group(1).split(",")]
                s2s_desc = bool(m.group(2))
            elif desc == "POST OUTPUT analysis." and name.endswith("_post") and decks and decks[-1]["name"] == name[:-5]:
                d["types"], d["kind"], s2s_desc = decks[-1]["types"], "post", None
            else:
                raise SystemExit("%s: description %r not understood" % (line, desc))
            if d["kind"] == "post":
                d["contact"] = "POST OUTPUT of %s" % decks[-1]["name"]
            elif procedure == "Explicit":
                d["contact"] = constraint
            else:
                # the file name decides (the spec's names are systematic; two descriptions are swapped, noted)
                s2s = "_surf" in name
                d["contact"] = "surface to surface" if s2s else "augmented Lagrange" if "_auglagr" in name else "node to surface"
                if s2s != s2s_desc:
                    d["note"] = "the spec's description says %s" % ("surface to surface" if s2s_desc else "node to surface")
            decks.append(d)
        else:
            raise SystemExit("line not understood: %r" % line)
        i += 1
    return decks


def candidates(d):
    """The test names (without rank suffix) a deck may be registered under, in order of preference."""
    t = "sax2t" if "SAX2T" in d["types"] else d["types"][0].lower()
    if d["kind"] == "post":  # a POST OUTPUT analysis of the deck before it: tests/restart/restart_post.sh
        return ["restart_post_output_" + t]
    if d["procedure"] == "Explicit":
        job = "sliding_%s_explicit_%s_%s" % (d["series"], d["contact"], t)
        return ["explicit_spec_" + job, "explicit_" + job]
    variant = {"surface to surface": "_surf", "augmented Lagrange": "_auglagr"}.get(d["contact"], "")
    if d["name"] in FILM_AMPLITUDE:  # the spec's illustration of a time-dependent film coefficient
        variant = "_filmamp"
    return ["sliding_%s%s_%s" % (d["series"], variant, t)]


def decks_of(spec=None):
    section, source = read_section(spec)
    return parse(section), source


# ---------------------------------------------------------------------------------------------------------------
# ctest: registered tests, labels, ranks; a run's log

def registered(build):
    """name -> {labels, ranks} of every test ctest lists in the build directory. ctest --show-only rewrites
    Testing/Temporary/LastTest.log where it runs, so it runs on a copy of the build's CTestTestfile.cmake files:
    the log of a ctest run in progress (this script is one of its tests) stays whole."""
    with tempfile.TemporaryDirectory() as tmp:
        for top, _, files in os.walk(build):
            if "CTestTestfile.cmake" in files:
                dest = os.path.join(tmp, os.path.relpath(top, build))
                os.makedirs(dest, exist_ok=True)
                shutil.copy(os.path.join(top, "CTestTestfile.cmake"), dest)
        if not os.path.exists(os.path.join(tmp, "CTestTestfile.cmake")):
            raise SystemExit("%s: no CTestTestfile.cmake (not a configured build directory)" % build)
        out = subprocess.run(["ctest", "--show-only=json-v1"], cwd=tmp, check=True, capture_output=True, text=True).stdout
    tests = {}
    for t in json.loads(out)["tests"]:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        command = " ".join(t.get("command", []))
        m = re.search(r"(?:mpiexec|mpirun)\S*'?\s+-n\s+(\d+)", command)
        tests[t["name"]] = {"labels": sorted(props.get("LABELS", [])), "ranks": int(m.group(1)) if m else None,
                            "processors": props.get("PROCESSORS", 1)}
    # a deck's tests by its name: run tests <name>_np<N>, companions <name>_np<N>_<what> and <name>_heat_equals_<type>
    runs, comps = {}, {}
    for n in tests:
        m = re.fullmatch(r"((?:(?!_np\d).)+)_np(\d+)", n)
        if m:
            runs.setdefault(m.group(1), {})[n] = int(m.group(2))
            continue
        m = re.fullmatch(r"((?:(?!_np\d|_heat_equals_).)+)_(np\d+_.+|heat_equals_.+)", n)
        if m:
            comps.setdefault(m.group(1), []).append(n)
    return {"tests": tests, "runs": runs, "companions": comps}


def deck_tests(d, reg):
    """The deck's registered name and its tests: run tests {name: np} and companions [names]."""
    for base in candidates(d):
        if base in reg["runs"]:
            return base, reg["runs"][base], sorted(reg["companions"].get(base, []))
    return None, {}, []


CHECK = re.compile(r"^(?P<name>.+): (?P<value>\S+) \(expected (?P<expected>\S+), (?P<rel>relative )?tolerance (?P<tol>\S+)\) (?P<ok>PASS|FAIL)$")
CHECK_TRUE = re.compile(r"^(?P<text>.+: .*) (?P<ok>PASS|FAIL)$")


def read_logs(paths):
    """name -> {status (Passed, Failed, ...), passed, time, checks} from ctest's LastTest*.log files (a later file
    wins for a test it holds), and the runs' start lines."""
    runs, starts = {}, []
    for path in paths:
        name, out, inside, time, status = None, [], False, None, "Failed"
        for raw in open(path, encoding="utf-8", errors="replace"):
            line = raw.rstrip("\n")
            if line.startswith("Start testing: "):
                starts.append(line[len("Start testing: "):])
            m = re.match(r"^\d+/\d+ Test: (\S+)$", line)
            if m:
                name, out, inside, time, status = m.group(1), [], False, None, "Failed"
                continue
            if name is None:
                continue
            if line == "Output:":
                inside = True
            elif inside:
                if line == "<end of output>":
                    inside = False
                else:
                    out.append(line)
            elif re.match(r"^Test time = +[0-9.]+ sec$", line):
                time = float(line.split()[3])
            elif re.match(r"^Test (Passed|Failed|Not Run)", line):
                status = re.match(r"^Test (Passed|Failed|Not Run)", line).group(1)
            elif line.startswith("Test Fail Reason:"):  # a PASS/FAIL_REGULAR_EXPRESSION decided
                status = "Failed"
            elif line.startswith('"%s" end time: ' % name):
                runs[name] = {"status": status, "passed": status == "Passed", "time": time, "checks": checks_of(out)}
                name = None
    return runs, starts


def checks_of(lines):
    """The check lines of a test's output (tslcheck.check and check_true)."""
    out = []
    for line in lines:
        if line.startswith("-" * 20):
            continue
        m = CHECK.match(line)
        if m:
            out.append({"name": m.group("name"), "value": float(m.group("value")), "expected": float(m.group("expected")),
                        "tol": float(m.group("tol")), "relative": bool(m.group("rel")), "ok": m.group("ok") == "PASS"})
            continue
        m = CHECK_TRUE.match(line)
        if m and not line.startswith(("thermoslide", " ")):  # a check_true line, not the job's log
            out.append({"name": m.group("text"), "value": None, "ok": m.group("ok") == "PASS"})
    return out


# ---------------------------------------------------------------------------------------------------------------
# The table

# The spec's stated outcomes, by the words of the checks that show them (tests/verification/check_sliding.py,
# tests/explicit/check_sliding_explicit.py), in the spec's order; a check matching none counts among the others.
OUTCOMES = [
    ("symmetric", r"symmetric"),
    ("interface heat = flux in", r"heat across the interface = flux in"),
    ("film heat = flux in", r"film heat out = flux in"),
    ("step 4 drop ratio", r"(step 4 / step 3|step 4 drop / step 3 drop)"),
    ("slid-off block isothermal", r"isothermal"),
    ("no interface heat after slide-off", r"(after sliding off|slide-off: heat across)"),
    ("generated", r"dissipation"),
    ("absorbed", r"heat absorbed"),
    ("final temperature", r"final temperature"),
    ("time-dependent film", r"(time-dependent film|film faces' mean temperature)"),
]


def g(x, tol=None):
    """x to 6 significant digits, or as many as a relative tolerance tol needs to show (at most 10)."""
    digits = 6 if not tol else min(10, max(6, int(math.ceil(-math.log10(tol))) + 2))
    return "%.*g" % (digits, x)


def show(c):
    """A check as `measured (expected ± tolerance)`."""
    if c["value"] is None:  # check_true: its text after the name
        text = c["name"]
        m = re.search(r"([-+0-9.eE]+) in \[([-+0-9.eE]+), ([-+0-9.eE]+)\]", text)
        if m:
            return "%s in [%s, %s]" % m.groups()
        m = re.search(r"within \[([-+0-9.eE]+), ([-+0-9.eE]+)\].*: ratio ([-+0-9.eE]+)", text)
        if m:
            return "%s in [%s, %s]" % (m.group(3), m.group(1), m.group(2))
        return text.split(": ", 1)[-1] or "true"
    if c["relative"]:
        tol = "%g %%" % (100 * c["tol"]) if c["tol"] >= 1e-4 else "%g rel." % c["tol"]
        return "%s (%s ± %s)" % (g(c["value"], c["tol"]), g(c["expected"], c["tol"]), tol)
    if c["expected"] == 0:
        return "%.3g (≤ %.3g)" % (c["value"], c["tol"])
    rel = c["tol"] / abs(c["expected"])
    return "%s (%s ± %.3g)" % (g(c["value"], rel), g(c["expected"], rel), c["tol"])


# where several checks show one outcome, what tells them apart (the first pattern that matches)
TAGS = [(r"mean conductances", "vs mean k"), (r"within", "around 4"), (r"ALLFD", "ALLFD"), (r"end of the job", "end of job"),
        (r"friction force x slip path", "= μN × 6"), (r"N about 200", "≈ 120"), (r"coldest", "min"), (r"hottest", "max"),
        (r"^(step \d+)", None)]


def tag(name):
    for pattern, text in TAGS:
        m = re.search(pattern, name)
        if m:
            return text or m.group(1)
    return ""


def outcomes(checks):
    """The stated outcomes shown by a run's checks (`outcome: measured (expected ± tol)`), and the others counted."""
    parts, used = [], set()
    for label, pattern in OUTCOMES:
        got = [k for k, c in enumerate(checks) if k not in used and re.search(pattern, c["name"])]
        used.update(got)
        if got:
            vals = [((tag(checks[k]["name"]) + " ") if len(got) > 1 else "") + show(checks[k]) + ("" if checks[k]["ok"] else " **FAIL**")
                    for k in got]
            parts.append("%s: %s" % (label, "; ".join(v.strip() for v in vals)))
    others = [c for k, c in enumerate(checks) if k not in used]
    failed = [c["name"] for c in others if not c["ok"]]
    if others:
        parts.append("other checks: %d %s" % (len(others), "**failed: %s**" % "; ".join(failed) if failed else "pass"))
    return " · ".join(parts)


def short(name, base):
    return name[len(base) + 1:].replace("_", " ")


def labels_of(run_tests, base, tests):
    """The run tests' labels (their companions share them), without `spec`; per rank count where they differ."""
    groups = {}
    for n in sorted(run_tests, key=run_tests.get):
        groups.setdefault(", ".join(l for l in tests[n]["labels"] if l != "spec"), []).append(short(n, base))
    if len(groups) == 1:
        return next(iter(groups))
    return "; ".join("%s: %s" % (", ".join(v), k) for k, v in groups.items())


def rows(decks, reg, runs):
    tests = reg["tests"]
    out, stats = [], {"mapped": 0, "run": 0, "passed": 0, "failed": 0, "not run": 0, "exception": 0}
    for d in decks:
        base, run_tests, comp = deck_tests(d, reg)
        cells = [d["name"], ", ".join(d["types"]), d["series"], d["contact"] + (" (%s)" % d["note"] if d["note"] else ""), d["procedure"]]
        if not base:
            why = EXCEPTIONS.get(d["name"], "**no counterpart** (not in EXCEPTIONS)")
            stats["exception"] += 1
            out.append(cells + ["none", "", "no counterpart: " + why, ""])
            continue
        stats["mapped"] += 1
        ordered = sorted(run_tests, key=lambda n: run_tests[n])
        names = ordered + comp
        ranks = ", ".join("np%d" % run_tests[n] + ("" if tests[n]["ranks"] in (None, run_tests[n]) else " (-n %d)" % tests[n]["ranks"]) for n in ordered)
        test_cell = "`%s` %s" % (base, ranks) + ("; " + ", ".join(short(n, base) for n in comp) if comp else "")
        inrun = [n for n in names if n in runs]
        if not inrun:
            stats["not run"] += 1
            longs = [n for n in ordered if "long" in tests[n]["labels"]]
            result = "not in this run" + (" (label long)" if longs and len(longs) == len(ordered) else "")
            out.append(cells + [test_cell, labels_of(run_tests, base, tests), result, ""])
            continue
        stats["run"] += 1
        status = ["%s %s" % (short(n, base), "PASS" if runs[n]["passed"] else "**%s**" % runs[n]["status"].upper()) for n in inrun]
        missing = [short(n, base) for n in names if n not in runs]
        if missing:
            status.append("not in this run: " + ", ".join(missing))
        if all(runs[n]["passed"] for n in inrun):
            stats["passed"] += 1
        else:
            stats["failed"] += 1
        shown = next((n for n in ordered if n in runs and runs[n]["checks"]), None)
        what = ""
        if shown:
            what = ("%s: " % short(shown, base) if len(ordered) > 1 else "") + outcomes(runs[shown]["checks"])
        out.append(cells + [test_cell, labels_of(run_tests, base, tests), "; ".join(status), what])
    return out, stats


def table(decks, reg, runs, starts):
    body, stats = rows(decks, reg, runs)
    std = sum(d["procedure"] == "Standard" for d in decks)
    lines = [BEGIN, "",
             "%d spec decks (%d Abaqus/Standard, %d Abaqus/Explicit): %d with a counterpart in the suite, %d without; "
             "`ctest -L spec` lists %d tests, %d of them in the default suite (not `long`). "
             "From the ctest run%s of %s (%d tests): %d decks run, %d passed, %d failed; %d not in this run." % (
                 len(decks), std, len(decks) - std, stats["mapped"], stats["exception"],
                 sum("spec" in t["labels"] for t in reg["tests"].values()),
                 sum("spec" in t["labels"] and "long" not in t["labels"] for t in reg["tests"].values()), "s" if len(starts) > 1 else "",
                 ", ".join(starts) or "?", len(runs), stats["run"], stats["passed"], stats["failed"], stats["not run"]), "",
             "| spec deck | elements | series | contact | procedure | test (ranks; companions) | labels | result | stated outcomes: measured (expected ± tolerance) |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in body:
        lines.append("| " + " | ".join(c.replace("|", "\\|") for c in r) + " |")
    lines += ["", END]
    return "\n".join(lines) + "\n", stats


def update(doc, text):
    src = open(doc, encoding="utf-8").read()
    if src.count(BEGIN) != 1 or src.count(END) != 1:
        raise SystemExit("%s: needs one line %r and one %r" % (doc, BEGIN, END))
    head, rest = src.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    open(doc, "w", encoding="utf-8").write(head + text.rstrip("\n") + tail)


# ---------------------------------------------------------------------------------------------------------------

def option(args, name, default=None):
    if name in args:
        k = args.index(name)
        value = args[k + 1]
        del args[k:k + 2]
        return value
    return default


def main(argv):
    args = list(argv[1:])
    extra = []
    if "--" in args:  # run: more ctest arguments
        args, extra = args[:args.index("--")], args[args.index("--") + 1:]
    if not args:
        raise SystemExit(__doc__)
    cmd = args.pop(0)
    spec = option(args, "--spec")
    build = option(args, "--build")
    doc = option(args, "--update")
    if cmd == "extract":
        section, source = read_section(spec)
        if source == EXTRACT:
            raise SystemExit("the spec is not at %s: give --spec FILE" % SPEC)
        parse(section)  # it must parse
        print("# The \"Input files\" section of the spec (%s), as tests/tools/spec_table.py extract" % os.path.basename(source))
        print("# writes it: the list of decks where the spec is not at hand. spec_table.py check compares it with the")
        print("# spec whenever the spec is readable; do not edit by hand.")
        print("Input files")
        print("\n".join(section))
        return 0
    decks, source = decks_of(spec)
    if cmd == "bases":
        print("\n".join(b for d in decks for b in candidates(d)))
        return 0
    if not build:
        raise SystemExit("--build DIR is needed")
    reg = registered(build)
    tests = reg["tests"]
    if cmd == "check":
        bad = []
        std = sum(d["procedure"] == "Standard" for d in decks)
        print("spec decks: %d (%d Abaqus/Standard, %d Abaqus/Explicit), read from %s" % (len(decks), std, len(decks) - std, source))
        if (len(decks), std) != (212, 154):
            bad.append("the spec lists 212 decks, 154 Standard and 58 Explicit")
        names = [d["name"] for d in decks]
        if len(set(names)) != len(names):
            bad.append("a deck name twice")
        if source != EXTRACT and os.path.exists(EXTRACT):
            kept = [l for l in spec_section(open(EXTRACT, encoding="utf-8").read().splitlines()) if not l.startswith("#")]
            if parse(kept) != decks:
                bad.append("tests/tools/spec_decks.txt differs from the spec: rewrite it with spec_table.py extract")
            else:
                print("tests/tools/spec_decks.txt: the spec's list")
        mapped, used = 0, set()
        for d in decks:
            base, run_tests, comp = deck_tests(d, reg)
            if base:
                mapped += 1
                if base in used:
                    bad.append("%s: its tests %s serve another deck too" % (d["name"], base))
                used.add(base)
                if d["name"] in EXCEPTIONS:
                    bad.append("%s: in EXCEPTIONS but registered as %s" % (d["name"], base))
                for n in list(run_tests) + comp:
                    if "spec" not in tests[n]["labels"]:
                        bad.append("%s: no `spec` label" % n)
                for n, np in run_tests.items():
                    if tests[n]["ranks"] not in (None, np):
                        bad.append("%s: runs on %s ranks" % (n, tests[n]["ranks"]))
            elif d["name"] in EXCEPTIONS:
                print("no counterpart: %s: %s" % (d["name"], EXCEPTIONS[d["name"]]))
            else:
                bad.append("%s: no registered test (%s) and no exception named" % (d["name"], " or ".join(candidates(d)) or "a %s deck" % d["kind"]))
        for name in EXCEPTIONS:
            if name not in names:
                bad.append("EXCEPTIONS names %s, which the spec does not list" % name)
        spec_labelled = sorted(n for n, t in tests.items() if "spec" in t["labels"])
        ours = {n for d in decks for n in (lambda b, r, c: list(r) + c)(*deck_tests(d, reg))}
        for n in spec_labelled:
            if n not in ours:
                bad.append("%s: labelled spec, but no deck's test" % n)
        print("mapped to registered tests: %d; named exceptions: %d; tests labelled spec: %d" % (mapped, len(decks) - mapped, len(spec_labelled)))
        for b in bad:
            print("FAIL: " + b)
        print("FAILED" if bad else "PASS")
        return 1 if bad else 0
    if cmd == "run":
        # ctest -L spec in the build directory (more ctest arguments after --), its log kept as spec_run.log
        jobs = option(args, "-j", "2")
        ctest = ["ctest", "-L", "spec", "-j", jobs, "--output-on-failure"] + extra
        print("in %s: %s" % (build, " ".join(ctest)), flush=True)
        subprocess.run(ctest, cwd=build)  # failed tests are rows of the table, not an error of the script
        args = [os.path.join(build, "spec_run.log")]
        shutil.copy(os.path.join(build, "Testing", "Temporary", "LastTest.log"), args[0])
        cmd = "table"
    if cmd == "table":
        logs = args or [os.path.join(build, "Testing", "Temporary", "LastTest.log")]
        runs, starts = read_logs(logs)
        text, stats = table(decks, reg, runs, starts)
        if doc:
            update(doc, text)
            print("%s: %d rows; %d decks in the run, %d passed, %d failed, %d not in the run" % (
                doc, len(decks), stats["run"], stats["passed"], stats["failed"], stats["not run"]))
        else:
            sys.stdout.write(text)
        return 0
    raise SystemExit(__doc__)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
