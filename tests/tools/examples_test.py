"""Every example koppel shows runs: the command lines of README.md and docs/*.md, and every `--help` example.

    python3 examples_test.py KOPPEL_EXECUTABLE SOURCE_DIR [--list]

Which lines are examples (so that none can be left out by accident):
- README.md and the pages of docs/ (in the order of the site's navigation, docs/build.py's NAV;
  a page of docs/ missing there fails the test): every line of an indented code block (outside ``` fences) that starts with
  `koppel `, `build/tools/koppel ` or `$ ` followed by one of those. In a block that has `$ `
  lines, only those are commands; the lines after one, up to the next, are what it prints: lines
  starting `koppel ...:` are its stderr (not compared), the others its stdout, compared in order,
  `...` standing for any lines, numbers to 1e-6 relative (the last digits of 12 may move with the
  compiler). `[...]` in a synopsis is run with its content, or without it where the content names
  a placeholder in capitals (`[--filter REGEX]`, `[ID ...]`).
- `koppel --help-all`: every `Example: koppel ...` or `Examples: koppel ...` (and the `koppel`
  lines indented under it), anywhere in a line, which covers every subcommand's `--help`. Every
  subcommand must have one.
- A comment ` # ...` ends a command. An example meant to show a refusal says so: `# exit N` as
  the comment's start in README, `Example (exit N): koppel ...` in `--help`; every other example
  must exit 0.
- A code block preceded by `<!-- examples: not run, REASON -->` is left out (a cluster's
  shared file system); the test prints those it leaves out, and REASON is required.
- A ``` block preceded by `<!-- examples: file PATH -->` shows a file that ships: it must be
  PATH's text, so the example that reads PATH runs what README shows. With `saved as NAME`
  (`<!-- examples: file PATH, saved as NAME -->`, or `<!-- examples: saved as NAME -->` alone)
  the block is the file a reader saves as NAME: it is written to NAME in the temporary directory
  before the examples run (blocks saved under one NAME must agree).
- A ```python block preceded by `<!-- examples: python -->` runs as a script in the temporary
  directory after the command lines (it must exit 0 and print something) where `import koppel`
  works (ctest puts the build's module on PYTHONPATH when it is built); elsewhere the test says
  that it left them out.

Each example runs under `bash -o pipefail` in one temporary directory in the order shown
(README's first, then docs/' pages', then --help's: an example may read what an earlier one
wrote, atlas.bin, chart.csv, as a reader following them would), where `catalog/`, `docs/`,
`tests/` and `tools/` of the
source tree, `build/tools/koppel` and `koppel` on PATH resolve. It must print something meaningful:
no "internal error"; every file it names with -o (or --error-curve) exists and is not empty;
without -o a non-empty stdout; a CSV on stdout has data rows with a non-zero number beyond its
first column and `singular` (a table of zeros, like a torque without masses, is no example);
`--format json` output parses.
"""
import importlib.util
import json
import math
import os
import re
import shlex
import subprocess
import sys
import tempfile
import time
import unittest

KOPPEL, SOURCE = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
LIST_ONLY = "--list" in sys.argv[3:]

# Printed numbers carry 12 significant digits; README's transcripts are taken on Debian 12's GCC,
# and a last digit may move with another compiler or an unrelated change in summation order.
TRANSCRIPT_RELATIVE = 1e-6
# Roundoff-sized numbers (coordinates that are 0 up to 1e-14) compare absolutely.
TRANSCRIPT_ABSOLUTE = 1e-9
# The slowest example (koppel bench over every benchmark) takes about a minute alone.
EXAMPLE_TIMEOUT_S = 600

COMMAND_START = re.compile(r"^(?:\$ )?(?:koppel|build/tools/koppel) ")
NOT_RUN = re.compile(r"<!--\s*examples:\s*not run,\s*(\S.*?)\s*-->")
SHOWN_FILE = re.compile(r"<!--\s*examples:\s*file\s+([^\s,]+)[^>]*-->")
PYTHON_BLOCK = re.compile(r"<!--\s*examples:\s*(python)\s*-->")
SAVED_FILE = re.compile(r"<!--\s*examples:[^>]*\bsaved as\s+([^\s,]+)[^>]*-->")
EXIT_COMMENT = re.compile(r"^exits? (\d+)\b")
HELP_EXAMPLE = re.compile(r"Examples?(?: \(exit (\d+)\))?: (koppel .*)$")
PLACEHOLDER = re.compile(r"\b[A-Z][A-Z0-9_]{1,}\b|\.\.\.")
OUTPUT_FLAGS = ("-o", "--output-file", "--error-curve", "--yaml", "--curves")


