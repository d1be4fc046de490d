"""Builds koppel's documentation site, offline, with Debian's mkdocs and mkdocs-material.

    python3 docs/build.py KOPPEL OUT_DIR [--work DIR]

KOPPEL is the koppel executable whose `--help` the command pages are generated from (never copied
by hand); OUT_DIR receives the site (open OUT_DIR/index.html from disk: no server needed). The
pages are staged in a work folder (default OUT_DIR.src) beside the generated ones:
- commands/*.md: one page per command (and per subcommand of catalog, synth and atlas), the
  text of `koppel COMMAND --help`, and commands/index.md listing them;
- python-reference.md: the Python module's classes and functions with their docstrings, read from
  its type stub tools/python/koppel/_koppel.pyi and the pure-Python modules beside it;
- img/: the pictures koppel draws, from tools/plot/gallery and tools/edit (the tests keep them
  current), and the tutorial's pictures drawn now by KOPPEL from docs/examples/fourbar.yaml.
Then `mkdocs build --strict`: a broken link or a page missing from the navigation fails the build.
"""
import ast
import html
import os
import re
import shutil
import subprocess
import sys
import time

DOCS = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(DOCS)

# The pages written by hand, in the order of the navigation (title, file).
NAV = [
    ("Home", "index.md"),
    ("Installing and building", "install.md"),
    ("Tutorial: your first mechanism", "tutorial.md"),
    ("Using koppel", "usage.md"),
    ("Mechanism files", "mechanism-file.md"),
    ("Concepts", "concepts.md"),
    ("Tolerances and clearance", "tolerance.md"),
    ("Synthesis", "synthesis.md"),
    ("Pictures, DXF and GIF", "pictures.md"),
    ("The editor page", "editor.md"),
    ("The catalog", "catalog.md"),
    ("C++ and Python API", "library.md"),
    ("Python reference", "python-reference.md"),
    ("Commands", None),  # generated: commands/index.md and one page per command
    ("Limits and exit codes", "limits.md"),
    ("Performance", "performance.md"),
    ("Design", "design.md"),
    ("Dependencies", "dependencies.md"),
]

# Pictures koppel drew, kept current by the tests gallery_current, animate_gif and editor_page.
PICTURES = [
    "tools/plot/gallery/transfer-slider-crank-offset.svg",
    "tools/plot/gallery/coupler-curve-mzc-crank-rocker.svg",
    "tools/plot/gallery/tolerance-slider-crank-offset.svg",
    "tools/plot/gallery/cycle-mzc-crank-rocker.gif",
    "tools/edit/editor-slider-crank-offset.png",
]

# The tutorial's pictures, drawn by the koppel being documented: (file in img/, arguments).
TUTORIAL = "docs/examples/fourbar.yaml"
DRAWN = [
    ("tutorial-scheme.svg", ["draw", TUTORIAL, "--at", "60", "--trace", "K"]),
    ("tutorial-deadcentres.svg", ["draw", TUTORIAL, "--deadcentres"]),
    ("tutorial-transfer.svg", ["plot", TUTORIAL, "--transfer", "psi", "--order", "2"]),
    ("tutorial-mu.svg", ["plot", TUTORIAL, "--mu"]),
    ("tutorial-curve.svg", ["plot", TUTORIAL, "--curve", "K"]),
]


def run(args, **kwargs):
    return subprocess.run(args, capture_output=True, text=True, check=True, cwd=SOURCE, **kwargs).stdout


def subcommands(help_text):
    """The names under `Subcommands:` of a --help text."""
    names, inside = [], False
    for line in help_text.split("\n"):
        if line.startswith("Subcommands:"):
            inside = True
        elif inside and re.match(r"^  \S", line):
            names.append(line.split()[0])
        elif inside and line and not line.startswith(" "):
            inside = False
    return names


def first_sentence(help_text):
    """The description that opens a --help text, up to its first full stop."""
    text = " ".join(help_text.split("\n\n")[0].split())
    match = re.match(r"(.+?\.)(\s|$)", text)
    return match.group(1) if match else text


def command_page(koppel, words):
    text = run([koppel] + words + ["--help"])
    title = "koppel " + " ".join(words)
    page = [f"# `{title}`", "",
            f"Generated from `{title} --help` of {run([koppel, '--version']).strip()} when this site was built.", "",
            "<pre class=\"help\"><code>" + html.escape(text.rstrip("\n")) + "</code></pre>", ""]
    return text, "\n".join(page)


def write_commands(koppel, stage):
    """commands/*.md; returns the navigation entries."""
    folder = os.path.join(stage, "docs", "commands")
    os.makedirs(folder)
    top = run([koppel, "--help"])
    nav, rows = [("Overview", "commands/index.md")], []
    for name in subcommands(top):
        text, page = command_page(koppel, [name])
        file = f"commands/{name}.md"
        open(os.path.join(stage, "docs", file), "w", encoding="utf-8").write(page)
        nav.append((f"koppel {name}", file))
        rows.append(f"| [`koppel {name}`]({name}.md) | {first_sentence(text).replace('|', '&#124;')} |")
        for sub in subcommands(text):
            sub_text, sub_page = command_page(koppel, [name, sub])
            sub_file = f"commands/{name}-{sub}.md"
            open(os.path.join(stage, "docs", sub_file), "w", encoding="utf-8").write(sub_page)
            nav.append((f"koppel {name} {sub}", sub_file))
            rows.append(f"| [`koppel {name} {sub}`]({name}-{sub}.md) | "
                        f"{first_sentence(sub_text).replace('|', '&#124;')} |")
    index = ["# Commands", "",
             "One page per command, generated from its `--help` when this site was built. "
             "`koppel --help` lists them, `koppel COMMAND --help` explains one.", "",
             "<pre class=\"help\"><code>" + html.escape(top.rstrip("\n")) + "</code></pre>", "",
             "| command | what it does |", "| --- | --- |"] + rows + [""]
    open(os.path.join(folder, "index.md"), "w", encoding="utf-8").write("\n".join(index))
    return nav


