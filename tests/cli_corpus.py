"""A corpus of bad scene files and bad ``camcontact`` calls, and hostile scenes that must not execute.

Not a test module: ``tests/unit/test_cli_corpus.py`` runs it (in-process, and in child processes for the
cases that need a real stdout or might block), ``benchmarks/cli_corpus.py`` runs all of it in child
processes and prints the counts.

Each :class:`Case` is a name, the bytes of a scene file (or None: no file is written) and the arguments
of ``camcontact``. In the arguments ``{scene}`` stands for the written scene file and ``{tmp}`` for the
case's own temporary directory (:func:`prepare` substitutes them and makes the FIFO of ``setup="fifo"``).
Every case must end with ``status`` (2: bad input, the default; 1: a failure while running; 141: stdout
closed), one error line ``camcontact: error: ...`` on stderr (none for a closed stdout), no traceback,
within a bounded time: :func:`problems` lists what a finished call got wrong.

The bad scenes are mutations of two valid ones: :data:`LINE`, a line contact whose run takes
milliseconds (also swept by ``camcontact sweep``: two loads), and the embedded default scene (the LS-1
cam, whose run takes seconds: each of its cases fails while the file is read or the analysis planned).
"""

from __future__ import annotations

import json
import os
import random
import re
import subprocess
import sys
import time
from pathlib import Path
from typing import NamedTuple

from camcontact.scene_file import (
    MAX_NESTING,
    MAX_SCENE_BYTES,
    MAX_SWEEP_CASES,
    default_scene_text,
)

__all__ = ["CASES", "LINE", "MARKER_PAYLOADS", "Case", "Outcome", "cases", "marker_cases", "prepare", "problems",
           "run_subprocess"]

_BODY1 = """\
[contact.body1]
radius = "20 mm"
speed = "2 m/s"
roughness = "0.2 um"
concave = false

[contact.body1.material]
name = "steel"
E = "210 GPa"
nu = 0.3
"""
_BODY2_MATERIAL = """\
[contact.body2.material]
name = "steel"
E = "210 GPa"
nu = 0.3
"""
#: a valid line-contact scene (runs in milliseconds), with a two-case [sweep] table
LINE = """\
scene = "line_contact"
name = "corpus line contact"
outputs = ["b", "p_h", "h_c", "regime"]
effects = ["elasticity", "piezoviscosity"]

[models]
film = "moes"

[report]
units = { h_c = "um", p_h = "MPa" }

[sweep]
load = ["1 kN", "2 kN"]

[contact]
load = "1 kN"
length = "10 mm"
temperature = "60 degC"

""" + _BODY1 + """
[contact.body2]
radius = "10 mm"
speed = "2 m/s"
roughness = "0.2 um"

""" + _BODY2_MATERIAL + """
[contact.lubricant]
name = "ISO VG 100"
nu40 = "100 cSt"
nu100 = "11 cSt"
density = "870 kg/m^3"
alpha = "22 1/GPa"
"""

#: exit statuses (as camcontact.cli documents them)
BAD_INPUT, FAILURE, BROKEN_PIPE = 2, 1, 141


class Case(NamedTuple):
    """One bad call: ``camcontact *argv`` with ``scene`` written to ``{scene}``."""

    name: str
    scene: bytes | None
    argv: tuple[str, ...]
    status: int = BAD_INPUT
    #: "fifo": ``{tmp}/fifo.toml`` is made a FIFO; "" nothing
    setup: str = ""
    #: run in a child process also in the tests (needs a real stdout, or could block if it went wrong)
    subprocess: bool = False
    #: close the child's stdout at once (a reader that went away: ``camcontact run | head``)
    closed_stdout: bool = False


class Outcome(NamedTuple):
    """What a call did."""

    status: int | None  # None: did not finish in time
    stdout: str
    stderr: str
    seconds: float


def _edit(text: str, old: str, new: str, count: int = 1) -> str:
    """``text`` with ``old`` replaced (it must be there: a corpus case never silently turns valid)."""
    if old not in text:
        raise AssertionError(f"corpus: {old!r} is not in the base scene")
    return text.replace(old, new, count)


