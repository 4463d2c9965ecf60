"""Scene files: a TOML description of a scene, read without executing any code.

Quantities are strings with units (``"15 mm"``, ``"85 degC"``); dimensionless numbers are
plain TOML numbers. Every table maps onto the fields of a component, so an unknown key is
reported with the keys that are allowed. Layout::

    scene = "line_contact"            # the scene kind
    name = "..."                      # optional label
    outputs = ["b", "p_h", "h_min"]   # optional; default: the scene's default outputs
    effects = ["elasticity", "piezoviscosity"]   # optional

    [models]                          # optional: model per slot; a list makes variants
    film = ["grubin", "moes"]

    [report]                          # optional
    units = { h_min = "nm" }

    [sweep]                           # optional: `camcontact sweep` runs the cartesian product
    speed = ["500 rpm", "1000 rpm"]
    "cam.base_radius" = ["30 mm", "40 mm"]

    [contact]                         # LineContact fields
    load = "10 kN"
    length = "41.35 mm"
    [contact.body1]                   # Body fields
    radius = "149 mm"
    [contact.body1.material]          # Material fields
    E = "200 GPa"
    nu = 0.3
    [contact.body2] ...
    [contact.lubricant]               # Lubricant fields
    nu40 = "575 cSt"

A ``cam_follower`` scene's [contact] table holds :class:`~camcontact.components.CamFollower`
fields, with nested [contact.cam] (its ``program`` a table of ``segments``), [contact.follower],
[contact.valve_train] and [contact.lubricant] tables. A ``raceway_contact`` scene's [contact] holds
:class:`~camcontact.components.RacewayContact` fields with [contact.raceway_material],
[contact.roller_material] and [contact.lubricant]; its [models] ``convention = ["thesis",
"corrected"]`` runs both side by side. A ``bearing`` scene's [contact] holds
:class:`~camcontact.components.LoadedBearing` fields with [contact.bearing] (a
:class:`~camcontact.components.SphericalRollerBearing`, its [contact.bearing.material]) and
[contact.lubricant]. A ``ball_cone_cvt`` scene's [contact] holds
:class:`~camcontact.components.LoadedBallConeCVT` fields with [contact.cvt] (a
:class:`~camcontact.components.BallConeCVT`, its [contact.cvt.material] and [contact.cvt.lubricant]).
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from importlib import resources
from pathlib import Path
from typing import Any

import attrs

from .analysis import Analysis
from .components import (BallConeCVT, Body, Cam, CamFollower, Follower, LineContact, LoadedBallConeCVT, LoadedBearing,
                         Lubricant, Material, RacewayContact, SphericalRollerBearing, ValveTrain)
from .errors import InputError

__all__ = ["DEFAULT_SCENE", "Scene", "default_scene_text", "load_scene", "parse_scene"]

DEFAULT_SCENE = "default_scene.toml"

def _motion_program(table: Any, where: str) -> Any:
    """A cam's ``program`` table: ``segments = [{law, start, end, lift_start, lift_end}, ...]``."""
    from .kinematics.motion_program import MotionProgram

    if not isinstance(table, Mapping) or set(table) != {"segments"} or not isinstance(table["segments"], list):
        raise InputError(f"{where}: expected a table with one key, segments = [{{law = \"P-1\", start = \"0 deg\", "
                         f"end = \"90 deg\", lift_start = \"0 mm\", lift_end = \"20 mm\"}}, ...]")
    return MotionProgram.from_segments(table["segments"])


#: scene kind -> component class of the [contact] table (the scene component)
_KINDS = {"line_contact": LineContact, "cam_follower": CamFollower, "raceway_contact": RacewayContact,
          "bearing": LoadedBearing, "ball_cone_cvt": LoadedBallConeCVT}
#: nested tables: component class -> {field: component class, or a builder(table, where)}
_NESTED: dict[type, dict[str, Any]] = {
    LineContact: {"body1": Body, "body2": Body, "lubricant": Lubricant},
    Body: {"material": Material},
    CamFollower: {"cam": Cam, "follower": Follower, "valve_train": ValveTrain, "lubricant": Lubricant},
    Cam: {"material": Material, "program": _motion_program},
    Follower: {"material": Material},
    RacewayContact: {"raceway_material": Material, "roller_material": Material, "lubricant": Lubricant},
    LoadedBearing: {"bearing": SphericalRollerBearing, "lubricant": Lubricant},
    SphericalRollerBearing: {"material": Material},
    LoadedBallConeCVT: {"cvt": BallConeCVT},
    BallConeCVT: {"material": Material, "lubricant": Lubricant},
}
_TOP_KEYS = {"scene", "name", "outputs", "effects", "models", "report", "contact", "sweep"}