def signature(node, source):
    """`name(args) -> returns` of a function in the stub, as written there."""
    text = ast.get_source_segment(source, node)
    head = text.split(":\n")[0] if ":\n" in text else text.split("...")[0]
    head = re.sub(r"^(async\s+)?def\s+", "", head.strip())
    head = " ".join(head.split())
    return head.rstrip(":").rstrip()


def describe(node, source, level, out):
    """A class as its stub declares it (members and method signatures), a function as its
    signature, each with its docstring where it has one."""
    doc = ast.get_docstring(node) or ""
    if isinstance(node, ast.ClassDef):
        out += [f"{'#' * level} class `{node.name}`", ""]
        if doc:
            out += [doc, ""]
        out += ["```python", ast.get_source_segment(source, node), "```", ""]
        for child in node.body:  # methods with a docstring of their own (the Python modules')
            if isinstance(child, ast.FunctionDef) and not child.name.startswith("_") and ast.get_docstring(child):
                out += [f"`{node.name}.{signature(child, source)}`: {ast.get_docstring(child)}", ""]
    elif isinstance(node, ast.FunctionDef):
        out += [f"{'#' * level} `{node.name}`", "", "```python", signature(node, source), "```", ""]
        if doc:
            out += [doc, ""]


def write_python_reference(stage):
    """python-reference.md from the module's stub and its pure-Python modules."""
    package = os.path.join(SOURCE, "tools", "python", "koppel")
    out = ["# Python reference", "",
           "Generated when this site was built from the module's type stub "
           "(`koppel/_koppel.pyi`: the compiled part's classes, members and signatures) and its Python modules "
           "`koppel.catalog` and `koppel.synth`. The [C++ and Python API](library.md) page shows "
           "how to build, install and use it.", ""]
    for module, file in (("koppel", "_koppel.pyi"), ("koppel.catalog", "catalog.py"), ("koppel.synth", "synth.py")):
        path = os.path.join(package, file)
        if not os.path.exists(path):
            continue
        source = open(path, encoding="utf-8").read()
        tree = ast.parse(source)
        out += [f"## `{module}`", ""]
        doc = ast.get_docstring(tree)
        if doc:
            out += [doc, ""]
        for node in tree.body:
            if isinstance(node, (ast.ClassDef, ast.FunctionDef)) and not node.name.startswith("_"):
                describe(node, source, 3, out)
    open(os.path.join(stage, "docs", "python-reference.md"), "w", encoding="utf-8").write("\n".join(out) + "\n")


def write_pictures(koppel, stage):
    img = os.path.join(stage, "docs", "img")
    os.makedirs(img)
    for picture in PICTURES:
        shutil.copy(os.path.join(SOURCE, picture), img)
    for name, args in DRAWN:
        run([koppel] + args + ["-o", os.path.join(img, name)])


def write_config(stage, commands_nav):
    lines = ["site_name: koppel", "site_description: " + json_str("planar linkages: analysis, synthesis and a catalog"),
             "docs_dir: docs", "use_directory_urls: false", "strict: true",
             # no web fonts (offline) and no search: its web worker cannot start from file://
             "theme:", "  name: material", "  font: false", "  features: [navigation.sections]",
             "plugins: []",
             "markdown_extensions: [toc, tables, fenced_code, admonition]",
             "extra_css: [koppel.css]", "nav:"]
    for title, file in NAV:
        if file:
            lines.append(f"  - {json_str(title)}: {file}")
        else:
            lines.append(f"  - {json_str(title)}:")
            lines += [f"      - {json_str(t)}: {f}" for t, f in commands_nav]
    open(os.path.join(stage, "mkdocs.yml"), "w", encoding="utf-8").write("\n".join(lines) + "\n")


def json_str(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def main():
    args = [a for a in sys.argv[1:]]
    work = None
    if "--work" in args:
        i = args.index("--work")
        work = os.path.abspath(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        sys.exit(__doc__)
    koppel, out = os.path.abspath(args[0]), os.path.abspath(args[1])
    stage = work or out + ".src"
    started = time.monotonic()
    shutil.rmtree(stage, ignore_errors=True)
    os.makedirs(os.path.join(stage, "docs"))
    for title, file in NAV:
        if file and file != "python-reference.md":
            shutil.copy(os.path.join(DOCS, file), os.path.join(stage, "docs", file))
    shutil.copy(os.path.join(DOCS, "koppel.css"), os.path.join(stage, "docs"))
    shutil.copytree(os.path.join(DOCS, "examples"), os.path.join(stage, "docs", "examples"))
    write_pictures(koppel, stage)
    commands_nav = write_commands(koppel, stage)
    write_python_reference(stage)
    write_config(stage, commands_nav)
    r = subprocess.run(["mkdocs", "build", "--strict", "--clean", "-f", os.path.join(stage, "mkdocs.yml"), "-d", out],
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.stderr.write(r.stdout + r.stderr)
        sys.exit(f"docs/build.py: mkdocs build --strict failed (exit {r.returncode})")
    pages = sum(1 for _, _, files in os.walk(out) for f in files if f.endswith(".html"))
    print(f"docs/build.py: {pages} pages in {out} ({time.monotonic() - started:.1f} s)")


if __name__ == "__main__":
    main()
