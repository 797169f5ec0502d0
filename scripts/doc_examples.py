#!/usr/bin/env python3
"""doc_examples.py — run the worked examples of docs/*.md and compare what they print with what the docs show.

A worked example is a ```console block: lines starting with "$ " are commands (a trailing backslash continues one),
the lines after a command up to the next "$ " are what it prints (stdout and stderr, as a terminal shows them). Every block of one page runs in order in
one scratch folder, so a later block may use the files an earlier one wrote (docs/cli.md's `uniformize kerr-t0.ply`
reads what `discretize` wrote). `conformesh` is the build's binary, `python3` the interpreter CMake found,
`scripts/` and `docs/` the source tree's, `build/tests/data/meshes/` and bare mesh names (`blade.off`) the test data folder's.
`$ cat FILE` of a file that does not exist yet writes the shown text to FILE (the docs show an input that way).

Compared as printed, except wall-clock figures: a number followed by " s" and every number on a line that starts
with "seconds" (after indentation) or holds `"seconds"`, and the last column of a table headed "... sec"
(`convergence`), are masked. A block whose commands print nothing is run
but not compared; a block in which no command shows output is a recipe (docs/studies.md's long runs) and is not run.
A line "..." in the docs matches any run of lines. A command must exit 0 unless the docs show its error
("error:" in its output) or its exit status (`; echo "exit status $?"`).

  doc_examples.py --conformesh BIN --data DIR [--python PY] [--update] docs/cli.md ...

Exit 0 when every page matches; 1 with a unified diff per mismatching block (page and line named); 2 for bad usage.
--update rewrites the docs' outputs with what the build prints (review the diff, then commit it with the change that
moved the numbers).
"""
import argparse
import difflib
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


def same_line(expected, actual):
    """Equal lines, except that two numbers both printed with 15 or more significant digits (%.17g round trips) need
    only agree to 1e-12 relative: their last digits follow the kernels OpenBLAS picks for the CPU (CHOLMOD's supernodal
    solves), not the code. 1e-12 is far below any figure the docs discuss (tolerances 1e-10 and above)."""
    if expected == actual:
        return True
    e_nums, a_nums = [m.group(0) for m in NUMBER.finditer(expected)], [m.group(0) for m in NUMBER.finditer(actual)]
    if len(e_nums) != len(a_nums) or NUMBER.sub("#", expected) != NUMBER.sub("#", actual):
        return False
    for e, a in zip(e_nums, a_nums):
        if e == a:
            continue
        if min(significant_digits(e), significant_digits(a)) < 15:
            return False
        x, y = float(e), float(a)
        if abs(x - y) > 1e-12 * max(abs(x), abs(y)):
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


def matches(expected, actual):
    """Line-by-line equality (lines already normalized; same_line), with "..." matching any run of lines."""
    if not expected:
        return not actual
    if expected[0].strip() == "...":
        return any(matches(expected[1:], actual[k:]) for k in range(len(actual) + 1))
    return bool(actual) and same_line(expected[0], actual[0]) and matches(expected[1:], actual[1:])


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
    failures, replacements = 0, []
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
                    failures += 1
                    diff = difflib.unified_diff(expected, actual, f"{path}:{at} (docs)", "the build prints", lineterm="")
                    print("\n".join(diff), file=sys.stderr)
                    replacements.append((out_at, len(expected), actual))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if args.update and failures:
        lines = text.split("\n")
        for out_at, n, actual in sorted(replacements, reverse=True):
            lines[out_at:out_at + n] = actual
        with open(path, "w") as f:
            f.write("\n".join(lines))
        print(f"{path}: outputs rewritten from the build", file=sys.stderr)
    return failures


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--conformesh", required=True, help="the conformesh binary")
    ap.add_argument("--data", required=True, help="the test data folder (CGAL's meshes)")
    ap.add_argument("--python", default=sys.executable, help="interpreter for the docs' python3 (default: this one)")
    ap.add_argument("--update", action="store_true", help="rewrite the docs' outputs with what the build prints")
    ap.add_argument("pages", nargs="+", help="docs/*.md pages")
    args = ap.parse_args()
    for p in [args.conformesh, args.data] + args.pages:
        if not os.path.exists(p):
            print(f"doc_examples: {p}: no such file", file=sys.stderr)
            return 2
    failures = sum(check_page(p, args) for p in args.pages)
    print(f"doc_examples: {len(args.pages)} pages, {failures} mismatching examples")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
