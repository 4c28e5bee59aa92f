#!/usr/bin/python3
"""Every docs/MATH.md section cited anywhere in the repository exists as a heading of docs/MATH.md.

Usage: check_math_citations.py <repository root>

Citations are the `§N.N` tokens of every git-tracked text file (`§0` the conventions, `§A`..`§C` the
appendices), including lists (`§7.2, §7.3`) and ranges (`§2-§5`, `§3.7-3.8`). Fails, naming file:line,
on a section that is not a heading of docs/MATH.md, on a MATH.md other than docs/MATH.md (a bare
`MATH.md 7.2`, a path into another tree), on `docs/MATH.md` followed by a section number without `§`,
and when no citation at all is found.
"""
import re
import sys

from tracked_text import tracked_text_files

SECTION = r"[0-9]+(?:\.[0-9]+)*|[A-C]\b"
CITATION = re.compile(r"§(" + SECTION + r")(?:\s*[-–]\s*§?(" + SECTION + r"))?")
HEADING = re.compile(r"^#+\s+(?:Appendix\s+)?(" + SECTION + r")[.:\s]")
OTHER_MATH = re.compile(r"(?<!docs/)\bMATH\.md\b")
NUMBER_WITHOUT_SIGN = re.compile(r"docs/MATH\.md[\s,]+[0-9]")


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    with open(f"{root}/docs/MATH.md", encoding="utf-8") as f:
        sections = {m.group(1).rstrip(".") for line in f if (m := HEADING.match(line))}
    failures = []
    cited = 0
    for name, text in tracked_text_files(root):
        for number, line in enumerate(text.splitlines(), 1):
            for m in CITATION.finditer(line):
                for section in filter(None, m.groups()):
                    cited += 1
                    if section not in sections:
                        failures.append(f"{name}:{number}: §{section} is not a section of docs/MATH.md")
            if OTHER_MATH.search(line):
                failures.append(f"{name}:{number}: cites a MATH.md other than docs/MATH.md: {line.strip()}")
            if NUMBER_WITHOUT_SIGN.search(line):
                failures.append(f"{name}:{number}: a section of docs/MATH.md is cited without §: {line.strip()}")
    for failure in failures:
        print(failure)
    if cited == 0:
        print("no docs/MATH.md citation found: the check ran on nothing")
        return 1
    print(f"{cited} citations of {len(sections)} sections checked, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