class Example:
    def __init__(self, origin, command, expect=0, transcript=None):
        self.origin, self.command, self.expect = origin, command, expect
        self.transcript = transcript or []

    def __repr__(self):
        return f"{self.origin}: {self.command}" + (f"   (exit {self.expect})" if self.expect else "")


def split_comment(line):
    """The command and its comment: ` # ...` outside quotes."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c == "#" and i > 0 and line[i - 1] == " ":
            return line[:i].rstrip(), line[i + 1:].strip()
    return line.rstrip(), ""


def expand_synopsis(command):
    """`[...]` kept (brackets dropped) unless it holds a placeholder in capitals, then dropped."""
    def keep_or_drop(match):
        inner = match.group(1)
        return "" if PLACEHOLDER.search(inner) else inner
    previous = None
    while previous != command:  # nested brackets, innermost first
        previous, command = command, re.sub(r"\[([^\[\]]*)\]", keep_or_drop, command)
    return re.sub(r"  +", " ", command).strip()


def documents():
    """README.md, then the hand-written pages of docs/ in the order of the site's navigation."""
    spec = importlib.util.spec_from_file_location("docs_build", os.path.join(SOURCE, "docs", "build.py"))
    build = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(build)
    pages = [f"docs/{file}" for _, file in build.NAV if file and os.path.exists(os.path.join(SOURCE, "docs", file))]
    unlisted = sorted(set(f"docs/{f}" for f in os.listdir(os.path.join(SOURCE, "docs")) if f.endswith(".md")) - set(pages))
    if unlisted:
        raise SystemExit(f"examples_test.py: {', '.join(unlisted)} not in docs/build.py's NAV")
    return ["README.md"] + pages


def readme_examples():
    examples, skipped = [], []
    for document in documents():
        found, left_out = document_examples(document)
        examples += found
        skipped += left_out
    return examples, skipped


def document_examples(document):
    with open(os.path.join(SOURCE, document), encoding="utf-8") as f:
        lines = f.read().split("\n")
    examples, skipped, block, fenced, blank_before, not_run = [], [], [], False, True, None

    def flush(block, not_run):
        has_prompt = any(text.startswith("$ ") for _, text in block)
        current = None
        for number, text in block:
            if not COMMAND_START.match(text) or (has_prompt and not text.startswith("$ ")):
                if current is not None:
                    current.transcript.append(text)
                continue
            command, comment = split_comment(text[2:] if text.startswith("$ ") else text)
            exit_match = EXIT_COMMENT.match(comment)
            current = Example(f"{document}:{number}", expand_synopsis(command),
                              int(exit_match.group(1)) if exit_match else 0)
            (skipped if not_run else examples).append((current, not_run) if not_run else current)
            if not has_prompt:
                current = None

    for number, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        indent = len(line) - len(line.lstrip(" "))
        if not fenced and line.strip() and indent >= 4 and (block or blank_before):
            block.append((number, line.strip()))
            continue
        if block:
            flush(block, not_run)
            block, not_run = [], None
        marker = NOT_RUN.search(line)
        if marker:
            not_run = marker.group(1)
        elif line.strip():
            not_run = None if not line.strip().startswith("<!--") else not_run
        blank_before = not line.strip() or bool(marker)
    if block:
        flush(block, not_run)
    return examples, skipped


def help_text():
    return subprocess.run([KOPPEL, "--help-all"], capture_output=True, text=True, check=True).stdout


def help_examples(text):
    examples, lines = [], text.split("\n")
    for number, line in enumerate(lines):
        match = HELP_EXAMPLE.search(line)
        if not match:
            continue
        column = match.start(2)
        found = [match.group(2)]
        for following in lines[number + 1:]:  # `Examples:` continues in the same column
            if len(following) > column and following[:column].strip() == "" and following[column:].startswith("koppel "):
                found.append(following[column:])
            else:
                break
        for command in found:
            command, _ = split_comment(command)
            examples.append(Example(f"koppel --help-all:{number + 1}", command, int(match.group(1) or 0)))
    return examples


def subcommands(text):
    """The top-level subcommands listed by `koppel --help`."""
    listing = subprocess.run([KOPPEL, "--help"], capture_output=True, text=True, check=True).stdout
    names, inside = [], False
    for line in listing.split("\n"):
        if line.startswith("Subcommands:"):
            inside = True
        elif inside and re.match(r"^  \S", line):
            names.append(line.split()[0])
    return names


