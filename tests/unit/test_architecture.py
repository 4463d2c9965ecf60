"""The shape of the code: the import layers hold (import-linter contracts in pyproject.toml), no module
imports another module's private names, scene builders stay short."""

from __future__ import annotations

import ast
import inspect
from pathlib import Path

from camcontact.step_graph import scene_builders

ROOT = Path(__file__).resolve().parents[2]
#: a scene builder states inputs, steps, defaults, effects and plot: short enough to read at a glance
BUILDER_LINES = 60


def test_import_contracts_hold(capsys):
    """The layers contract (no module imports from a layer above its own, independent siblings stay
    independent) and the acyclic-siblings contract (no import circle among the modules or subpackages
    of any package), as `lint-imports` checks them."""
    from importlinter import cli  # the [test] extra

    status = cli.lint_imports(config_filename=str(ROOT / "pyproject.toml"), no_cache=True, no_logo=True)
    report = capsys.readouterr().out
    assert status == 0, report
    assert "2 kept, 0 broken" in report


def private_imports(source: str, where: str) -> list[str]:
    """``from x import _name`` of a private name from another module (a private *module* of the
    importing module's own package, ``from . import _kernels``, is the package's own business)."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, ast.ImportFrom):
            continue
        own_package_module = node.level == 1 and node.module is None
        for alias in node.names:
            if alias.name.startswith("_") and not alias.name.startswith("__") and not own_package_module:
                found.append(f"{where}:{node.lineno}: from {'.' * node.level}{node.module or ''} import {alias.name}")
    return found


def test_no_private_name_is_imported_across_modules():
    files = sorted((ROOT / "camcontact").rglob("*.py")) + sorted((ROOT / "plugins").rglob("*.py"))
    assert len(files) > 50
    found = [line for path in files
             for line in private_imports(path.read_text(encoding="utf-8"), str(path.relative_to(ROOT)))]
    assert not found, "\n".join(found)


def test_the_private_import_check_finds_one():
    source = "from .line_multigrid import _stagnated, solve\nfrom . import _kernels\nfrom ._kernels import relax\n"
    assert private_imports(source, "x.py") == ["x.py:1: from .line_multigrid import _stagnated"]


def test_scene_builders_are_short():
    builders = {cls: f for cls, f in scene_builders().items() if f.__module__.startswith("camcontact.scenes.")}
    assert {cls.__name__ for cls in builders} == {"LineContact", "CamFollower", "RacewayContact", "LoadedBearing",
                                                  "LoadedBallConeCVT", "PointContact", "LoadedBallBearing",
                                                  "LoadedCylindricalRollerBearing"}
    for function in builders.values():
        lines = inspect.getsource(function).count("\n")
        assert lines <= BUILDER_LINES, f"{function.__qualname__} has {lines} lines"
