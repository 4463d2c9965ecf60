"""Sphinx configuration of the camcontact documentation site.

Build: ``.venv/bin/sphinx-build -W -b html docs docs/_build/html`` (the ``docs`` extra; the test suite builds it,
tests/docs/test_docs_site.py). The tutorials are executed into a gallery (sphinx-gallery) from a copy of
``tutorials/`` (their figures and files land in the copy, not in the repository); the accuracy-vs-time page
runs the benchmarks' quick modes for its tables and Pareto plot. Both happen when the build starts
(``builder-inited``), not when this file is read. Sphinx-gallery and autosummary write their pages into
``docs/`` (``tutorials/``, ``_generated/``; gitignored): one build at a time.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(ROOT))

import camcontact  # noqa: E402

sys.path.insert(0, str(DOCS))
from tutorial_gallery import convert_tree  # noqa: E402

project = "camcontact"
author = "the camcontact developers"
copyright = "2026, the camcontact developers"
release = version = camcontact.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
]
exclude_patterns = ["_build", "_gallery_src", "_generated/**/*.csv"]
html_theme = "alabaster"
html_theme_options = {"description": "Lubricated contacts of machine elements, in physical units", "page_width": "1100px"}
autosummary_generate = True
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()
nitpicky = False

# ------------------------------------------------------------------ the tutorials gallery
GALLERY_SOURCE = DOCS / "_gallery_src"
sphinx_gallery_conf = {
    "examples_dirs": str(GALLERY_SOURCE),
    "gallery_dirs": "tutorials",
    "filename_pattern": r"/\d\d_",
    "abort_on_example_error": True,
    "download_all_examples": False,
    "remove_config_comments": False,
    "within_subsection_order": "FileNameSortKey",
}
GENERATED = DOCS / "_generated" / "accuracy"


def prepare_gallery(app) -> None:
    """builder-inited, before sphinx-gallery's: a fresh converted copy of ``tutorials/`` (their figures and files
    land in the copy, gitignored, not in the repository)."""
    if GALLERY_SOURCE.exists():
        shutil.rmtree(GALLERY_SOURCE)
    shutil.copytree(ROOT / "tutorials", GALLERY_SOURCE, ignore=shutil.ignore_patterns("__pycache__", "*.png", "*.csv"))
    convert_tree(ROOT / "tutorials", GALLERY_SOURCE)
    (GALLERY_SOURCE / "GALLERY_HEADER.rst").write_text(
        "Tutorials\n=========\n\nThe scripts of ``tutorials/``, executed when the site is built: what each prints "
        "and draws is below its code.\n", encoding="utf-8")


def run_benchmarks(app) -> None:
    """builder-inited: the accuracy-vs-time page's tables and plot from the benchmarks' quick modes; a benchmark
    that fails stops the build with its own error output."""
    GENERATED.mkdir(parents=True, exist_ok=True)
    for mode in ([], ["--friction"], ["--traction"]):
        command = [sys.executable, str(ROOT / "benchmarks" / "accuracy_vs_time.py"), *mode, "--quick", "--out",
                   str(GENERATED)]
        done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"docs: {' '.join(command[1:])} failed ({done.returncode}):\n{done.stderr[-3000:]}")


# ------------------------------------------------------------------ docstrings: |x| is an absolute value
def _escape_bars(line: str) -> str:
    """``|`` escaped outside ``literals`` and :math:`roles` (the docstrings write |x| for an absolute value,
    which reST would read as a substitution)."""
    pieces = re.split(r"(``.*?``|:math:`[^`]*`)", line)
    return "".join(piece if i % 2 else piece.replace("|", "\\|") for i, piece in enumerate(pieces))


def escape_absolute_values(app, what, name, obj, options, lines) -> None:
    """autodoc-process-docstring: escape the bars of |x| in prose, not in math, code or literal blocks."""
    verbatim_indent = None  # inside a directive or literal block: its indentation
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        indent = len(line) - len(stripped)
        if verbatim_indent is not None:
            if stripped and indent <= verbatim_indent:
                verbatim_indent = None
            else:
                continue
        if re.match(r"\.\. (math|code-block|code|literalinclude)::", stripped) or line.rstrip().endswith("::"):
            verbatim_indent = indent
            if not line.rstrip().endswith("::") or stripped.startswith(".."):
                continue
        if stripped.startswith("+") or (stripped.startswith("|") and stripped.rstrip().endswith("|")
                                        and stripped.count("|") > 2):
            continue  # a grid table's rows
        lines[i] = _escape_bars(line)


def setup(app):
    app.connect("builder-inited", prepare_gallery, priority=100)  # before sphinx-gallery's (500)
    app.connect("builder-inited", run_benchmarks, priority=100)
    app.connect("autodoc-process-docstring", escape_absolute_values)