def output_targets(command):
    words = shlex.split(command)
    words = words[:words.index("|")] if "|" in words else words
    return [words[i + 1] for i, w in enumerate(words[:-1]) if w in OUTPUT_FLAGS]


def marked_files(pattern):
    """(document:marker line, PATH or NAME, the text of the ``` block after a marker matching pattern)."""
    shown = []
    for document in documents():
        with open(os.path.join(SOURCE, document), encoding="utf-8") as f:
            lines = f.read().split("\n")
        for number, line in enumerate(lines):
            marker = pattern.search(line)
            if not marker:
                continue
            fence = next(i for i in range(number + 1, len(lines)) if lines[i].startswith("```"))
            close = next(i for i in range(fence + 1, len(lines)) if lines[i].startswith("```"))
            shown.append((f"{document}:{number + 1}", marker.group(1), "\n".join(lines[fence + 1:close]) + "\n"))
    return shown


def shown_files():
    return marked_files(SHOWN_FILE)


def saved_files():
    """NAME -> text of every block marked `saved as NAME`; blocks saved under one name agree."""
    saved = {}
    for where, name, text in marked_files(SAVED_FILE):
        if saved.setdefault(name, (where, text))[1] != text:
            raise SystemExit(f"examples_test.py: {where} saves {name} otherwise than {saved[name][0]}")
    return {name: text for name, (_, text) in saved.items()}


NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def cells_match(shown, actual):
    if shown == actual:
        return True
    if NUMBER.match(shown) and NUMBER.match(actual):
        a, b = float(shown), float(actual)
        return abs(a - b) <= TRANSCRIPT_RELATIVE * max(abs(a), abs(b)) + TRANSCRIPT_ABSOLUTE
    return False


def line_matches(shown, actual):
    s, a = shown.split(","), actual.split(",")
    return len(s) == len(a) and all(cells_match(x.strip(), y.strip()) for x, y in zip(s, a))


def transcript_mismatch(transcript, stdout):
    """None when the transcript's stdout lines are the output's (`...`: any lines), else why."""
    shown = [t for t in transcript if not re.match(r"^koppel [\w ]*:", t)]
    actual = stdout.rstrip("\n").split("\n") if stdout.strip() else []
    position, skipping = 0, False
    for line in shown:
        if line == "...":
            skipping = True
            continue
        if skipping:
            while position < len(actual) and not line_matches(line, actual[position]):
                position += 1
        if skipping and position >= len(actual):
            return f"the page shows\n    {line}\nafter '...'; koppel prints no such line"
        if position >= len(actual) or not line_matches(line, actual[position]):
            where = actual[position] if position < len(actual) else "(end of output)"
            return f"the page shows\n    {line}\nkoppel prints\n    {where}"
        position, skipping = position + 1, False
    if not skipping and position != len(actual):
        return f"koppel prints more than the page shows (no '...'): {actual[position]}"
    return None


def meaningless_csv(stdout):
    """Why a CSV table on stdout says nothing, or None."""
    rows = [line.split(",") for line in stdout.strip().split("\n")]
    if len(rows) < 2 or len(rows[0]) < 2 or any(len(r) != len(rows[0]) for r in rows):
        return None  # not a CSV table
    header = rows[0]
    for row in rows[1:]:
        for name, cell in zip(header[1:], row[1:]):
            if name != "singular" and NUMBER.match(cell.strip()) and float(cell) != 0:
                return None
            if name != "singular" and cell.strip() and not NUMBER.match(cell.strip()):
                return None  # text cells (a kind, a status) say something
    return "every number beyond the first column is 0"


