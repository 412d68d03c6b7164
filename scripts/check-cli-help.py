#!/usr/bin/env python3
"""--help as a user reads it (issue 33 item 5): every line of `metalfit --help`, of each subcommand's --help and of
`glpreview --help` fits 100 columns (code points); each subcommand's --help ends with one example,
`Example: metalfit <command> ...`, and that example runs as written (exit 0) in an empty folder, except `bench`
(a minute of timings; its example is checked to name the subcommand only).
Usage: check-cli-help.py METALFIT [GLPREVIEW]. Exit 1 listing every problem."""
import os
import re
import shlex
import subprocess
import sys
import tempfile

COLUMNS = 100
NOT_RUN = {"bench": "a minute of timings"}


def long_lines(text, where):
    return [f"{where}: line {i + 1} has {len(line)} columns: {line[:60]}..."
            for i, line in enumerate(text.splitlines()) if len(line) > COLUMNS]


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    exe = os.path.abspath(sys.argv[1])
    problems = []
    top = subprocess.run([exe, "--help"], capture_output=True, text=True, check=True).stdout
    problems += long_lines(top, "metalfit --help")
    commands = re.findall(r"^Subcommands:\n((?:  \S.*\n?(?:   +\S.*\n?)*)+)", top, re.M)
    names = re.findall(r"^  (\w+)", commands[0], re.M) if commands else []
    if not names:
        sys.exit(f"check-cli-help: no subcommands in `{exe} --help`")
    ran = 0
    with tempfile.TemporaryDirectory(prefix="cli-help-") as work:
        for command in names:
            text = subprocess.run([exe, command, "--help"], capture_output=True, text=True, check=True).stdout
            problems += long_lines(text, f"metalfit {command} --help")
            examples = re.findall(r"^Example: metalfit (.+)$", text, re.M)
            if len(examples) != 1:
                problems.append(f"metalfit {command} --help: {len(examples)} example lines (expected one)")
                continue
            args = shlex.split(examples[0])
            if args[0] != command:
                problems.append(f"metalfit {command} --help: its example runs `{args[0]}`")
                continue
            if command in NOT_RUN:
                continue
            folder = os.path.join(work, command)
            os.makedirs(folder)
            run = subprocess.run([exe] + args, cwd=folder, capture_output=True, text=True)
            if run.returncode != 0:
                problems.append(f"metalfit {examples[0]}: exit {run.returncode}: {run.stderr.strip()[:200]}")
            ran += 1
    if len(sys.argv) == 3:
        text = subprocess.run([sys.argv[2], "--help"], capture_output=True, text=True, check=True).stdout
        problems += long_lines(text, "glpreview --help")
    if problems:
        print("\n".join(problems))
        sys.exit(1)
    print(f"check-cli-help: {len(names)} subcommands within {COLUMNS} columns, {ran} examples run "
          f"({', '.join(f'{c}: not run, {why}' for c, why in NOT_RUN.items())})")


if __name__ == "__main__":
    main()
