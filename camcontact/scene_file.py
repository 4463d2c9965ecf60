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

A ``point_contact`` scene's [contact] holds :class:`~camcontact.components.PointContact` fields with
[contact.body1] / [contact.body2] (each with ``radius`` along and ``transverse_radius`` across rolling) and
[contact.lubricant]. A ``cam_follower`` scene's [contact] table holds :class:`~camcontact.components.CamFollower`
fields, with nested [contact.cam] (its ``program`` a table of ``segments``), [contact.follower],
[contact.valve_train] and [contact.lubricant] tables. A ``raceway_contact`` scene's [contact] holds
:class:`~camcontact.components.RacewayContact` fields with [contact.raceway_material],
[contact.roller_material] and [contact.lubricant]; its [models] ``convention = ["thesis",
"corrected"]`` runs both side by side. A ``bearing`` scene's [contact] holds
:class:`~camcontact.components.LoadedBearing` fields with [contact.bearing] (a
:class:`~camcontact.components.SphericalRollerBearing`, its [contact.bearing.material]) and
[contact.lubricant]; a ``ball_bearing`` scene's [contact] holds :class:`~camcontact.components.LoadedBallBearing`
fields with [contact.bearing] (a :class:`~camcontact.components.BallBearing`, its [contact.bearing.material])
and [contact.lubricant]; a ``cylindrical_roller_bearing`` scene's [contact] holds
:class:`~camcontact.components.LoadedCylindricalRollerBearing` fields with [contact.bearing] (a
:class:`~camcontact.components.CylindricalRollerBearing`, its [contact.bearing.material]) and [contact.lubricant].
A ``ball_cone_cvt`` scene's [contact] holds
:class:`~camcontact.components.LoadedBallConeCVT` fields with [contact.cvt] (a
:class:`~camcontact.components.BallConeCVT`, its [contact.cvt.material] and [contact.cvt.lubricant]).
"""

from __future__ import annotations

import os
import stat
import tomllib
from collections.abc import Mapping
from importlib import resources
from pathlib import Path
from typing import Any

import attrs

from .analysis import Analysis
from .components import (
    BallBearing,
    BallConeCVT,
    Body,
    Cam,
    CamFollower,
    CylindricalRollerBearing,
    Follower,
    LineContact,
    LoadedBallBearing,
    LoadedBallConeCVT,
    LoadedBearing,
    LoadedCylindricalRollerBearing,
    Lubricant,
    Material,
    PointContact,
    RacewayContact,
    SphericalRollerBearing,
    ValveTrain,
)
from .errors import InputError
from .quantities import spec
from .sweep_cases import MAX_SWEEP_CASES, check_case_count, check_path
from .units import Q_, parse_unit

__all__ = ["DEFAULT_SCENE", "MAX_NESTING", "MAX_SCENE_BYTES", "MAX_SWEEP_CASES", "Scene", "check_report_unit",
           "default_scene_text", "load_scene", "parse_scene"]

DEFAULT_SCENE = "default_scene.toml"
#: the largest scene file read [bytes] (a scene is a few kB; checked with stat and by the bytes read)
MAX_SCENE_BYTES = 1_000_000
#: the deepest nesting of tables and arrays in a scene (the default scene has 6)
MAX_NESTING = 16
#: byte-order marks of encodings other than UTF-8 (a UTF-8 mark is skipped)
_FOREIGN_BOMS = {b"\xff\xfe\x00\x00": "UTF-32", b"\x00\x00\xfe\xff": "UTF-32", b"\xff\xfe": "UTF-16",
                 b"\xfe\xff": "UTF-16"}

def _motion_program(table: Any, where: str) -> Any:
    """A cam's ``program`` table: ``segments = [{law, start, end, lift_start, lift_end}, ...]``."""
    from .kinematics.motion_program import MotionProgram

    if not isinstance(table, Mapping) or set(table) != {"segments"} or not isinstance(table["segments"], list):
        raise InputError(f"{where}: expected a table with one key, segments = [{{law = \"P-1\", start = \"0 deg\", "
                         f"end = \"90 deg\", lift_start = \"0 mm\", lift_end = \"20 mm\"}}, ...]")
    try:
        return MotionProgram.from_segments(table["segments"])
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None


#: scene kind -> component class of the [contact] table (the scene component)
_KINDS = {"line_contact": LineContact, "cam_follower": CamFollower, "raceway_contact": RacewayContact,
          "bearing": LoadedBearing, "ball_bearing": LoadedBallBearing, "ball_cone_cvt": LoadedBallConeCVT,
          "point_contact": PointContact, "cylindrical_roller_bearing": LoadedCylindricalRollerBearing}
