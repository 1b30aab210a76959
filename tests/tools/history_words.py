#!/usr/bin/env python3
"""Lists the places in tracked files that speak of how the project was made rather than of
what it is: the word "session", "issue N" / "issues N-M", "PR N", and file or folder names
that carry a development round ("_s33", "table1_s21_..."). Facts are stated as facts, with
the date and commit where a figure was measured; history belongs in git log.

  python3 tests/tools/history_words.py [repository root]   # prints file:line: text, exits 1 if any
"""

import os
import re
import subprocess
import sys

# In text: the word for a development round (singular or plural), and an issue or pull-request
# number written after its word, with or without "#", alone or as a range.
TEXT = re.compile(r"\bsessions?\b|\bissues?\s*#?\d+|\bPR\s*#?\d+", re.IGNORECASE)
# In a path component: a round number after an underscore or a dash, e.g. table1_s21, run-s3
PATH = re.compile(r"(^|[_\-])s\d{1,3}($|[_\-.])")
# This file names the words it looks for.
SELF = "tests/tools/history_words.py"


def tracked_files(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "-z"], check=True, capture_output=True).stdout
    return [p for p in out.decode("utf-8").split("\0") if p]


def findings(root):
    found = []
    for rel in tracked_files(root):
        for part in rel.split("/"):
            if PATH.search(part):
                found.append(f"{rel}: file or folder name '{part}'")
                break
        if rel == SELF:
            continue
        path = os.path.join(root, rel)
        try:
            with open(path, "rb") as f:
                data = f.read()
        except OSError:
            continue
        if b"\0" in data[:8192]:      # binary (figures, restart files)
            continue
        text = data.decode("utf-8", errors="replace")
        for number, line in enumerate(text.splitlines(), 1):
            if TEXT.search(line):
                found.append(f"{rel}:{number}: {line.strip()[:160]}")
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    found = findings(root)
    for line in found:
        print(line)
    print(f"{len(found)} place(s)", file=sys.stderr)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
