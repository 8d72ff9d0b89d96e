#!/usr/bin/python3
"""Mutation testing of thermoslide's deck reader and solver ("test as a stranger would").

Takes working decks, applies one random mutation at a time (a line deleted, duplicated or swapped; a
number replaced by 0, -1, a huge or tiny value, NaN, Inf or text; a field dropped or added; a keyword
parameter removed or given a bad value; an element type exchanged; the file truncated; CRLF endings;
a very long line; bytes that are not UTF-8; an *INCLUDE of a missing file), runs each mutant under a
time limit and classifies what happened. A mutant may run or fail, but never:

  CRASH    the process died on a signal, or PETSc printed a stack trace / "Caught signal"
  HANG     it ran past the time limit (a limit of several times the unmutated deck's run); an explicit run
           still printing its progress lines is listed as SLOW instead, for a look, and not counted
  SILENT   it failed (non-zero exit) without a "thermoslide: error:" line
  NOLINE   a deck error ("error: <deck>:") whose line number is 0 or missing when the mutant had a line
  MIXED    it completed (exit 0) but printed an error line

A share of the mutants (--options, default 0.2) also get one to three command-line options with odd values
(negative tolerances, zero cutbacks, unknown solver types, ...), which must be refused or honoured the same way.

usage: fuzz_deck.py THERMOSLIDE OUTDIR [--seed S] [--count N] [--np P] [--timeout-factor F] [--options F] DECK...
Prints one line per finding and a summary; exits 1 if any finding. Reproduce a finding with the mutant
kept in OUTDIR (the file named in the line) and the same command.
"""
import os
import random
import re
import shutil
import subprocess
import sys
import time

NUM = re.compile(r"(?<![A-Za-z_])[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?")
BAD_NUMBERS = ["0", "-1", "1e300", "-1e300", "1e-300", "nan", "inf", "-inf", "abc", "", "99999999999", "3.5", "1,2", "0x10", "1e", "--1"]
TYPES = ["CPE4T", "CPE4RT", "CPE8T", "CPE3T", "CPS4T", "CAX4T", "CGAX4T", "C3D8T", "C3D8RT", "C3D4T", "C3D10MT", "SC8RT", "CPE4", "C3D8", "S4R", "XYZ"]
KEYWORDS = ["*STEP", "*END STEP", "*NODE", "*ELEMENT, TYPE=CPE4T, ELSET=X", "*BOUNDARY", "*MATERIAL, NAME=M", "*CONTACT PAIR, INTERACTION=I",
            "*SURFACE INTERACTION, NAME=I", "*GAP CONDUCTANCE", "*FRICTION", "*DSLOAD", "*CFLUX", "*AMPLITUDE, NAME=A", "*NSET, NSET=N",
            "*ELSET, ELSET=E", "*SURFACE, NAME=S", "*OUTPUT, FIELD", "*NODE OUTPUT", "*HEADING", "*RESTART, WRITE", "*UNKNOWN KEYWORD",
            "*COUPLED TEMPERATURE-DISPLACEMENT", "*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT", "*INITIAL CONDITIONS, TYPE=TEMPERATURE"]