#: nested tables: component class -> {field: component class, or a builder(table, where)}
_NESTED: dict[type, dict[str, Any]] = {
    LineContact: {"body1": Body, "body2": Body, "lubricant": Lubricant},
    PointContact: {"body1": Body, "body2": Body, "lubricant": Lubricant},
    Body: {"material": Material},
    CamFollower: {"cam": Cam, "follower": Follower, "valve_train": ValveTrain, "lubricant": Lubricant},
    Cam: {"material": Material, "program": _motion_program},
    Follower: {"material": Material},
    RacewayContact: {"raceway_material": Material, "roller_material": Material, "lubricant": Lubricant},
    LoadedBearing: {"bearing": SphericalRollerBearing, "lubricant": Lubricant},
    SphericalRollerBearing: {"material": Material},
    LoadedBallBearing: {"bearing": BallBearing, "lubricant": Lubricant},
    BallBearing: {"material": Material},
    LoadedCylindricalRollerBearing: {"bearing": CylindricalRollerBearing, "lubricant": Lubricant},
    CylindricalRollerBearing: {"material": Material},
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
    #: where the scene came from (a file's path), named in error messages
    source: str = "scene"

    def analysis(self, strict: bool = False) -> Analysis:
        """The :class:`~camcontact.analysis.Analysis` this scene describes (planned, not run: an unknown
        model, output or effect is an InputError naming :attr:`source`); ``strict``: see
        :class:`~camcontact.analysis.Analysis`."""
        try:
            return Analysis(self.component, outputs=self.outputs, models=self.models, effects=self.effects,
                            strict=strict)
        except InputError as exc:
            raise InputError(f"{self.source}: {exc}") from None


def _build(cls: type, table: Any, where: str) -> Any:
    """The component ``cls`` of a table (nested tables built first); every problem an InputError naming
    ``where`` — the file and the table — and the key."""
    if not isinstance(table, Mapping):
        raise InputError(f"{where}: expected a table of {cls.__name__} fields, got {table!r}")
    allowed = {field.name for field in attrs.fields(cls)}
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise InputError(f"{where}: unknown keys {unknown} for {cls.__name__}; allowed: {', '.join(sorted(allowed))}")
    required = [field.name for field in attrs.fields(cls) if field.init and field.default is attrs.NOTHING]
    missing = [name for name in required if name not in table]
    if missing:
        raise InputError(f"{where}: missing keys {missing} for {cls.__name__}; required: {', '.join(required)}")
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
    except (InputError, TypeError) as exc:  # a field's check, or a field attrs refuses
        raise InputError(f"{where}: {exc}") from None


def _string_list(data: Mapping, key: str, where: str) -> tuple[str, ...] | None:
    """``outputs`` / ``effects``: absent (None) or a non-empty list of strings."""
    if key not in data:
        return None
    value = data[key]
    if not (isinstance(value, list) and value and all(isinstance(v, str) for v in value)):
        raise InputError(f"{where}: {key} must be a list of strings (at least one), got {value!r}")
    return tuple(value)


def _check_nesting(data: Any, where: str) -> None:
    """InputError when tables and arrays nest deeper than :data:`MAX_NESTING` (checked without recursion)."""
    stack = [(data, 1)]
    while stack:
        value, depth = stack.pop()
        if depth > MAX_NESTING:
            raise InputError(f"{where}: tables and arrays nested deeper than {MAX_NESTING} levels; allowed: at most "
                             f"{MAX_NESTING} (a scene needs about 6)")
        children = value.values() if isinstance(value, Mapping) else value if isinstance(value, list) else ()
        stack.extend((child, depth + 1) for child in children if isinstance(child, (Mapping, list)))


def _load_toml(text: str, where: str) -> dict[str, Any]:
    """The TOML document of ``text``: syntax errors, too deep nesting and oversize text as InputError."""
    if len(text) > MAX_SCENE_BYTES:
        raise InputError(f"{where}: {len(text)} characters; allowed: at most {MAX_SCENE_BYTES} (a scene is a few kB)")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{where}: not valid TOML ({exc})") from None
    except RecursionError:
        raise InputError(f"{where}: tables and arrays nested too deep to read; allowed: at most {MAX_NESTING} "
                         f"levels") from None
    _check_nesting(data, where)
    return data


def _scene_kind(data: Mapping, where: str) -> str:
    """The ``scene = "<kind>"`` key: one of the known scene kinds."""
    if "scene" not in data:
        raise InputError(f"{where}: missing the key scene = \"<kind>\"; known scene kinds: {', '.join(_KINDS)}")
    kind = data["scene"]
    if not isinstance(kind, str) or kind not in _KINDS:
        raise InputError(f"{where}: scene = {kind!r}; known scene kinds: {', '.join(_KINDS)}")
    return kind


def _scene_name(data: Mapping, kind: str, where: str) -> str:
    """The optional ``name`` label (a string; default: the kind)."""
    name = data.get("name", kind)
    if not isinstance(name, str):
        raise InputError(f"{where}: name = {name!r}; allowed: a string (a label for the report)")
    return name


def _models(data: Mapping, where: str) -> dict[str, Any]:
    """The [models] table: slot = "name" or slot = ["name", ...] (variants)."""
    models = data.get("models", {})
    if not isinstance(models, Mapping):
        raise InputError(f"{where}: [models] must be a table of slot = name (or list of names), got {models!r}")
    for slot, value in models.items():
        names = value if isinstance(value, list) else [value]
        if not (names and all(isinstance(name, str) for name in names)):
            raise InputError(f"{where}: [models] {slot} = {value!r}; allowed: a model name or a non-empty list of "
                             f"model names (strings)")
    return dict(models)


def check_report_unit(name: str, unit: Any, where: str) -> None:
    """InputError unless ``unit`` is a unit text (:func:`~camcontact.units.parse_unit`, nothing evaluated)
    that quantity ``name`` of the catalogue can be reported in (same dimension as its SI unit)."""
    try:
        quantity = spec(name)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None
    if quantity.si_unit is None:
        raise InputError(f"{where}: {name} is a text quantity ({quantity.description}); it has no unit")
    if not isinstance(unit, str):
        raise InputError(f"{where}: {name} = {unit!r}; allowed: a unit as a string, e.g. {quantity.display_unit!r}")
    parsed = parse_unit(unit, where=f"{where}: {name}")
    try:
        Q_(1.0, quantity.si_unit).to(parsed)
    except Exception:
        raise InputError(f"{where}: {name} = {unit!r} has dimension {parsed.dimensionality}; {name} is "
                         f"[{quantity.si_unit or 'dimensionless'}], e.g. {quantity.display_unit!r}") from None


def _report_units(data: Mapping, where: str) -> dict[str, str]:
    """The [report] table: ``units = {quantity = "unit"}``, each unit checked against its quantity."""
    report = data.get("report", {})
    if not isinstance(report, Mapping):
        raise InputError(f"{where}: [report] must be a table (units = {{h_min = \"nm\"}}), got {report!r}")
    unknown = sorted(set(report) - {"units"})
    if unknown:
        raise InputError(f"{where}: unknown keys {unknown} in [report]; allowed: units")
    units = report.get("units", {})
    if not isinstance(units, Mapping):
        raise InputError(f"{where}: [report] units must be a table of quantity = \"unit\", got {units!r}")
    for name, unit in units.items():
        check_report_unit(name, unit, f"{where} [report] units")
    return dict(units)


def _check_field_value(component: Any, path: str, value: Any, where: str) -> None:
    """InputError unless ``value`` passes the converter and validators of the field at ``path`` on its own
    (checks across fields are left to each case)."""
    *heads, last = path.split(".")
    owner = component
    for head in heads:
        owner = getattr(owner, head)
    field = attrs.fields_dict(type(owner))[last]
    converter = field.converter
    try:
        converted = value
        if isinstance(converter, attrs.Converter):
            converted = converter.converter(value, *([owner] if converter.takes_self else []),
                                            *([field] if converter.takes_field else []))
        elif converter is not None:
            converted = converter(value)
        if field.validator is not None:
            field.validator(owner, field, converted)
    except (InputError, TypeError, ValueError, OverflowError) as exc:
        raise InputError(f"{where}: {path!r} = {value!r}: {exc}") from None


def _sweep(data: Mapping, component: Any, where: str) -> dict[str, list]:
    """The [sweep] table: path = [value, ...]; paths, the number of cases and each value checked up front."""
    sweep = data.get("sweep", {})
    if not isinstance(sweep, Mapping) or not all(isinstance(v, list) and v for v in sweep.values()):
        raise InputError(f"{where}: [sweep] must be a table of path = [value, ...] (e.g. speed = [\"500 rpm\", "
                         f"\"1000 rpm\"], \"cam.base_radius\" = [\"30 mm\", \"40 mm\"])")
    check_case_count([len(values) for values in sweep.values()], f"{where}: [sweep]")
    for path, values in sweep.items():
        check_path(component, path)
        for value in values:
            _check_field_value(component, path, value, f"{where} [sweep]")
    return {str(k): list(v) for k, v in sweep.items()}


def parse_scene(text: str, where: str = "scene") -> Scene:
    """Parse scene TOML text into a :class:`Scene` (see the module docstring).

    Everything is checked here, before anything runs: TOML syntax, size and nesting
    (:data:`MAX_SCENE_BYTES`, :data:`MAX_NESTING`), the keys of every table, the component's fields, the
    model names' types, the report units (:func:`check_report_unit`) and the [sweep] table (its paths,
    at most :data:`MAX_SWEEP_CASES` cases, and each value against its field); any problem is an
    :class:`~camcontact.errors.InputError` naming ``where`` and the key.
    """
    data = _load_toml(text, where)
    unknown = sorted(set(data) - _TOP_KEYS)
    if unknown:
        raise InputError(f"{where}: unknown top-level keys {unknown}; allowed: {', '.join(sorted(_TOP_KEYS))}")
    kind = _scene_kind(data, where)
    if "contact" not in data:
        raise InputError(f"{where}: missing the [contact] table")
    component = _build(_KINDS[kind], data["contact"], f"{where} [contact]")
    return Scene(
        kind=kind, name=_scene_name(data, kind, where), component=component,
        outputs=_string_list(data, "outputs", where), effects=_string_list(data, "effects", where),
        models=_models(data, where), units=_report_units(data, where), sweep=_sweep(data, component, where),
        source=where,
    )


def _read_limited(path: Path) -> bytes:
    """The bytes of the regular file ``path`` (at most :data:`MAX_SCENE_BYTES`): FIFOs, devices and
    directories are refused before the file is opened for reading, and the read is bounded."""
    try:
        status = path.stat()
    except (OSError, ValueError) as exc:
        raise InputError(f"cannot read scene file {str(path)!r}: {getattr(exc, 'strerror', None) or exc}") from None
    if stat.S_ISDIR(status.st_mode):
        raise InputError(f"scene file {str(path)!r} is a directory; give a .toml file")
    if not stat.S_ISREG(status.st_mode):
        raise InputError(f"scene file {str(path)!r} is not a regular file (a FIFO, socket or device); give a .toml "
                         f"file")
    if status.st_size > MAX_SCENE_BYTES:
        raise InputError(f"scene file {str(path)!r}: {status.st_size} bytes; allowed: at most {MAX_SCENE_BYTES}")
    try:  # non-blocking, and checked again once open: a file swapped for a FIFO meanwhile does not block
        descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(descriptor, "rb") as file:
            if not stat.S_ISREG(os.fstat(file.fileno()).st_mode):
                raise InputError(f"scene file {str(path)!r} is not a regular file; give a .toml file")
            data = file.read(MAX_SCENE_BYTES + 1)
    except OSError as exc:
        raise InputError(f"cannot read scene file {str(path)!r}: {exc.strerror or exc}") from None
    if len(data) > MAX_SCENE_BYTES:
        raise InputError(f"scene file {str(path)!r}: more than {MAX_SCENE_BYTES} bytes; allowed: at most "
                         f"{MAX_SCENE_BYTES}")
    return data


def _decode(data: bytes, where: str) -> str:
    """UTF-8 text of a scene file (a UTF-8 byte-order mark is skipped); anything else is an InputError."""
    for mark, encoding in _FOREIGN_BOMS.items():
        if data.startswith(mark):
            raise InputError(f"{where}: starts with a {encoding} byte-order mark; allowed: UTF-8 text (save the "
                             f"file as UTF-8)")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[:exc.start].count(b"\n") + 1
        raise InputError(f"{where}: not UTF-8 text: byte 0x{data[exc.start]:02x} at byte offset {exc.start} (line "
                         f"{line}); allowed: UTF-8 text") from None


def load_scene(path: str | Path | None = None) -> Scene:
    """Read a scene file; ``None`` reads the embedded default scene.

    The file must be a regular file of at most :data:`MAX_SCENE_BYTES` bytes of UTF-8 text; then
    :func:`parse_scene` checks its content. Every problem is an :class:`~camcontact.errors.InputError`.
    """
    if path is None:
        return parse_scene(default_scene_text(), where=f"embedded {DEFAULT_SCENE}")
    path = Path(path)
    return parse_scene(_decode(_read_limited(path), str(path)), where=str(path))


def default_scene_text() -> str:
    """TOML text of the embedded default scene."""
    return resources.files("camcontact.data").joinpath(DEFAULT_SCENE).read_text(encoding="utf-8")
