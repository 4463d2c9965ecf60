"""Turn the tutorials (jupytext percent scripts with Markdown cells) into sphinx-gallery examples.

sphinx-gallery wants a module docstring with a title and reStructuredText text blocks (``# %%`` followed by
comment lines). The tutorials stay plain percent scripts that open as notebooks; this converts a copy: the first
Markdown cell becomes the docstring, the others text blocks, with Markdown headings made reST titles and inline
code ``literal``. Used by ``conf.py`` only.
"""

from __future__ import annotations

import re
from pathlib import Path

UNDERLINE = {1: "=", 2: "-", 3: "~"}


def markdown_to_rst(lines: list[str]) -> list[str]:
    """The few Markdown forms the tutorials use, as reST: ``#``/``##``/``###`` headings, `code`."""
    out: list[str] = []
    for line in lines:
        heading = re.match(r"^(#{1,3}) (.*)$", line)
        if heading:
            title = heading.group(2).strip()
            out += [title, UNDERLINE[len(heading.group(1))] * len(title), ""]
            continue
        out.append(re.sub(r"(?<!`)`([^`]+)`(?!`)", r"``\1``", line))
    return out


def cells(source: str) -> list[tuple[str, list[str]]]:
    """(kind, lines) of each ``# %%`` cell: ("markdown", text without the leading ``# ``) or ("code", lines)."""
    result: list[tuple[str, list[str]]] = []
    kind, body = None, []
    for line in source.splitlines():
        if line.startswith("# %%"):
            if kind is not None:
                result.append((kind, body))
            kind, body = ("markdown" if "[markdown]" in line else "code"), []
            continue
        if kind == "markdown":
            body.append(line[2:] if line.startswith("# ") else line.lstrip("#"))
        elif kind is not None:
            body.append(line)
    if kind is not None:
        result.append((kind, body))
    return result


def gallery_script(source: str, path: Path) -> str:
    """The sphinx-gallery form of one tutorial's source, which lies at ``path`` (sphinx-gallery runs it without
    ``__file__``: the end of the first code cell sets it in lines the gallery hides, so the tutorial finds its scene
    files)."""
    parts = cells(source)
    if not parts or parts[0][0] != "markdown":
        raise ValueError("a tutorial must open with a Markdown cell holding its title")
    text = ['"""', *markdown_to_rst(parts[0][1]), '"""', ""]
    located = False
    for kind, body in parts[1:]:
        while body and not body[-1].strip():
            body = body[:-1]
        if kind == "markdown":
            text += ["# %%", *(f"# {line}".rstrip() for line in markdown_to_rst(body)), ""]
            continue
        if not located:
            body = [*body, "# sphinx_gallery_start_ignore", f"__file__ = {str(path)!r}",
                    "# sphinx_gallery_end_ignore"]  # at the end: comments after "# %%" open a text block
            located = True
        text += ["# %%", *body, ""]
    return "\n".join(text) + "\n"


def convert_tree(source: Path, target: Path) -> None:
    """Every ``NN_*.py`` tutorial of ``source`` converted into ``target`` (other files as they are)."""
    for path in target.glob("[0-9][0-9]_*.py"):
        path.write_text(gallery_script(path.read_text(encoding="utf-8"), path), encoding="utf-8")
