#!/usr/bin/env python3
"""doc_examples.py — run the worked examples of docs/*.md and compare what they print with what the docs show.

A worked example is a ```console block: lines starting with "$ " are commands (a trailing backslash continues one),
the lines after a command up to the next "$ " are what it prints (stdout and stderr, as a terminal shows them). Every block of one page runs in order in
one scratch folder, so a later block may use the files an earlier one wrote (docs/cli.md's `uniformize kerr-t0.ply`
reads what `discretize` wrote). `conformesh` is the build's binary, `python3` the interpreter CMake found,
`scripts/` and `docs/` the source tree's, `build/tests/data/meshes/` and bare mesh names (`blade.off`) the test data folder's.
`$ cat FILE` of a file that does not exist yet writes the shown text to FILE (the docs show an input that way).

Compared as printed (strictly: see same_line), except wall-clock figures: a number followed by " s" and every number on a line that starts
with "seconds" (after indentation) or holds `"seconds"`, and the last column of a table headed "... sec"
(`convergence`), are masked. A block whose commands print nothing is run
but not compared; a block in which no command shows output is a recipe (docs/studies.md's long runs) and is not run.
A line "..." in the docs matches any run of lines.
An example that differs only as another x86-64 CPU makes it differ (PORTABLE_RELATIVE, ROUND_OFF) is reported as a note
and does not fail the run unless --strict: the same binary and libraries give other round-off on an AMD EPYC than on
the Intel Xeon the pages were written on (not OpenBLAS's kernel choice: OPENBLAS_CORETYPE does not move them), and a
tie broken the other way moves discrete outcomes slightly (2 of 8327 vertices). A command must exit 0 unless the docs show its error
("error:" in its output) or its exit status (`; echo "exit status $?"`).

  doc_examples.py --conformesh BIN --data DIR [--python PY] [--update] [--strict] docs/cli.md ...

Exit 0 when every page matches; 1 with a unified diff per mismatching block (page and line named); 2 for bad usage.
--update rewrites the docs' outputs of the examples that fail (with --strict: of every one that differs) with what the build prints (review the diff, then commit it with the change that
moved the numbers).
"""
import argparse
import difflib
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

TIME = re.compile(r"(?<![\w.])[-+]?\d+(\.\d+)?([eE][-+]?\d+)? ?s\b")
NUMBER = re.compile(r"[-+]?\d+(\.\d+)?([eE][-+]?\d+)?")


def parse_blocks(text):
    """[(first line, [(command, [expected lines], its line number, index of its first output line)], end)]."""
    blocks, lines, i = [], text.split("\n"), 0
    while i < len(lines):
        if lines[i].strip() != "```console":
            i += 1
            continue
        start, i, cmds = i + 1, i + 1, []
        while i < len(lines) and lines[i].strip() != "```":
            line = lines[i]
            if line.startswith("$ "):
                cmd, at = line[2:], i + 1
                while cmd.endswith("\\") and i + 1 < len(lines):
                    i += 1
                    cmd = cmd + "\n" + lines[i]
                cmds.append((cmd, [], at, i + 1))
            elif cmds:
                cmds[-1][1].append(line)
            i += 1
        blocks.append((start, cmds, i))
        i += 1
    return blocks


def significant_digits(text):
    return len(re.sub(r"[eE].*$", "", text).lstrip("+-").replace(".", "").lstrip("0"))


# Cross-machine precision (the second tier of same_line): a figure may move by 1e-3 relative (the largest seen between
# the two CPUs: e_G 2.7446e-3 -> 2.7469e-3, 8.4e-4), and a round-off figure — both |x| below ROUND_OFF, a residual or
# an error at machine precision — by a factor of 10 either way or to the other sign. Index of the element where such a
# round-off maximum sits (`edge 224`) is free.
PORTABLE_RELATIVE = 1e-3
ROUND_OFF = 1e-9
ELEMENT_INDEX = re.compile(r"\b(edge|vertex|face|triangle) $")


def same_number(e, a, portable):
    """Two printed figures. Strict: equal text, or both printed with 15 or more significant digits (%.17g round trips)
    and within 1e-12 relative (their last digits are round-off, far below any tolerance the docs discuss, 1e-10 and
    above). Portable: also the cross-machine tier above."""
    if e == a:
        return True
    x, y = float(e), float(a)
    if min(significant_digits(e), significant_digits(a)) >= 15 and abs(x - y) <= 1e-12 * max(abs(x), abs(y)):
        return True
    if not portable:
        return False
    if abs(x) < ROUND_OFF and abs(y) < ROUND_OFF:
        return x == 0 == y or (x != 0 and y != 0 and abs(math.log10(abs(x) / abs(y))) <= 1)
    return abs(x - y) <= PORTABLE_RELATIVE * max(abs(x), abs(y))


def same_line(expected, actual, portable=False):
    """Equal lines up to same_number on each figure (the text between figures equal)."""
    if expected == actual:
        return True
    e_it, a_it = list(NUMBER.finditer(expected)), list(NUMBER.finditer(actual))
    if len(e_it) != len(a_it) or NUMBER.sub("#", expected) != NUMBER.sub("#", actual):
        return False
    round_off_line = portable and any(abs(float(m.group(0))) < ROUND_OFF and float(m.group(0)) != 0 for m in e_it)
    for em, am in zip(e_it, a_it):
        if round_off_line and ELEMENT_INDEX.search(expected[:em.start()]):
            continue
        if not same_number(em.group(0), am.group(0), portable):
            return False
    return True


