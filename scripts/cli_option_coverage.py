#!/usr/bin/env python3
"""cli_option_coverage.py — every long option of every `conformesh` subcommand is passed by some test.

Runs `conformesh --help`, then `conformesh <cmd> [<sub>] --help` for every subcommand it lists (recursively), extracts
each long option from the option lines, and fails, listing `<cmd> --option`, for every option that appears neither in
a file under tests/ nor in a ```console example of docs/*.md (those are run by the doc_examples CTest). An option
counts as covered when the literal `--option` (not followed by a further name character) occurs; this does not check
that the occurrence belongs to the same subcommand (options such as --json are shared), only that no option is
entirely unexercised. --help is exempt (the script itself passes it).

Usage: cli_option_coverage.py --conformesh BIN --source DIR [--known-gaps FILE]
--known-gaps: a file of `<cmd> --option` lines (# comments) still without a test, each to be given one; an uncovered
option not in it fails, and so does a listed one that is now covered (the list only shrinks).
Exit 0 when every option is covered or a listed gap, 1 listing the others, 2 on bad usage.
"""
import argparse
import pathlib
import re
import subprocess
import sys

OPTION_LINE = re.compile(r"^\s+(?:-\w,)?(--[a-z][a-z0-9-]*)")
SECTION = re.compile(r"^(\w[\w ]*):\s*$")


def help_text(binary, path):
    run = subprocess.run([binary, *path, "--help"], capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        sys.exit(f"cli_option_coverage: `{' '.join(['conformesh', *path, '--help'])}` exited {run.returncode}")
    return run.stdout


def parse(text):
    """(long options, subcommand names) of one help page."""
    options, subcommands, section = [], [], None
    for line in text.splitlines():
        m = SECTION.match(line)
        if m:
            section = m.group(1)
            continue
        if section == "Subcommands":
            sub = re.match(r"^\s+([a-z][a-z0-9-]*)\s", line)
            if sub:
                subcommands.append(sub.group(1))
            continue
        m = OPTION_LINE.match(line)
        if m and m.group(1) != "--help":
            options.append(m.group(1))
    return options, subcommands


def all_options(binary):
    found, stack = [], [[]]
    while stack:
        path = stack.pop()
        options, subcommands = parse(help_text(binary, path))
        found += [(" ".join(path) or "(global)", o) for o in options]
        stack += [path + [s] for s in subcommands]
    return found


def corpus(source, exclude):
    texts = []
    for f in (source / "tests").rglob("*"):
        if exclude and f.resolve() == exclude.resolve():
            continue  # the list of gaps names every option it lists
        if f.is_file() and f.suffix in {".cpp", ".h", ".py", ".cmake", ".txt", ".sh", ".json"}:
            texts.append(f.read_text(errors="replace"))
    for page in (source / "docs").glob("*.md"):
        texts += re.findall(r"```console\n(.*?)```", page.read_text(errors="replace"), re.S)
    return "\n".join(texts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--conformesh", required=True)
    ap.add_argument("--source", required=True, type=pathlib.Path)
    ap.add_argument("--known-gaps", type=pathlib.Path)
    args = ap.parse_args()
    options = all_options(args.conformesh)
    if not options:
        sys.exit("cli_option_coverage: no options parsed from the help pages (format changed?)")
    text = corpus(args.source, args.known_gaps)
    missing = [(c, o) for c, o in options if not re.search(re.escape(o) + r"(?![a-z0-9-])", text)]
    known = set()
    if args.known_gaps:
        for line in args.known_gaps.read_text().splitlines():
            line = line.split("#")[0].strip()
            if line:
                known.add(line)
    missing = {f"{c} {o}" for c, o in missing}
    new, stale = sorted(missing - known), sorted(known - missing)
    print(f"{len(options)} options of {len({c for c, _ in options})} commands, {len(missing)} in no test or doc "
          f"example ({len(missing & known)} of them listed as known gaps)")
    for m in new:
        print(f"  uncovered: {m}")
    for m in stale:
        print(f"  listed as a gap but now covered (or no longer an option), remove it from the list: {m}")
    return 1 if new or stale else 0


if __name__ == "__main__":
    sys.exit(main())