class Examples(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.help = help_text()
        cls.readme, cls.skipped = readme_examples()
        cls.from_help = help_examples(cls.help)
        cls.dir = tempfile.TemporaryDirectory(prefix="koppel-examples-")
        root = cls.dir.name
        for name in ("catalog", "docs", "tests", "tools"):
            os.symlink(os.path.join(SOURCE, name), os.path.join(root, name))
        for name, text in saved_files().items():  # the files a reader saves from a page
            with open(os.path.join(root, name), "w", encoding="utf-8") as f:
                f.write(text)
        os.makedirs(os.path.join(root, "build", "tools"))
        os.symlink(KOPPEL, os.path.join(root, "build", "tools", "koppel"))
        os.makedirs(os.path.join(root, ".bin"))
        os.symlink(KOPPEL, os.path.join(root, ".bin", "koppel"))
        cls.env = dict(os.environ, PATH=os.path.join(root, ".bin") + os.pathsep + os.environ["PATH"])

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def test_every_subcommand_has_an_example(self):
        shown = {e.command.split()[1] for e in self.from_help}
        for name in subcommands(self.help):
            self.assertIn(name, shown, f"`koppel {name} --help` shows no example")

    def test_readme_has_examples(self):
        # the extraction itself could rot: README's tour holds some ten, docs/usage.md's overview
        # alone some forty
        self.assertGreaterEqual(sum(e.origin.startswith("README.md:") for e in self.readme), 10)
        self.assertGreaterEqual(sum(e.origin.startswith("docs/usage.md:") for e in self.readme), 40)
        for example, reason in self.skipped:
            print(f"not run: {example} ({reason})", file=sys.stderr)

    def test_shown_files_are_the_files(self):
        self.assertTrue(saved_files(), "no page saves a file (the tour's fourbar.yaml)")
        for where, path, text in shown_files():
            with self.subTest(file=path):
                with open(os.path.join(SOURCE, path), encoding="utf-8") as f:
                    self.assertEqual(text, f.read(), f"{where} shows {path} otherwise than it ships")

    def test_examples_run(self):
        for example in self.readme + self.from_help:
            with self.subTest(example=repr(example)):
                self.run_example(example)

    def test_python_examples_run(self):
        blocks = marked_files(PYTHON_BLOCK)
        self.assertTrue(blocks, "no page marks a Python example")
        probe = subprocess.run([sys.executable, "-c", "import koppel"], cwd=self.dir.name, env=self.env,
                               capture_output=True, text=True)
        if probe.returncode != 0:
            for where, _, _ in blocks:
                print(f"not run: the Python example of {where} (import koppel: "
                      f"{probe.stderr.strip().splitlines()[-1] if probe.stderr.strip() else 'failed'})", file=sys.stderr)
            self.skipTest("no koppel module for this Python")
        for where, _, text in blocks:
            with self.subTest(example=where):
                started = time.monotonic()
                r = subprocess.run([sys.executable, "-c", text], cwd=self.dir.name, env=self.env,
                                   capture_output=True, text=True, timeout=EXAMPLE_TIMEOUT_S)
                print(f"{time.monotonic() - started:6.1f} s  exit {r.returncode}  {where}: python", file=sys.stderr)
                context = f"\n{where}\nstderr:\n{r.stderr[-3000:]}\nstdout:\n{r.stdout[:2000]}"
                self.assertEqual(r.returncode, 0, "exit code" + context)
                self.assertTrue(r.stdout.strip(), "prints nothing" + context)

    def run_example(self, example):
        root = self.dir.name
        for target in output_targets(example.command):  # a fresh output, not an earlier example's
            path = os.path.join(root, target)
            if os.path.isfile(path):
                os.remove(path)
        started = time.monotonic()
        r = subprocess.run(["bash", "-o", "pipefail", "-c", example.command], cwd=root, env=self.env,
                           capture_output=True, text=True, timeout=EXAMPLE_TIMEOUT_S)
        print(f"{time.monotonic() - started:6.1f} s  exit {r.returncode}  {example}", file=sys.stderr)
        context = f"\n{example}\nstderr:\n{r.stderr[-3000:]}\nstdout:\n{r.stdout[:2000]}"
        self.assertEqual(r.returncode, example.expect, "exit code" + context)
        self.assertNotIn("internal error", r.stderr, context)
        targets = output_targets(example.command)
        for target in targets:
            path = os.path.join(root, target)
            self.assertTrue(os.path.exists(path), f"{target} not written" + context)
            if os.path.isdir(path):
                self.assertTrue(os.listdir(path), f"{target}/ is empty" + context)
            else:
                self.assertGreater(os.path.getsize(path), 0, f"{target} is empty" + context)
        if example.expect != 0:
            self.assertTrue(r.stderr.strip(), "a refusal says why" + context)
            return
        if not targets:
            self.assertTrue(r.stdout.strip(), "prints nothing" + context)
        if "--format json" in example.command and not targets and "|" not in example.command:
            json.loads(r.stdout)
        elif r.stdout.strip():
            why = meaningless_csv(r.stdout)
            self.assertIsNone(why, why + context if why else "")
        if example.transcript:
            mismatch = transcript_mismatch(example.transcript, r.stdout)
            self.assertIsNone(mismatch, f"{mismatch}{context}" if mismatch else "")


if __name__ == "__main__":
    if LIST_ONLY:
        readme, skipped = readme_examples()
        for e in readme + help_examples(help_text()):
            print(repr(e), "|", len(e.transcript), "transcript lines")
        for e, reason in skipped:
            print("not run:", repr(e), "|", reason)
        sys.exit(0)
    unittest.main(argv=sys.argv[:1], verbosity=2)
