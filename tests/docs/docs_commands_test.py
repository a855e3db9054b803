#!/usr/bin/env python3
"""Every command the README and docs/*.md show runs, with the exit code the page says.

Usage: docs_commands_test.py --hecal BUILD/bin/hecal --python-path BUILD/python [--slow] [--list]

The rules (docs/README.md, "Commands in these pages run"):
- Commands are the lines of fenced blocks tagged sh, bash, shell, console or untagged that start
  with `hecal `, `build/bin/hecal ` or `python3 ` (a trailing `\\` joins the next line; a leading
  `$ ` is dropped). ```python blocks are code, not commands.
- A `hecal` line with `[`, `|`, `…`, `...` or an upper-case placeholder (`DIR`, `N`, `MM,DEG`)
  is a synopsis, not a command.
- An HTML comment on the line before the fence marks the block: `<!-- exit N -->` (each command
  must end with exit code N, default 0), `<!-- not run: REASON -->` (skipped; the reason is
  required), `<!-- slow -->` (run only with --slow, ctest label `slow`).
- Each page runs its commands in order in a scratch folder of its own, with `data/`, `tests/`,
  `examples/` and `web/` of the repository linked into it, and empty copies of the folders of
  `docs/` as `docs/…` and `out/…`; `hecal` on the
  PATH and `build/bin/hecal` are the built binary, `import hecal` is the built module.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SHELL_TAGS = {"", "sh", "bash", "shell", "console"}
COMMAND = re.compile(r"^(hecal|build/bin/hecal|python3)\s")
PLACEHOLDER = re.compile(r"(^|\s)[A-Z][A-Z0-9_]*(,[A-Z0-9_]+)*(\s|$)")
MARKER = re.compile(r"^<!--\s*(exit\s+(\d+)|not run:\s*(\S.*?)|slow)\s*-->$")
LINKED = ("data", "tests", "examples", "web")


def pages():
    docs = os.path.join(ROOT, "docs")
    return ["README.md"] + sorted(
        os.path.join("docs", name) for name in os.listdir(docs) if name.endswith(".md"))


def is_synopsis(command):
    return any(mark in command for mark in ("[", "|", "…", "...")) or bool(PLACEHOLDER.search(command))


def blocks(text):
    """(line number, tag, marker, lines) of every fenced block."""
    lines = text.split("\n")
    out, i = [], 0
    while i < len(lines):
        fence = re.match(r"^\s*```(\S*)", lines[i])
        if not fence:
            i += 1
            continue
        previous = next((lines[k].strip() for k in range(i - 1, -1, -1) if lines[k].strip()), "")
        marker = MARKER.match(previous)
        start, body = i, []
        i += 1
        while i < len(lines) and not re.match(r"^\s*```\s*$", lines[i]):
            body.append(lines[i])
            i += 1
        out.append((start + 1, fence.group(1), marker, body))
        i += 1
    return out


def commands(body):
    joined, current = [], ""
    for line in body:
        line = line.strip()
        if line.startswith("$ "):
            line = line[2:]
        current = current + " " + line if current else line
        if current.endswith("\\"):
            current = current[:-1].rstrip()
            continue
        joined.append(current)
        current = ""
    return [c for c in joined if COMMAND.match(c)]


def collect():
    """Every command: (page, line, command, kind, expected exit, skip reason)."""
    found = []
    for page in pages():
        with open(os.path.join(ROOT, page), encoding="utf-8") as f:
            text = f.read()
        for line, tag, marker, body in blocks(text):
            if tag not in SHELL_TAGS:
                continue
            kind, code, reason = "unit", 0, None
            if marker and marker.group(2):
                code = int(marker.group(2))
            elif marker and marker.group(3):
                reason = marker.group(3)
            elif marker:
                kind = "slow"
            for command in commands(body):
                if command.startswith(("hecal", "build/bin/hecal")) and is_synopsis(command):
                    continue
                found.append((page, line, command, kind, code, reason))
    return found


def scratch_folder(hecal, base):
    folder = tempfile.mkdtemp(prefix="docs_commands_", dir=base)
    for name in LINKED:
        os.symlink(os.path.join(ROOT, name), os.path.join(folder, name))
    os.makedirs(os.path.join(folder, "out"))
    for parent, _, _ in os.walk(os.path.join(ROOT, "docs")):  # empty: outputs land in the scratch
        below = os.path.relpath(parent, os.path.join(ROOT, "docs"))
        for top in ("docs", "out"):
            os.makedirs(os.path.join(folder, top, below), exist_ok=True)
    os.makedirs(os.path.join(folder, "build", "bin"))
    os.symlink(hecal, os.path.join(folder, "build", "bin", "hecal"))
    return folder


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--hecal", required=True)
    parser.add_argument("--python-path", required=True)
    parser.add_argument("--slow", action="store_true", help="run the <!-- slow --> blocks only")
    parser.add_argument("--list", action="store_true", help="print the commands, run nothing")
    parser.add_argument("--timeout", type=float,
                        help="seconds per command (default 300, with --slow 1800)")
    args = parser.parse_args()
    if args.timeout is None:
        args.timeout = 1800 if args.slow else 300
    hecal = os.path.abspath(args.hecal)
    found = collect()
    if args.list:
        for page, line, command, kind, code, reason in found:
            state = f"not run ({reason})" if reason else f"{kind}, exit {code}"
            print(f"{page}:{line}: [{state}] {command}")
        return 0

    base = tempfile.mkdtemp(prefix="hecal_docs_commands_")
    env = dict(os.environ)
    env["PATH"] = os.path.join(base, "bin") + os.pathsep + env.get("PATH", "")
    env["PYTHONPATH"] = os.path.abspath(args.python_path)
    os.makedirs(os.path.join(base, "bin"))
    os.symlink(hecal, os.path.join(base, "bin", "hecal"))
    wanted = "slow" if args.slow else "unit"
    ran = skipped = other = 0
    failures = []
    folders = {}
    start = time.monotonic()
    try:
        for page, line, command, kind, code, reason in found:
            if reason:
                skipped += 1
                continue
            if kind != wanted:
                other += 1
                continue
            if page not in folders:
                folders[page] = scratch_folder(hecal, base)
            began = time.monotonic()
            try:
                run = subprocess.run(["bash", "-c", command], cwd=folders[page], env=env,
                                     capture_output=True, text=True, timeout=args.timeout)
                status, err = run.returncode, run.stderr
            except subprocess.TimeoutExpired:
                status, err = "timeout", ""
            ran += 1
            seconds = time.monotonic() - began
            print(f"{page}:{line}: exit {status} ({seconds:.1f} s): {command}")
            if status != code:
                failures.append(f"{page}:{line}: `{command}` ended with {status}, the page "
                                f"says {code}\n{err.strip()[-2000:]}")
    finally:
        shutil.rmtree(base, ignore_errors=True)
    print(f"{ran} run, {skipped} not run (marked), {other} left to the "
          f"{'unit' if args.slow else 'slow'} test; {time.monotonic() - start:.1f} s")
    for failure in failures:
        print("FAILED " + failure, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
