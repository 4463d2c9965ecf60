"""The scenes whose complete reports are frozen as golden files (tests/regression/golden/).

Each case is an Analysis asking for *every* output its scene graph can give from its inputs
(not only the default outputs); the golden file holds ``to_frame()`` and, for scenes with an
index (cam angle, roller), ``summary_frame()``, with the list of outputs asked for.

Regenerate (only when a change of results is intended and explained in the commit):
``python -m tests.regression.scene_reports``.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import attrs
import numpy as np
import pandas as pd

import camcontact as cc
from camcontact.dynamics.valve_train_ode import LumpedValveTrain
from camcontact.quantities import QUANTITIES
from camcontact.scene_file import default_scene_text, load_scene, parse_scene

ROOT = Path(__file__).resolve().parents[2]
GOLDEN = Path(__file__).resolve().parent / "golden"
TUTORIAL_SCENES = sorted((ROOT / "tutorials").glob("*.toml"))


def default_scene():
    return parse_scene(default_scene_text(), "default scene")


def cases() -> dict[str, tuple]:
    """name -> (scene component, models, effects) of every frozen report."""
    out = {}
    default = default_scene()
    out["default_scene"] = (default.component, default.models, default.effects)
    for path in TUTORIAL_SCENES:
        scene = load_scene(path)
        out[f"tutorial_{path.stem}"] = (scene.component, scene.models, scene.effects)
    cam = default.component
    lumped = attrs.evolve(cam, valve_train=attrs.evolve(cam.valve_train, lumped=LumpedValveTrain.ferrarese_2dof()))
    # the dynamics effect beside the default ones (the default film formula needs elasticity and piezoviscosity)
    out["cam_dynamics"] = (lumped, default.models, {"elasticity", "piezoviscosity", "compressibility", "dynamics"})
    out["cam_multigrid"] = (cam, {"film": cc.registry.get("film_models", "multigrid", threads=2)}, None)
    return out


def all_outputs(component, models, effects) -> tuple[list[str], dict[str, str]]:
    """Every reportable quantity the scene graph can give with these models (reachable from its inputs),
    and those that are reachable but whose step refuses to run (name -> the error's text)."""
    planner = cc.Analysis(component, models=models, effects=effects)
    names = []
    for graph, _, _ in planner.plans.values():
        for step in graph.steps:
            names += [name for name in step.provides if name in QUANTITIES and name not in names]
    reachable = []
    for name in names:
        try:
            cc.Analysis(component, outputs=[name], models=models, effects=effects)
        except cc.InputError:
            continue
        reachable.append(name)
    try:
        _run(component, models, effects, reachable)
        return reachable, {}
    except cc.InputError:
        pass
    refused = {}
    for name in reachable:
        try:
            _run(component, models, effects, [name])
        except cc.InputError as exc:
            refused[name] = str(exc)
    return [name for name in reachable if name not in refused], refused


def _run(component, models, effects, outputs):
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return cc.Analysis(component, outputs=outputs, models=models, effects=effects, strict=True).run()


def report(component, models, effects, outputs) -> dict:
    """The complete report of one case as plain data."""
    result = _run(component, models, effects, outputs)
    frames = {"to_frame": result.to_frame()}
    if result.index is not None:
        frames["summary_frame"] = result.summary_frame()
    return {name: frame_data(frame) for name, frame in frames.items()}


def frame_data(frame: pd.DataFrame) -> dict:
    def cell(value):
        if isinstance(value, (bool, np.bool_)):
            return {"bool": bool(value)}
        if isinstance(value, (int, float, np.integer, np.floating)):
            value = float(value)
            return value if math.isfinite(value) else {"float": repr(value)}
        if value is None:
            return None
        return str(value)

    return {"columns": [str(c) for c in frame.columns],
            "rows": [[cell(v) for v in row] for row in frame.itertuples(index=False, name=None)]}


def load(name: str) -> dict:
    return json.loads((GOLDEN / f"{name}.json").read_text())


def freeze() -> None:
    GOLDEN.mkdir(exist_ok=True)
    for name, (component, models, effects) in cases().items():
        outputs, refused = all_outputs(component, models, effects)
        data = {"outputs": outputs, "refused": refused, **report(component, models, effects, outputs)}
        (GOLDEN / f"{name}.json").write_text(json.dumps(data, indent=0, ensure_ascii=False) + "\n")
        print(f"{name}: {len(outputs)} outputs, {len(refused)} refused", file=sys.stderr)


if __name__ == "__main__":
    freeze()
