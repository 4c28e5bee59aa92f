#!/usr/bin/python3
"""The product speaks of itself: no git-tracked file mentions how its work was organised.

Usage: check_process_words.py <repository root>

Fails, naming file:line and the words, on "session N", "reviewer(s)", "found in review", "issue #N" or
"helper session" in any git-tracked text file, and when no file was read.
"""
import re
import sys

from tracked_text import tracked_text_files

PROCESS_WORDS = re.compile(
    r"\bsessions?\s+[0-9]|\breviewers?\b|found\s+in\s+review|\bissue\s+#[0-9]|\bhelper\s+session",
    re.IGNORECASE)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    failures = []
    read = 0
    for name, text in tracked_text_files(root):
        read += 1
        for number, line in enumerate(text.splitlines(), 1):
            for m in PROCESS_WORDS.finditer(line):
                failures.append(f"{name}:{number}: \"{m.group(0)}\": {line.strip()[:160]}")
    for failure in failures:
        print(failure)
    if read == 0:
        print("no tracked text file was read: the check ran on nothing")
        return 1
    print(f"{read} files checked, {len(failures)} process words")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
