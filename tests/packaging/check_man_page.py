#!/usr/bin/env python3
"""ctest packaging.man_page: the man page renders with man-db (`man -l`, which runs groff)
without a warning, has a section per subcommand, and names every subcommand and every flag
that `pita --help` and each `pita SUBCOMMAND --help` print. The flags are read from --help's
output here, not from the generator's code.
Usage: check_man_page.py PITA MAN_PAGE
"""
import os
import re
import subprocess
import sys

pita, page = sys.argv[1:3]


def run(command, env=None):
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} exited {result.returncode}:\n{result.stderr}")
    return result


def help_text(*args):
    return run([pita, *args, "--help"]).stdout


def subcommands(text):
    """The names in the "Subcommands:" block of pita --help (up to its first empty line)."""
    names = []
    block = text.split("\nSubcommands:\n", 1)
    if len(block) < 2:
        sys.exit("pita --help has no Subcommands: block")
    for line in block[1].splitlines():
        if not line.strip():
            break
        match = re.match(r"^  (\S+)\s", line)
        if match:
            names.append(match.group(1))
    return names


def flags(text):
    """Every -x and --long-name in the option lines of a --help (the lines that start with
    two spaces and a dash, and the Excludes/Needs they carry)."""
    found = set()
    for line in text.splitlines():
        if re.match(r"^  +-", line):
            found.update(re.findall(r"(?<![\w-])(--?[A-Za-z][\w-]*)", line))
    return {f for f in found if re.fullmatch(r"-[A-Za-z]|--[a-z][a-z0-9-]*", f)}


environment = dict(os.environ, MANWIDTH="200", LANG="C.UTF-8", LC_ALL="C.UTF-8")
rendered = run(["man", "--warnings", "-l", page], env=environment)
if rendered.stderr.strip():
    sys.exit(f"man --warnings -l {page} warns:\n{rendered.stderr}")
text = rendered.stdout
# man-db drops the overstrike of bold and underline when its output is not a terminal;
# remove any that is left.
text = re.sub(r".\x08", "", text)

main_help = help_text()
names = subcommands(main_help)
if len(names) < 8:
    sys.exit(f"pita --help lists only {names}")
missing = []
for name in names:
    if not re.search(rf"^PITA {name.upper()}$", text, re.MULTILINE):
        missing.append(f"section PITA {name.upper()}")
for flag in sorted(flags(main_help)):
    if not re.search(rf"(?<![\w-]){re.escape(flag)}(?![\w-])", text):
        missing.append(f"pita {flag}")
for name in names:
    for flag in sorted(flags(help_text(name))):
        section = re.search(rf"^PITA {name.upper()}$(.*?)(?=^[A-Z][A-Z ]+$|\Z)", text, re.MULTILINE | re.DOTALL)
        if not section or not re.search(rf"(?<![\w-]){re.escape(flag)}(?![\w-])", section.group(1)):
            missing.append(f"pita {name} {flag}")
if missing:
    sys.exit("the man page lacks:\n  " + "\n  ".join(missing))
print(f"pita.1 renders and names {len(names)} subcommands and their flags")
