#!/usr/bin/env python3
"""List the C++ functions whose body is longer than a limit (issue 24: at most 5 over 60 lines).

Rule: a function's length is the number of lines from the line holding its opening brace to the
line holding its closing brace, both included. A lambda or local class counts as part of the
function that holds it. A function left long on purpose carries `// long: <reason>` on the line
just above its signature; such functions are listed with their reason (they still count).

Usage: tools/dev/long_functions.py [--limit 60] [--check N] [dir ...]   (default dirs: core solver catalog tools)
Prints one line per function, longest first: `length  file:line  name  [long: reason]`, then the
count. A heuristic scanner, not a C++ parser: comments, strings and character literals are blanked,
then each `{` is classified by the text before it (namespace, class, function or other).
"""
import argparse
import pathlib
import re
import sys

SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".cc"}
SKIPPED_DIRS = {"build", "tests", ".git"}


def blank_comments_and_strings(text):
    """Replace comments and string/char literal contents by spaces, keeping newlines and offsets."""
    out = list(text)
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out[i:j] = " " * (j - i)
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out[i:j] = [ch if ch == "\n" else " " for ch in text[i:j]]
            i = j
        elif c == 'R' and text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out[i:j] = [ch if ch == "\n" else " " for ch in text[i:j]]
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # digit separator 1'000
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out[i + 1:j] = " " * (j - i - 1)
            i = j + 1
        else:
            i += 1
    return "".join(out)


def classify(head):
    """What a `{` opens, judged by the text since the previous `;`, `{` or `}`."""
    head = re.sub(r"\s+", " ", head).strip()
    head = re.sub(r"^(public|private|protected) ?:", "", head).strip()
    if re.match(r"^(inline )?namespace\b", head) or head.startswith('extern "'):
        return "namespace"
    if re.search(r"\b(class|struct|union|enum)\b[^(=]*$", head) and "(" not in head.split(":")[0]:
        return "class"
    if "(" in head and not head.endswith("=") and not re.search(r"=\s*$", head):
        if re.match(r"^(if|for|while|switch|catch|do|else)\b", head):
            return "other"
        return "function"
    return "other"


def function_name(head):
    """The name before the parameter list (the first `(` not inside a template argument list)."""
    head = re.sub(r"\s+", " ", head)
    m = re.search(r"([A-Za-z_~][\w:~<>,]*(?:operator\s*\S+?)?)\s*\(", head)
    return m.group(1) if m else head.strip()[:40]


def long_reason(lines, signature_index):
    """The `// long: reason` comment on the line above the signature (0-based index), if any."""
    if signature_index == 0:
        return None
    m = re.search(r"//\s*long:\s*(.*)", lines[signature_index - 1])
    return m.group(1).strip() if m else None


def functions(path):
    text = path.read_text(encoding="utf-8", errors="replace")
    code = blank_comments_and_strings(text)
    # preprocessor lines (with their continuations) are not part of any declaration
    code = re.sub(r"^[ \t]*#(?:[^\n]*\\\n)*[^\n]*", lambda m: re.sub(r"[^\n]", " ", m.group(0)), code,
                  flags=re.M)
    lines = text.split("\n")
    stack = []  # (kind, offset of '{', head start offset, name)
    head_start = 0
    for i, c in enumerate(code):
        if c == "{":
            enclosing = stack[-1][0] if stack else "namespace"
            kind = classify(code[head_start:i]) if enclosing in ("namespace", "class") else "inner"
            stack.append((kind, i, head_start, function_name(code[head_start:i])))
            head_start = i + 1
        elif c == "}":
            if not stack:
                continue
            kind, start, hstart, name = stack.pop()
            if kind == "function":
                first = code.count("\n", 0, start) + 1
                last = code.count("\n", 0, i) + 1
                head = code[hstart:start]
                signature_index = code.count("\n", 0, hstart + len(head) - len(head.lstrip()))
                yield last - first + 1, first, name, long_reason(lines, signature_index)
            head_start = i + 1
        elif c == ";":
            head_start = i + 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--limit", type=int, default=60)
    parser.add_argument("dirs", nargs="*", default=["core", "solver", "catalog", "tools"])
    parser.add_argument("--check", type=int, metavar="N",
                        help="exit 1 when more than N functions are over the limit or one of them has no `// long:` reason")
    args = parser.parse_args()
    found = []
    for d in args.dirs:
        for path in sorted(pathlib.Path(d).rglob("*")):
            if path.suffix in SOURCE_SUFFIXES and not SKIPPED_DIRS & set(path.parts):
                for length, line, name, reason in functions(path):
                    if length > args.limit:
                        found.append((length, f"{path}:{line}", name, reason))
    for length, where, name, reason in sorted(found, key=lambda f: (-f[0], f[1])):
        print(f"{length:5d}  {where}  {name}" + (f"  [long: {reason}]" if reason else ""))
    print(f"{len(found)} functions over {args.limit} lines", file=sys.stderr)
    if args.check is not None:
        unexplained = [f for f in found if not f[3]]
        if len(found) > args.check or unexplained:
            print(f"more than {args.check}, or without a `// long: <reason>` comment: {len(unexplained)}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