@attrs.frozen
class Scene:
    """A parsed scene file: the component and what to ask of it."""

    kind: str
    name: str
    component: Any
    outputs: tuple[str, ...] | None
    effects: tuple[str, ...] | None
    models: dict[str, Any]
    units: dict[str, str]
    #: the [sweep] table: field path -> list of values (empty: no sweep)
    sweep: dict[str, list] = attrs.field(factory=dict)

    def analysis(self) -> Analysis:
        """The :class:`~camcontact.analysis.Analysis` this scene describes."""
        return Analysis(self.component, outputs=self.outputs, models=self.models, effects=self.effects)


def _build(cls: type, table: Any, where: str) -> Any:
    if not isinstance(table, Mapping):
        raise InputError(f"{where}: expected a table of {cls.__name__} fields, got {table!r}")
    allowed = {field.name for field in attrs.fields(cls)}
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise InputError(f"{where}: unknown keys {unknown} for {cls.__name__}; allowed: {', '.join(sorted(allowed))}")
    arguments = {}
    for key, value in table.items():
        nested = _NESTED.get(cls, {}).get(key)
        if nested is None:
            arguments[key] = value
        elif attrs.has(nested):
            arguments[key] = _build(nested, value, f"{where}.{key}")
        else:
            arguments[key] = nested(value, f"{where}.{key}")
    try:
        return cls(**arguments)
    except TypeError as exc:  # a missing required field
        raise InputError(f"{where}: {exc}") from None


def _string_list(data: Mapping, key: str, where: str) -> tuple[str, ...] | None:
    if key not in data:
        return None
    value = data[key]
    if not (isinstance(value, list) and all(isinstance(v, str) for v in value)):
        raise InputError(f"{where}: {key} must be a list of strings, got {value!r}")
    return tuple(value)


def parse_scene(text: str, where: str = "scene") -> Scene:
    """Parse scene TOML text into a :class:`Scene` (see the module docstring)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{where}: not valid TOML ({exc})") from None
    unknown = sorted(set(data) - _TOP_KEYS)
    if unknown:
        raise InputError(f"{where}: unknown top-level keys {unknown}; allowed: {', '.join(sorted(_TOP_KEYS))}")
    kind = data.get("scene")
    if kind not in _KINDS:
        raise InputError(f"{where}: scene = {kind!r}; known scene kinds: {', '.join(_KINDS)}")
    if "contact" not in data:
        raise InputError(f"{where}: missing the [contact] table")
    component = _build(_KINDS[kind], data["contact"], f"{where} [contact]")
    models = data.get("models", {})
    if not isinstance(models, Mapping):
        raise InputError(f"{where}: [models] must be a table of slot = name (or list of names)")
    report = data.get("report", {})
    units = report.get("units", {}) if isinstance(report, Mapping) else None
    if not isinstance(units, Mapping) or not all(isinstance(v, str) for v in units.values()):
        raise InputError(f"{where}: [report] units must be a table of quantity = \"unit\"")
    sweep = data.get("sweep", {})
    if not isinstance(sweep, Mapping) or not all(isinstance(v, list) and v for v in sweep.values()):
        raise InputError(f"{where}: [sweep] must be a table of path = [value, ...] (e.g. speed = [\"500 rpm\", "
                         f"\"1000 rpm\"], \"cam.base_radius\" = [\"30 mm\", \"40 mm\"])")
    if sweep:
        from .sweep_cases import check_path

        for path in sweep:
            check_path(component, path)
    return Scene(
        kind=kind, name=str(data.get("name", kind)), component=component,
        outputs=_string_list(data, "outputs", where), effects=_string_list(data, "effects", where),
        models=dict(models), units=dict(units), sweep={str(k): list(v) for k, v in sweep.items()},
    )


def load_scene(path: str | Path | None = None) -> Scene:
    """Read a scene file; ``None`` reads the embedded default scene."""
    if path is None:
        return parse_scene(default_scene_text(), where=f"embedded {DEFAULT_SCENE}")
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise InputError(f"cannot read scene file {str(path)!r}: {exc.strerror}") from None
    return parse_scene(text, where=str(path))


def default_scene_text() -> str:
    """TOML text of the embedded default scene."""
    return resources.files("camcontact.data").joinpath(DEFAULT_SCENE).read_text(encoding="utf-8")