def _toml(value: str) -> str:
    """``value`` as a TOML basic string (JSON's escapes are TOML's)."""
    return json.dumps(value)


def _run(name: str, text: str | bytes, *extra: str, status: int = BAD_INPUT, **options) -> Case:
    data = text.encode("utf-8") if isinstance(text, str) else text
    return Case(name, data, ("run", "{scene}", "--csv", "{tmp}/report.csv", *extra), status, **options)


def _sweep(name: str, text: str, *extra: str) -> Case:
    return Case(name, text.encode("utf-8"), ("sweep", "{scene}", "--csv", "{tmp}/sweep.csv", "--no-progress", *extra))


def _line(name: str, old: str, new: str) -> Case:
    return _run(name, _edit(LINE, old, new))


def _cam(name: str, old: str, new: str) -> Case:
    return _run(name, _edit(default_scene_text(), old, new))


def _file_cases() -> list[Case]:
    """Encodings, empty and binary files, sizes."""
    line = LINE.encode("utf-8")
    noise = random.Random(18).randbytes(4096)
    return [
        _run("latin-1 degree sign", _edit(LINE, "60 degC", "60 °C").encode("latin-1")),
        _run("invalid UTF-8 in a string", line.replace(b'"steel"', b'"st\xc3\x28el"', 1)),
        _run("truncated UTF-8 at the end", line + b"# \xe2\x82"),
        _run("UTF-16 with BOM", LINE.encode("utf-16")),
        _run("UTF-16-BE with BOM", b"\xfe\xff" + LINE.encode("utf-16-be")),
        _run("UTF-32 with BOM", LINE.encode("utf-32")),
        _run("UTF-8 BOM then junk", b"\xef\xbb\xbfthis is not TOML"),
        _run("empty file", b""),
        _run("whitespace only", b"\n \n\t\n"),
        _run("comment only", b"# a scene will follow\n"),
        _run("binary junk (all bytes)", bytes(range(256)) * 4),
        _run("binary junk (random)", noise),
        _run("NUL byte", line.replace(b"\n", b"\x00\n", 1)),
        _run("gzip header", b"\x1f\x8b\x08\x00" + noise[:100]),
        _run("huge file (comments)", b"# padding\n" * (MAX_SCENE_BYTES // 10 + 10) + line),
        _run("huge quantity string", _edit(LINE, 'load = "1 kN"', f'load = "1{"0" * (MAX_SCENE_BYTES // 2)} N"')),
        _run("huge output list", _edit(LINE, 'outputs = ["b", "p_h", "h_c", "regime"]',
                                       "outputs = [" + ", ".join(['"zz"'] * 100_000) + "]")),
        _run("huge model name", _edit(LINE, 'film = "moes"', f'film = "{"m" * 500_000}"')),
    ]


def _special_file_cases() -> list[Case]:
    """Things that are not regular files (each refused before it is opened for reading)."""
    return [
        Case("FIFO as scene", None, ("run", "{tmp}/fifo.toml", "--csv", "{tmp}/report.csv"), setup="fifo",
             subprocess=True),
        Case("/dev/zero as scene", None, ("run", "/dev/zero", "--csv", "{tmp}/report.csv")),
        Case("/dev/null as scene", None, ("run", "/dev/null", "--csv", "{tmp}/report.csv")),
        Case("/dev/urandom as sweep scene", None, ("sweep", "/dev/urandom", "--csv", "{tmp}/sweep.csv")),
        Case("directory as scene", None, ("run", "{tmp}", "--csv", "{tmp}/report.csv")),
        Case("missing scene file", None, ("run", "{tmp}/missing.toml", "--csv", "{tmp}/report.csv")),
        Case("missing scene file (sweep)", None, ("sweep", "{tmp}/missing.toml")),
        Case("file used as a directory", LINE.encode(), ("run", "{scene}/x.toml", "--csv", "{tmp}/report.csv")),
    ]


def _syntax_cases() -> list[Case]:
    """TOML syntax errors and nesting."""
    deep = 10_000
    return [
        _line("unclosed table header", "[contact]\n", "[contact\n"),
        _line("unclosed string", 'load = "1 kN"', 'load = "1 kN'),
        _line("duplicate key", 'load = "1 kN"', 'load = "1 kN"\nload = "2 kN"'),
        _line("duplicate table", "[contact.lubricant]", "[contact.body2]\nx = 1\n[contact.lubricant]"),
        _line("key without value", 'length = "10 mm"', "length ="),
        _line("bare word value", 'length = "10 mm"', "length = mm"),
        _line("number then word", 'length = "10 mm"', "length = 10 mm"),
        _line("unclosed array", '"h_c", "regime"]', '"h_c", "regime"'),
        _line("unclosed inline table", 'units = { h_c = "um", p_h = "MPa" }', 'units = { h_c = "um"'),
        _line("invalid escape", 'name = "steel"', 'name = "st\\qeel"'),
        _line("python syntax", 'load = "1 kN"', "load = Q_(1, 'kN')"),
        _line("deep nesting: 10000 arrays", 'outputs = ["b", "p_h", "h_c", "regime"]',
              "outputs = " + "[" * deep + "]" * deep),
        _line("deep nesting: 10000 inline tables", 'film = "moes"', "film = " + "{a = " * deep + "1" + "}" * deep),
        _line("nesting above the bound (arrays)", 'outputs = ["b", "p_h", "h_c", "regime"]',
              "outputs = " + "[" * (MAX_NESTING + 4) + "]" * (MAX_NESTING + 4)),
        _line("nesting above the bound (tables)", "[contact.lubricant]",
              "[contact.lubricant." + ".".join(f"t{i}" for i in range(MAX_NESTING + 4)) + "]\nx = 1\n[contact.lubricant]"),
    ]


def _structure_cases() -> list[Case]:
    """Scene kinds, tables, keys at every level."""
    cam = default_scene_text()
    return [
        _line("unknown scene kind", 'scene = "line_contact"', 'scene = "gearbox"'),
        _line("scene kind an array", 'scene = "line_contact"', 'scene = ["line_contact"]'),
        _line("scene kind a number", 'scene = "line_contact"', "scene = 3"),
        _line("scene kind missing", 'scene = "line_contact"\n', ""),
        _run("missing [contact]", LINE.split("[contact]")[0]),
        _run("contact a string", 'contact = "steel on steel"\n' + LINE.split("[contact]")[0]),
        _line("unknown top-level key", 'scene = "line_contact"', 'scene = "line_contact"\nspeed = "1 m/s"'),
        _line("unknown key in [contact]", 'load = "1 kN"', 'load = "1 kN"\nforce = "1 kN"'),
        _line("unknown key in body1", 'radius = "20 mm"', 'radius = "20 mm"\nradiu = "20 mm"'),
        _line("unknown key in body1.material", 'E = "210 GPa"', 'E = "210 GPa"\nyoung = "210 GPa"'),
        _line("unknown key in lubricant", 'nu40 = "100 cSt"', 'nu40 = "100 cSt"\nnu60 = "40 cSt"'),
        _cam("unknown key in cam", 'base_radius = "40 mm"', 'base_radius = "40 mm"\nradius = "40 mm"'),
        _cam("unknown key in follower", 'offset = "5 mm"', 'offset = "5 mm"\noffset_angle = "5 deg"'),
        _cam("unknown key in valve_train", 'preload = "1000 N"', 'preload = "1000 N"\nspring = "1 N/m"'),
        _cam("unknown key in program", "segments = [", "segment = ["),
        _cam("unknown key in a segment", '{ law = "P-1",', '{ law = "P-1", ramp = "1 deg",'),
        _line("unknown key in [report]", "units = {", "unit = {"),
        _run("missing body2", LINE.split("[contact.body2]")[0] + "[contact.lubricant]" + LINE.split("[contact.lubricant]")[1]),
        _line("name a table", 'name = "corpus line contact"', "name = { label = 1 }"),
        _line("outputs empty", 'outputs = ["b", "p_h", "h_c", "regime"]', "outputs = []"),
        _line("outputs a string", 'outputs = ["b", "p_h", "h_c", "regime"]', 'outputs = "b"'),
        _line("outputs numbers", 'outputs = ["b", "p_h", "h_c", "regime"]', "outputs = [1, 2]"),
        _line("effects a table", 'effects = ["elasticity", "piezoviscosity"]', "effects = { thermal = true }"),
        _run("default scene without [contact.cam]", cam.split("[contact.cam]")[0] + "[contact.follower]"
             + cam.split("[contact.follower]")[1]),
    ]


def _type_cases() -> list[Case]:
    """Wrong TOML types for fields."""
    return [
        _line("string for a number", "nu = 0.3", 'nu = "abc"'),
        _line("string 'false' for a number", "nu = 0.3", 'nu = "false"'),
        _line("table for a string", 'name = "ISO VG 100"', "name = { oil = 1 }"),
        _line("array for a scalar quantity", 'load = "1 kN"', 'load = ["1 kN", "2 kN"]'),
        _line("boolean as string", "concave = false", 'concave = "false"'),
        _line("number for a boolean", "concave = false", "concave = 0"),
        _line("boolean for a quantity", 'load = "1 kN"', "load = true"),
        _line("date for a quantity", 'load = "1 kN"', "load = 1979-05-27"),
        _run("string for a table", _edit(_edit(LINE, _BODY1, ""), 'temperature = "60 degC"',
                                         'temperature = "60 degC"\nbody1 = "steel"')),
        _run("array for a table", _edit(_edit(LINE, _BODY2_MATERIAL, ""), 'radius = "10 mm"',
                                        'radius = "10 mm"\nmaterial = [1, 2]')),
        _line("misspelt nested table", "[contact.body1.material]", "[contact.body1.materia]"),
        _run("string for the segments", re.sub(r"segments = \[.*?\n\]", 'segments = "P-1"', default_scene_text(),
                                               flags=re.DOTALL)),
        _cam("unknown follower kind", 'kind = "roller"', 'kind = "flat-faced"'),
        _cam("unknown convention", 'convention = "consistent"', 'convention = "false"'),
    ]


def _quantity_cases() -> list[Case]:
    """Quantities: dimension, units alone, expressions, non-finite, ranges."""
    load = 'load = "1 kN"'
    return [
        _line("wrong dimension", load, 'load = "1 mm"'),
        _line("a unit alone", load, 'load = "kN"'),
        _line("a unit alone (mm)", 'length = "10 mm"', 'length = "mm"'),
        _line("a bare number string", load, 'load = "1000"'),
        _line("a bare number", load, "load = 1000"),
        _line("expression (10**400) N", load, 'load = "(10**400) N"'),
        _line("expression (10**10**8) N", load, 'load = "(10**10**8) N"'),
        _line("expression __import__", load, """load = "__import__('os').system('touch X') N\""""),
        _line("product with code", load, """load = "1 * __import__('os').getcwd()\""""),
        _line("NaN quantity", load, 'load = "nan N"'),
        _line("inf quantity", load, 'load = "inf N"'),
        _line("-inf quantity", load, 'load = "-inf N"'),
        _line("overflow to inf", load, 'load = "1e400 N"'),
        _line("TOML nan number", "nu = 0.3", "nu = nan"),
        _line("TOML inf number", "nu = 0.3", "nu = inf"),
        _line("negative load", load, 'load = "-1 kN"'),
        _line("zero load", load, 'load = "0 kN"'),
        _line("zero radius", 'radius = "20 mm"', 'radius = "0 mm"'),
        _line("negative modulus", 'E = "210 GPa"', 'E = "-210 GPa"'),
        _line("Poisson ratio 0.5", "nu = 0.3", "nu = 0.5"),
        _line("huge integer", "nu = 0.3", "nu = 99999999999999999999999999999"),
        _line("temperature below absolute zero", 'temperature = "60 degC"', 'temperature = "-300 degC"'),
        _line("unit power 1000", 'length = "10 mm"', 'length = "10 m**1000"'),
        _line("unit text too long", 'length = "10 mm"', 'length = "10 ' + "m*" * 100 + 'm"'),
        _cam("angle step 1e-4 deg", 'angle_step = "1 deg"', 'angle_step = "1e-4 deg"'),
        _cam("zero cam speed", 'speed = "1000 rpm"', 'speed = "0 rpm"'),
        _cam("cam speed in mm", 'speed = "1000 rpm"', 'speed = "1000 mm"'),
    ]


def _model_cases() -> list[Case]:
    """Model names and slots, effects, outputs."""
    cam = default_scene_text()
    return [
        _line("unknown film model", 'film = "moes"', 'film = "zzz"'),
        _line("unknown model in a variant list", 'film = "moes"', 'film = ["moes", "zzz"]'),
        _line("model slot that does not exist", 'film = "moes"', 'film = "moes"\ngearbox = "moes"'),
        _line("model name a number", 'film = "moes"', "film = 3"),
        _line("model name a table", 'film = "moes"', "film = { name = \"moes\" }"),
        _line("empty model list", 'film = "moes"', "film = []"),
        _run("models a string", _edit(LINE, '[models]\nfilm = "moes"', 'models = "moes"')),
        _line("unknown effect", 'effects = ["elasticity", "piezoviscosity"]', 'effects = ["elasticity", "magic"]'),
        _line("unknown output", '"h_c", "regime"]', '"h_c", "regime", "zz"]'),
        _line("output of another scene", '"h_c", "regime"]', '"h_c", "regime", "k_min"]'),
        _cam("unknown motion law", 'law = "P-2"', 'law = "P-9"'),
        _cam("unknown film model (cam)", 'film = "pan_hamrock"', 'film = "zzz"'),
        _cam("unknown model slot (cam)", 'film = "pan_hamrock"', 'film = "pan_hamrock"\nengine = "v8"'),
        _cam("unknown output (cam)", 'scene = "cam_follower"', 'scene = "cam_follower"\noutputs = ["h_min", "zz"]'),
        _cam("unknown effect (cam)", 'scene = "cam_follower"', 'scene = "cam_follower"\neffects = ["warp"]'),
        _run("cam scene with line-contact fields", _edit(cam, 'speed = "1000 rpm"', 'load = "1 kN"')),
    ]


def _report_cases() -> list[Case]:
    """[report] units."""
    units = 'units = { h_c = "um", p_h = "MPa" }'
    return [
        _line("report unit of an unknown quantity", units, 'units = { zz = "um" }'),
        _line("report unit of a wrong dimension", units, 'units = { h_c = "GPa" }'),
        _line("report unit unknown", units, 'units = { h_c = "furlongs_per_mm" }'),
        _line("report unit with numbers", units, 'units = { h_c = "10**3 nm" }'),
        _line("report unit with code", units, """units = { h_c = "__import__('os').getcwd()" }"""),
        _line("report unit a number", units, "units = { h_c = 1e-6 }"),
        _line("report units a list", units, 'units = ["um"]'),
        _line("report unit of a text quantity", units, 'units = { regime = "nm" }'),
        _line("report unit of a quantity not asked for", units, 'units = { h_min = "nm" }'),
        _run("report a string", 'report = "nm"\n' + _edit(LINE, '[report]\nunits = { h_c = "um", p_h = "MPa" }', "")),
        _cam("report unit wrong (cam)", 'units = { h_min = "um"', 'units = { h_min = "rpm"'),
    ]


def _sweep_cases() -> list[Case]:
    """[sweep] tables (run by ``camcontact sweep``)."""
    table = 'load = ["1 kN", "2 kN"]'
    paths = ["load", "length", "temperature", "body1.radius", "body2.radius", "body1.material.E",
             "body2.material.E", "body1.speed", "body2.speed", "lubricant.nu40"]
    units = ["kN", "mm", "degC", "mm", "mm", "GPa", "GPa", "m/s", "m/s", "cSt"]
    huge = "\n".join(f'"{p}" = [' + ", ".join(f'"{k + 1} {u}"' for k in range(100)) + "]" for p, u in zip(paths, units))
    assert 100 ** len(paths) > MAX_SWEEP_CASES
    return [
        _sweep("sweep path unknown", _edit(LINE, table, 'lode = ["1 kN"]')),
        _sweep("sweep path through a quantity", _edit(LINE, table, '"load.value" = ["1 kN"]')),
        _sweep("sweep path empty segment", _edit(LINE, table, '"body1..radius" = ["1 mm"]')),
        _sweep("sweep empty list", _edit(LINE, table, "load = []")),
        _sweep("sweep not a list", _edit(LINE, table, 'load = "1 kN"')),
        _sweep("sweep a list", 'sweep = ["load"]\n' + _edit(LINE, f"[sweep]\n{table}", "")),
        _sweep("sweep 10 paths x 100 values (1e20 cases)", _edit(LINE, table, huge)),
        _sweep("sweep 300k cases", _edit(LINE, table, 'load = [' + ", ".join(['"1 kN"'] * 300) + "]\n"
                                         + 'length = [' + ", ".join(['"10 mm"'] * 1000) + "]")),
        _sweep("sweep value of a wrong dimension", _edit(LINE, table, 'load = ["1 kN", "2 mm"]')),
        _sweep("sweep value an expression", _edit(LINE, table, 'load = ["1 kN", "(10**10**8) N"]')),
        _sweep("sweep value a unit alone", _edit(LINE, table, 'load = ["kN"]')),
        _sweep("sweep value a table", _edit(LINE, table, 'load = [{ a = 1 }]')),
        _sweep("sweep value NaN", _edit(LINE, table, 'load = ["nan N"]')),
        _sweep("sweep value negative", _edit(LINE, table, 'load = ["1 kN", "-2 kN"]')),
        _sweep("sweep value a boolean as string", _edit(LINE, table, '"body1.concave" = ["false"]')),
        _sweep("sweep of a scene without [sweep]", _edit(LINE, f"[sweep]\n{table}", "")),
        _sweep("sweep --workers -1", LINE, "--workers", "-1"),
        _sweep("sweep --workers abc", LINE, "--workers", "abc"),
        Case("sweep without a scene", None, ("sweep",)),
    ]


def _cli_cases() -> list[Case]:
    """Bad command lines (scene files valid)."""
    line = LINE.encode("utf-8")
    csv = ("--csv", "{tmp}/report.csv")

    def run(name: str, *argv: str, status: int = BAD_INPUT, **options) -> Case:
        return Case(name, line, ("run", "{scene}", *argv), status, **options)

    return [
        Case("no command", None, ()),
        Case("unknown command", None, ("frobnicate",)),
        Case("unknown option", None, ("--frobnicate", "run")),
        run("unknown run option", *csv, "--frobnicate"),
        run("two scenes", "{scene}", *csv),
        run("--units without =", *csv, "--units", "h_c"),
        run("--units without a name", *csv, "--units", "=nm"),
        run("--units without a unit", *csv, "--units", "h_c="),
        run("--units with an empty pair", *csv, "--units", "h_c=nm,,p_h=GPa"),
        run("--units without a value", *csv, "--units"),
        run("--units unknown name", *csv, "--units", "zz=nm"),
        run("--units output not asked for", *csv, "--units", "h_min=nm"),
        run("--units unknown unit", *csv, "--units", "h_c=furlong_per_mm"),
        run("--units wrong dimension", *csv, "--units", "h_c=GPa"),
        run("--units second pair wrong", *csv, "--units", "h_c=nm,p_h=mm"),
        run("--units text quantity", *csv, "--units", "regime=nm"),
        run("--units expression", *csv, "--units", "h_c=(10**400)*nm"),
        run("--units code", *csv, "--units", "h_c=__import__('os').getcwd()"),
        Case("--units swallowing the scene (old form)", line, ("run", "--units", "h_c=nm", "p_h=GPa", "{scene}")),
        run("--csv in a missing directory", "--csv", "/nonexistent/dir/x.csv"),
        run("--csv a directory", "--csv", "{tmp}"),
        run("--csv empty", "--csv", ""),
        run("--csv to /dev/full", "--csv", "/dev/full", status=FAILURE, subprocess=True),
        run("--plot unwritable", *csv, "--plot", "/sys/camcontact_plot.png"),
        run("--plot in a missing directory", *csv, "--plot", "/nonexistent/dir/x.png"),
        run("--plot a directory", *csv, "--plot", "{tmp}"),
        run("--plot unknown format", *csv, "--plot", "{tmp}/plot.xyz"),
        Case("plugins --family nonexistent", None, ("plugins", "--family", "nonexistent")),
        Case("default-scene with an argument", None, ("default-scene", "extra")),
        Case("--debug with a value", None, ("--debug=yes", "run")),
        run("stdout closed (broken pipe)", *csv, status=BROKEN_PIPE, subprocess=True, closed_stdout=True),
    ]


def cases() -> list[Case]:
    """The whole corpus (every name unique)."""
    corpus = (_file_cases() + _special_file_cases() + _syntax_cases() + _structure_cases() + _type_cases()
              + _quantity_cases() + _model_cases() + _report_cases() + _sweep_cases() + _cli_cases())
    names = [case.name for case in corpus]
    duplicates = sorted({name for name in names if names.count(name) > 1})
    if duplicates:
        raise AssertionError(f"corpus: duplicate names {duplicates}")
    return corpus


CASES = cases()

#: code that creates the file ``{marker}`` if anything evaluates it (Python, f-strings, format, pint-style)
MARKER_PAYLOADS = (
    "__import__('pathlib').Path('{marker}').touch()",
    "1 * __import__('pathlib').Path('{marker}').touch()",
    "1 N * __import__('pathlib').Path('{marker}').touch()",
    "{{__import__('pathlib').Path('{marker}').touch()}}",
    "f\"{{__import__('pathlib').Path('{marker}').touch()}}\"",
    "exec(\"__import__('pathlib').Path('{marker}').touch()\")",
    "1 kN; __import__('pathlib').Path('{marker}').touch()",
    "{{0.__class__.__init__.__globals__}}",
)


def marker_cases(marker: str) -> list[Case]:
    """Scenes and calls with a payload that would create ``marker`` in every string slot, one slot per case.

    Each fails with exit status 2, except the free-text labels (``name`` of the scene, a material, the
    lubricant), which are accepted as text and run (status 0): a label is printed, never evaluated.
    """
    result = []
    for number, template in enumerate(MARKER_PAYLOADS):
        payload = template.format(marker=marker)
        quoted = _toml(payload)
        slots = {
            "quantity": ('load = "1 kN"', f"load = {quoted}"),
            "number": ("nu = 0.3", f"nu = {quoted}"),
            "boolean": ("concave = false", f"concave = {quoted}"),
            "scene kind": ('scene = "line_contact"', f"scene = {quoted}"),
            "model name": ('film = "moes"', f"film = {quoted}"),
            "model variant": ('film = "moes"', f'film = ["moes", {quoted}]'),
            "model slot": ('film = "moes"', f'{quoted} = "moes"'),
            "output": ('"h_c", "regime"]', f'"h_c", {quoted}]'),
            "effect": ('effects = ["elasticity", "piezoviscosity"]', f'effects = ["elasticity", {quoted}]'),
            "report unit": ('units = { h_c = "um", p_h = "MPa" }', f"units = {{ h_c = {quoted} }}"),
            "report quantity": ('units = { h_c = "um", p_h = "MPa" }', f'units = {{ {quoted} = "nm" }}'),
            "contact key": ('load = "1 kN"', f'load = "1 kN"\n{quoted} = "1 kN"'),
            "top-level key": ('scene = "line_contact"', f'scene = "line_contact"\n{quoted} = 1'),
            "table name": ("[contact.lubricant]", f"[contact.lubricant]\n[contact.{quoted}]"),
        }
        for slot, (old, new) in slots.items():
            result.append(_run(f"marker {number} in {slot}", _edit(LINE, old, new)))
        sweeps = {
            "sweep value": ('load = ["1 kN", "2 kN"]', f'load = ["1 kN", {quoted}]'),
            "sweep path": ('load = ["1 kN", "2 kN"]', f'{quoted} = ["1 kN"]'),
        }
        for slot, (old, new) in sweeps.items():
            result.append(_sweep(f"marker {number} in {slot}", _edit(LINE, old, new)))
        cam = default_scene_text()
        result += [
            _run(f"marker {number} in motion law", _edit(cam, 'law = "P-2"', f"law = {quoted}")),
            _run(f"marker {number} in follower kind", _edit(cam, 'kind = "roller"', f"kind = {quoted}")),
            Case(f"marker {number} in --units unit", LINE.encode(),
                 ("run", "{scene}", "--csv", "{tmp}/report.csv", "--units", f"h_c={payload}")),
            Case(f"marker {number} in --units name", LINE.encode(),
                 ("run", "{scene}", "--csv", "{tmp}/report.csv", "--units", f"{payload}=nm")),
            Case(f"marker {number} in plugins --family", None, ("plugins", "--family", payload)),
        ]
        for slot, old in (("scene name", 'name = "corpus line contact"'), ("material name", 'name = "steel"'),
                          ("lubricant name", 'name = "ISO VG 100"')):
            result.append(_run(f"marker {number} in {slot} (a label: runs)",
                               _edit(LINE, old, f"name = {quoted}"), status=0))
    return result


def prepare(case: Case, tmp: Path) -> list[str]:
    """Write the case's scene file (and FIFO) into ``tmp``; its arguments with the placeholders filled in."""
    scene = tmp / "scene.toml"
    if case.scene is not None:
        scene.write_bytes(case.scene)
    if case.setup == "fifo":
        os.mkfifo(tmp / "fifo.toml")
    return [arg.replace("{scene}", str(scene)).replace("{tmp}", str(tmp)) for arg in case.argv]


def run_subprocess(case: Case, tmp: Path, timeout: float = 60.0) -> Outcome:
    """Run the case as ``python -m camcontact ...`` in ``tmp`` (its cwd), bounded by ``timeout`` [s]."""
    argv = [sys.executable, "-m", "camcontact", *prepare(case, tmp)]
    start = time.perf_counter()
    process = subprocess.Popen(argv, cwd=tmp, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True, encoding="utf-8", errors="replace")
    if case.closed_stdout:  # the reader goes away before anything is written
        process.stdout.close()
        process.stdout = None
    try:
        stdout, stderr = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        process.kill()
        process.communicate()
        return Outcome(None, "", "", time.perf_counter() - start)
    return Outcome(process.returncode, stdout or "", stderr, time.perf_counter() - start)


def problems(case: Case, outcome: Outcome) -> list[str]:
    """What ``outcome`` got wrong for ``case`` (empty: as it should be)."""
    found = []
    if outcome.status is None:
        return ["hang (no exit within the time bound)"]
    if outcome.status != case.status:
        found.append(f"exit status {outcome.status}, expected {case.status}")
    if "Traceback" in outcome.stderr or "Traceback" in outcome.stdout:
        found.append("traceback")
    lines = outcome.stderr.splitlines()
    if case.status == 0:
        if lines:
            found.append(f"stderr not empty: {lines[:3]}")
    elif case.closed_stdout:
        if lines:
            found.append(f"stderr not quiet after a broken pipe: {lines[:3]}")
    elif len(lines) != 1:
        found.append(f"{len(lines)} lines on stderr, expected 1: {lines[:4]}")
    elif not lines[0].startswith("camcontact: error: "):
        found.append(f"stderr line does not start with 'camcontact: error: ': {lines[0][:200]!r}")
    return found