def mutate(lines, rng):
    """One mutation of the deck's lines: returns (lines, description)."""
    n = len(lines)
    data = [i for i, l in enumerate(lines) if l.strip() and not l.lstrip().startswith("*")]
    keys = [i for i, l in enumerate(lines) if l.lstrip().startswith("*") and not l.lstrip().startswith("**")]
    op = rng.choice(["delete", "duplicate", "swap", "number", "number", "number", "dropfield", "addfield", "param", "param", "keyword",
                     "type", "truncate", "insert", "crlf", "longline", "bytes", "include", "blankfield", "case", "scale", "scale", "scale"])
    out = list(lines)
    if op == "delete" and n:
        i = rng.randrange(n)
        del out[i]
        return out, f"delete line {i + 1}"
    if op == "duplicate" and n:
        i = rng.randrange(n)
        out.insert(i, out[i])
        return out, f"duplicate line {i + 1}"
    if op == "swap" and n > 1:
        i = rng.randrange(n - 1)
        out[i], out[i + 1] = out[i + 1], out[i]
        return out, f"swap lines {i + 1},{i + 2}"
    if op in ("number", "dropfield", "addfield", "blankfield", "scale") and data:
        i = rng.choice(data)
        l = out[i].rstrip("\n")
        if op == "scale":  # a valid number, scaled: reaches the solver more often than garbage does
            ms = [m for m in NUM.finditer(l) if "." in m.group(0) or "e" in m.group(0).lower()]
            if ms:
                m = rng.choice(ms)
                f = rng.choice([-1, 0, 1e-9, 1e-3, 0.1, 0.5, 2, 10, 1e3, 1e9])
                new = repr(float(m.group(0).replace("d", "e").replace("D", "e")) * f)
                out[i] = l[: m.start()] + new + l[m.end():] + "\n"
                return out, f"line {i + 1}: {m.group(0)!r} -> {new!r}"
        if op == "number":
            ms = list(NUM.finditer(l))
            if ms:
                m = rng.choice(ms)
                new = rng.choice(BAD_NUMBERS)
                out[i] = l[: m.start()] + new + l[m.end():] + "\n"
                return out, f"line {i + 1}: {m.group(0)!r} -> {new!r}"
        f = l.split(",")
        if op == "dropfield" and len(f) > 1:
            k = rng.randrange(len(f))
            del f[k]
            out[i] = ",".join(f) + "\n"
            return out, f"line {i + 1}: field {k + 1} dropped"
        if op == "addfield":
            out[i] = l + ", " + rng.choice(["1", "0", "-5", "x", "1e10"]) + "\n"
            return out, f"line {i + 1}: field added"
        if op == "blankfield" and len(f) > 1:
            k = rng.randrange(len(f))
            f[k] = " "
            out[i] = ",".join(f) + "\n"
            return out, f"line {i + 1}: field {k + 1} blank"
    if op in ("param", "keyword", "type", "case") and keys:
        i = rng.choice(keys)
        l = out[i].rstrip("\n")
        parts = [p for p in l.split(",")]
        if op == "param" and len(parts) > 1:
            k = rng.randrange(1, len(parts))
            choice = rng.randrange(3)
            if choice == 0:
                del parts[k]
                what = "removed"
            elif choice == 1:
                name = parts[k].split("=")[0]
                parts[k] = name + "=" + rng.choice(["", "-1", "0", "1e300", "nan", "XYZ", "NOSUCH", "2.5"])
                what = "bad value"
            else:
                parts[k] = parts[k].split("=")[0]
                what = "value dropped"
            out[i] = ",".join(parts) + "\n"
            return out, f"line {i + 1}: parameter {k} {what}: {out[i].strip()!r}"
        if op == "keyword":
            del out[i]
            return out, f"keyword line {i + 1} removed"
        if op == "type" and "TYPE=" in l.upper() and l.upper().lstrip().startswith("*ELEMENT"):
            t = rng.choice(TYPES)
            out[i] = re.sub(r"(?i)TYPE\s*=\s*[A-Z0-9]+", "TYPE=" + t, l) + "\n"
            return out, f"line {i + 1}: element type -> {t}"
        if op == "case":
            out[i] = (l.lower() if rng.random() < 0.5 else l.replace(",", " , ").replace("=", " = ")) + "\n"
            return out, f"line {i + 1}: case/spacing changed"
    if op == "truncate" and n > 2:
        i = rng.randrange(1, n)
        return out[:i], f"truncated after line {i}"
    if op == "insert":
        i = rng.randrange(n + 1)
        out.insert(i, rng.choice(KEYWORDS) + "\n")
        return out, f"keyword inserted at line {i + 1}: {out[i].strip()!r}"
    if op == "crlf":
        return [l.rstrip("\n") + "\r\n" for l in out], "CRLF line endings"
    if op == "longline" and data:
        i = rng.choice(data)
        out[i] = out[i].rstrip("\n") + ("," + "1.0" * 3) * 5000 + "\n"
        return out, f"line {i + 1}: 20 000 more characters"
    if op == "bytes" and n:
        i = rng.randrange(n)
        out[i] = "\udcff\udcfe" + out[i]
        return out, f"line {i + 1}: bytes 0xff 0xfe in front"
    if op == "include":
        i = rng.randrange(n + 1)
        out.insert(i, "*INCLUDE, INPUT=no_such_file.inp\n")
        return out, f"*INCLUDE of a missing file at line {i + 1}"
    return mutate(lines, rng)


OPTIONS = {"-tsl_atol_rel": ["0", "-1", "1", "1e-30", "nan"], "-tsl_block_solves": ["0", "1", "2", "x"], "-tsl_contact_augment_tol": ["0", "-1", "1e9"],
           "-tsl_contact_max_its": ["0", "1", "-3"], "-tsl_cutback": ["0", "1", "2", "-0.5", "1e-9"], "-tsl_direct_max_dofs": ["0", "-1", "1000000000"],
           "-tsl_easy_its": ["0", "-1", "1000"], "-tsl_explicit_contact_search": ["0", "1", "-1"], "-tsl_explicit_history": ["0", "1", "-1", "100000"],
           "-tsl_explicit_kinematic_passes": ["0", "1", "-1"], "-tsl_explicit_kinematic_tol": ["0", "-1", "1"], "-tsl_explicit_progress": ["0", "-1", "1"],
           "-tsl_explicit_records": ["0", "1"], "-tsl_explicit_safety": ["0", "-1", "1e9", "1e-9", "nan"], "-tsl_fallback_its": ["0", "1"],
           "-tsl_fallback_max_dofs": ["0", "-1"], "-tsl_growth": ["0", "1", "-2", "1e9"], "-tsl_implicit_records": ["0", "1"],
           "-tsl_linear_forcing": ["0", "-1", "1", "1e9"], "-tsl_output_sync": ["0", "-1", "1e9"], "-tsl_rtol": ["0", "-1", "1", "nan"],
           "-tsl_contact_margin": ["0", "-1", "1e-12", "1e30"], "-tsl_contact_rebuild": ["0", "-1", "1"], "-tsl_partition": ["axis_x", "axis_y", "none", "xyz"],
           "-ksp_type": ["cg", "preonly", "nonsense"], "-pc_type": ["none", "jacobi", "lu", "nonsense"], "-snes_max_it": ["0", "1"],
           "-ksp_max_it": ["0", "1"], "-snes_type": ["ksponly", "nonsense"]}