def normalize(line):
    stripped = line.lstrip()
    if stripped.startswith("seconds") or '"seconds"' in line or "_seconds" in line:
        return NUMBER.sub("#", line)
    return TIME.sub("# s", line)


def normalize_lines(lines):
    """normalize() per line; in a table whose header's last column is "sec" (convergence), each row's last number."""
    out, timed = [], False
    for line in lines:
        if line.rstrip().endswith(" sec"):
            timed = True
        elif timed and re.match(r"\s*\d", line):
            line = re.sub(r"\s*\S+\s*$", " #", line)
        else:
            timed = False
        out.append(normalize(line))
    return out


def matches(expected, actual, portable=False):
    """Line-by-line equality (lines already normalized; same_line), with "..." matching any run of lines."""
    if not expected:
        return not actual
    if expected[0].strip() == "...":
        return any(matches(expected[1:], actual[k:], portable) for k in range(len(actual) + 1))
    return (bool(actual) and same_line(expected[0], actual[0], portable) and
            matches(expected[1:], actual[1:], portable))


def scratch_folder(args):
    work = tempfile.mkdtemp(prefix="conformesh-doc-")
    bin_dir = os.path.join(work, ".bin")
    os.makedirs(bin_dir)
    os.symlink(os.path.abspath(args.conformesh), os.path.join(bin_dir, "conformesh"))
    os.symlink(args.python, os.path.join(bin_dir, "python3"))
    source = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    os.symlink(os.path.join(source, "scripts"), os.path.join(work, "scripts"))
    os.symlink(os.path.join(source, "docs"), os.path.join(work, "docs"))
    os.makedirs(os.path.join(work, "build", "tests", "data"))
    os.makedirs(os.path.join(work, "build", "apps"))
    os.symlink(os.path.abspath(args.conformesh), os.path.join(work, "build", "apps", "conformesh"))
    os.symlink(os.path.abspath(args.data), os.path.join(work, "build", "tests", "data", "meshes"))
    for name in os.listdir(args.data):
        os.symlink(os.path.join(os.path.abspath(args.data), name), os.path.join(work, name))
    return work, bin_dir


def run_command(cmd, expected, work, env):
    cat = re.fullmatch(r"cat (\S+)", cmd.strip())
    if cat and not os.path.exists(os.path.join(work, cat.group(1))):
        with open(os.path.join(work, cat.group(1)), "w") as f:
            f.write("\n".join(expected).rstrip("\n") + "\n")
        return list(expected), 0, ""
    p = subprocess.run(["bash", "-c", cmd], cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True)
    out = p.stdout.split("\n")
    if out and out[-1] == "":
        out.pop()
    return out, p.returncode, p.stdout


def check_page(path, args):
    with open(path) as f:
        text = f.read()
    work, bin_dir = scratch_folder(args)
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""), MPLBACKEND="Agg")
    failures, notes, replacements = 0, 0, []
    try:
        for start, cmds, end in parse_blocks(text):
            if not any(expected for _, expected, _, _ in cmds):
                continue  # a recipe (docs/studies.md's long runs), not an example: nothing to compare
            for cmd, expected, at, out_at in cmds:
                actual, rc, err = run_command(cmd, expected, work, env)
                # An example of an error shows it: its non-zero exit is the point, what it prints is compared.
                allowed_failure = "exit status $?" in cmd or any("error:" in line for line in expected)
                if rc != 0 and not allowed_failure:
                    print(f"{path}:{at}: `{cmd}` exited {rc}\n{err}", file=sys.stderr)
                    failures += 1
                    continue
                if expected and not matches(normalize_lines(expected), normalize_lines(actual)):
                    portable = matches(normalize_lines(expected), normalize_lines(actual), portable=True)
                    if portable and not args.strict:
                        notes += 1
                        head = f"{path}:{at} (docs; matches to cross-machine precision only)"
                    else:
                        failures += 1
                        head = f"{path}:{at} (docs)"
                        replacements.append((out_at, len(expected), actual))
                    diff = difflib.unified_diff(expected, actual, head, "the build prints", lineterm="")
                    print("\n".join(diff), file=sys.stderr)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if args.update and replacements:
        lines = text.split("\n")
        for out_at, n, actual in sorted(replacements, reverse=True):
            lines[out_at:out_at + n] = actual
        with open(path, "w") as f:
            f.write("\n".join(lines))
        print(f"{path}: outputs rewritten from the build", file=sys.stderr)
    return failures, notes


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--conformesh", required=True, help="the conformesh binary")
    ap.add_argument("--data", required=True, help="the test data folder (CGAL's meshes)")
    ap.add_argument("--python", default=sys.executable, help="interpreter for the docs' python3 (default: this one)")
    ap.add_argument("--update", action="store_true", help="rewrite the docs' outputs with what the build prints")
    ap.add_argument("--strict", action="store_true",
                    help="fail on examples that match only to cross-machine precision (same machine as the pages)")
    ap.add_argument("pages", nargs="+", help="docs/*.md pages")
    args = ap.parse_args()
    for p in [args.conformesh, args.data] + args.pages:
        if not os.path.exists(p):
            print(f"doc_examples: {p}: no such file", file=sys.stderr)
            return 2
    counts = [check_page(p, args) for p in args.pages]
    failures, notes = sum(c[0] for c in counts), sum(c[1] for c in counts)
    print(f"doc_examples: {len(args.pages)} pages, {failures} mismatching examples, {notes} matching to cross-machine "
          f"precision only" + ("" if args.strict else " (--strict fails on those)"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
