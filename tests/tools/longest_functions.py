#!/usr/bin/python3
"""Longest function bodies in C++ sources (a review aid, not a test).

    longest_functions.py [DIR ...] [--top N]

A body is a brace block at namespace level (or a class member defined inline) whose
opening line looks like a function head: it contains '(' and is not a
class/struct/namespace/enum/lambda. Lines counted from the head's line to the closing
brace. Strings, characters and comments are blanked first, so braces in them do not count.
"""
import os
import re
import sys


def strip(text):
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    text = strip(open(path, errors="replace").read())
    lines = text.split("\n")
    found, stack = [], []  # stack of (kind, start line, head)
    for lineno, line in enumerate(lines, 1):
        for col, c in enumerate(line):
            if c == "{":
                before = " ".join(lines[max(0, lineno - 4):lineno - 1] + [line[:col]])
                head = before.strip().split(";")[-1].split("}")[-1].strip()
                in_function = any(k == "function" for k, _, _ in stack)
                is_type = re.search(r"\b(class|struct|namespace|enum|union)\b[^()]*$", head)
                is_function = (not in_function and "(" in head and not is_type
                               and not head.endswith("=") and not re.search(r"\]\s*\([^)]*\)\s*(mutable\s*)?(->[^{]*)?$", head))
                stack.append(("function" if is_function else "block", lineno, head))
            elif c == "}" and stack:
                kind, start, head = stack.pop()
                if kind == "function":
                    name = re.findall(r"([~\w:]+)\s*\(", head)
                    found.append((lineno - start + 1, path, start, name[0] if name else head[-60:]))
    return found


def main(argv):
    top = 10
    if "--top" in argv:
        k = argv.index("--top")
        top = int(argv[k + 1])
        argv = argv[:k] + argv[k + 2:]
    roots = argv or ["."]
    rows = []
    for root in roots:
        for d, _, files in os.walk(root):
            for f in files:
                if f.endswith((".cpp", ".h", ".cc")):
                    rows += functions(os.path.join(d, f))
    rows.sort(reverse=True)
    for length, path, start, name in rows[:top]:
        print(f"{length:5d}  {path}:{start}  {name}")


if __name__ == "__main__":
    main(sys.argv[1:])
