#!/usr/bin/env python3
"""docs/cli.md against `metalfit <command> --help` (issue 29 item 7): every long option a subcommand's --help lists is
named in that subcommand's section of docs/cli.md (or in "Materials, outputs and help", which covers every
subcommand), and every option a section's table names is one its --help lists. Exit 1 listing the differences.

    python3 scripts/check-cli-docs.py build/bin/metalfit docs/cli.md
"""
import re
import subprocess
import sys

OPTION = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*)")
GLOBAL = {"--help", "--version", "--data-dir", "--ocio-config"}  # "Global options", accepted by every command
SHARED_SECTION = "Materials, outputs and help"


def sections(markdown):
    """The text of each `## \\`metalfit CMD …\\`` section (its ### subsections included), and the shared section's."""
    out, current = {}, None
    for line in markdown.splitlines():
        heading = re.match(r"^(#+) (.*)", line)
        if heading and len(heading.group(1)) == 2:
            command = re.match(r"`metalfit (\w+)", heading.group(2))
            current = command.group(1) if command else (SHARED_SECTION if SHARED_SECTION in line else None)
        if current:
            out.setdefault(current, []).append(line)
    return {k: "\n".join(v) for k, v in out.items()}


def table_options(text):
    """Options in the first cell of the section's table rows."""
    found = set()
    for line in text.splitlines():
        if line.startswith("| `-"):
            found |= set(OPTION.findall(line.split("|")[1]))
    return found


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    exe, doc = sys.argv[1], sys.argv[2]
    documented = sections(open(doc, encoding="utf-8").read())
    shared = documented.get(SHARED_SECTION, "")
    top = subprocess.run([exe, "--help"], capture_output=True, text=True, check=True).stdout
    commands = re.findall(r"^Subcommands:\n((?:  \S.*\n?)+)", top, re.M)
    names = re.findall(r"^  (\w+)", commands[0], re.M) if commands else []
    if not names:
        sys.exit(f"check-cli-docs: no subcommands in `{exe} --help`")
    problems = []
    for command in names:
        if command not in documented:
            problems.append(f"{command}: no section '## `metalfit {command} …`' in {doc}")
            continue
        helped = set(OPTION.findall(
            subprocess.run([exe, command, "--help"], capture_output=True, text=True, check=True).stdout)) - GLOBAL
        text = documented[command]
        missing = sorted(o for o in helped if o not in set(OPTION.findall(text)) | set(OPTION.findall(shared)))
        stale = sorted(table_options(text) - helped - GLOBAL)
        if missing:
            problems.append(f"{command}: --help lists {', '.join(missing)}, which its section of {doc} does not name")
        if stale:
            problems.append(f"{command}: {doc} documents {', '.join(stale)}, which `metalfit {command} --help` lacks")
    for line in problems:
        print("check-cli-docs: " + line)
    if problems:
        sys.exit(1)
    print(f"check-cli-docs: {len(names)} subcommands, every option of --help named in {doc}")


if __name__ == "__main__":
    main()
