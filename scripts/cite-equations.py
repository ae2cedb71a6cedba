#!/usr/bin/env python3
"""Every equation cited in src/ and tests/ names its paper (README "The papers").

The papers number their equations independently: "Eq. 9" is the PITA
paper's Lagrange weights and the SAM paper's affine power. So a citation
reads "PITA Eq. 9", "SAM Eq. 9" or "chapter Eq. 3.19" (the interpolation
chapter, whose numbers carry the chapter's).

    scripts/cite-equations.py           list the citations that name no paper; exit 1 if any
    scripts/cite-equations.py --fix     prefix each with its paper, as guessed below, and list them

--fix guesses the paper: a number with a chapter's dot (3.19) is the chapter's;
an appendix number (D.1, A.3, F.1) is the PITA paper's; a citation beside
"SAM paper", "SAM Sec." or "SAM Fig." is the SAM paper's; a number above 20
is the PITA paper's (the SAM paper has 20); otherwise the file decides (the
affine powers, SAMs and poses are the SAM paper's). Review its changes.
"""
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAPERS = ("PITA", "SAM", "chapter", "Alexa's")  # and another paper's own, by name
CITATION = re.compile(r"\b(Eqs?\.)(\s?)([A-Z]\.\d+|\d+(?:\.\d+)?)")
SAM_FILE = re.compile(r"sam|affine|pose|steady_affine|rarap|alexa|field|swept|existence|bezier|patch|four_point|"
                      r"arap|log_matrix|exp_of_parts|grazing|space|3d|solid|camera|projection|steadiness|versus|"
                      r"velocit|subdiv", re.I)


def files():
    try:  # the tracked files; a tree without git (a source package): every file
        listed = subprocess.run(["git", "ls-files", "src", "tests", "scripts"], cwd=ROOT, capture_output=True,
                                text=True, check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        listed = []
    if not listed:
        listed = [str(p.relative_to(ROOT)) for top in ("src", "tests", "scripts") for p in (ROOT / top).rglob("*")]
    return [ROOT / f for f in listed if f.endswith((".cpp", ".hpp", ".h", ".py")) and not f.endswith("cite-equations.py")]


def named(before):
    return any(before.endswith(paper + " ") for paper in PAPERS)


def guess(path, before, number):
    context = before[-80:]
    if re.fullmatch(r"\d+\.\d+", number) or re.search(r"chapter", context, re.I):
        return "chapter"
    if re.fullmatch(r"[A-Z]\.\d+", number):
        return "PITA"
    if re.search(r"SAM (paper|Sec|Fig|appendix)", context):
        return "SAM"
    if re.search(r"PITA (paper|Sec|Fig)", context):
        return "PITA"
    if int(number) > 20:
        return "PITA"
    return "SAM" if SAM_FILE.search(path.name) else "PITA"


def main():
    fix = "--fix" in sys.argv[1:]
    unnamed = []
    for path in files():
        lines = path.read_text().split("\n")
        changed = False
        for i, line in enumerate(lines):
            out, last = [], 0
            for m in CITATION.finditer(line):
                before = line[: m.start()]
                if named(before):
                    continue
                paper = guess(path, before, m.group(3))
                unnamed.append(f"{path.relative_to(ROOT)}:{i + 1}: {m.group(0)} -> {paper} {m.group(0)}")
                out.append(line[last : m.start()] + paper + " ")
                last = m.start()
            if out and fix:
                lines[i] = "".join(out) + line[last:]
                changed = True
        if changed:
            path.write_text("\n".join(lines))
    for entry in unnamed:
        print(entry)
    if unnamed and not fix:
        print(f"{len(unnamed)} equation citations name no paper: write \"PITA Eq. N\", \"SAM Eq. N\" or "
              "\"chapter Eq. N.M\" (scripts/cite-equations.py --fix guesses them)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