def mutate_options(rng):
    """One to three command-line options with odd values."""
    opts = []
    for _ in range(rng.randrange(1, 4)):
        k = rng.choice(sorted(OPTIONS))
        opts += [k, rng.choice(OPTIONS[k])]
    return opts


def run(exe, deck, outdir, np, limit, opts=()):
    cmd = ["mpirun", "-n", str(np), exe, deck, "-o", os.path.join(outdir, "res")] if np > 1 else [exe, deck, "-o", os.path.join(outdir, "res")]
    cmd += list(opts)
    t0 = time.time()
    try:
        p = subprocess.run(cmd, cwd=outdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=limit)
        return p.returncode, p.stdout.decode("utf-8", "replace"), time.time() - t0
    except subprocess.TimeoutExpired as e:
        subprocess.run(["pkill", "-9", "-f", os.path.join(outdir, "res")], stderr=subprocess.DEVNULL)
        return None, (e.stdout or b"").decode("utf-8", "replace"), time.time() - t0


def classify(rc, log, deckname):
    if rc is None:  # past the limit: hung, or an explicit step still reporting its progress (a mutated mesh or
        # period can legitimately ask for many more increments: listed for a look, not counted as a finding)
        return "SLOW" if re.search(r"increment \d+: step time .* s left", log) else "HANG"
    if rc < 0 or rc >= 128 or "Caught signal" in log or "Segmentation" in log or "signal 11" in log or "signal 6" in log:
        return "CRASH"
    if "PETSC ERROR" in log and "thermoslide: error:" not in log:
        return "CRASH"
    err = [l for l in log.splitlines() if "thermoslide: error:" in l]
    if rc != 0 and not err:
        return "SILENT"
    if rc == 0 and err:
        return "MIXED"
    for l in err:
        m = re.search(re.escape(deckname) + r":(\d+)?", l)
        if m and (m.group(1) is None or m.group(1) == "0") and "cannot open" not in l and "the deck is empty" not in l:
            return "NOLINE"
    return None


def main(argv):
    args, decks = {}, []
    it = iter(argv[3:])
    for a in it:
        if a.startswith("--"):
            args[a[2:]] = next(it)
        else:
            decks.append(a)
    exe, out = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    seed, count, np = int(args.get("seed", 1)), int(args.get("count", 50)), int(args.get("np", 1))
    factor = float(args.get("timeout-factor", 6))
    os.makedirs(out, exist_ok=True)
    rng = random.Random(seed)
    findings, tally = [], {}
    for deck in decks:
        with open(deck, encoding="utf-8", errors="surrogateescape") as f:
            lines = f.readlines()
        base_dir = os.path.join(out, "base")
        shutil.rmtree(base_dir, ignore_errors=True)
        os.makedirs(base_dir)
        shutil.copy(deck, os.path.join(base_dir, "deck.inp"))
        rc, log, t = run(exe, "deck.inp", base_dir, np, 600)
        limit = max(20.0, factor * t)
        print(f"# {deck}: unmutated exit {rc} in {t:.1f} s; limit {limit:.0f} s", flush=True)
        stem = os.path.splitext(os.path.basename(deck))[0]
        for k in range(count):
            mlines, what, opts = lines, [], []
            if rng.random() < float(args.get("options", 0.2)):
                opts = mutate_options(rng)
                what.append("options " + " ".join(opts))
            for _ in range(rng.choice([0, 1, 1, 1, 2, 3]) if opts else rng.choice([1, 1, 1, 2, 3])):
                mlines, w = mutate(mlines, rng)
                what.append(w)
            what = "; ".join(what)
            d = os.path.join(out, f"{stem}.{seed}.{k}")
            shutil.rmtree(d, ignore_errors=True)
            os.makedirs(d)
            name = "deck.inp"
            with open(os.path.join(d, name), "w", encoding="utf-8", errors="surrogateescape", newline="") as f:
                f.writelines(mlines)
            rc, log, t = run(exe, name, d, np, limit, opts)
            with open(os.path.join(d, "log.txt"), "w") as f:
                f.write(f"# {what}\n# options {' '.join(opts)}\n# exit {rc} in {t:.2f} s\n" + log)
            c = classify(rc, log, name)
            tally[c or ("ok" if rc == 0 else "refused")] = tally.get(c or ("ok" if rc == 0 else "refused"), 0) + 1
            if c == "SLOW":
                print(f"SLOW {d}/deck.inp ({what}; still progressing after {t:.1f} s; not a finding)", flush=True)
            elif c:
                findings.append(f"{c} {d}/deck.inp ({what}; exit {rc}, {t:.1f} s)")
                print(findings[-1], flush=True)
            else:
                shutil.rmtree(d, ignore_errors=True)
    print("# summary: " + ", ".join(f"{k} {v}" for k, v in sorted(tally.items())))
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
