"""Units at the door: the one pint registry, parsing, attrs field helpers and SI views.

camcontact accepts dimensional inputs only as pint Quantities or strings such as
``"15 mm"`` or ``"85 degC"`` — a number, then a unit expression (:func:`parse_unit`:
unit names, products, quotients, brackets and small powers; nothing is evaluated). A
bare number for a dimensional field, a unit alone, an expression, a wrong dimension,
NaN or infinity, or an array for a single-valued field raise
:class:`~camcontact.errors.InputError` naming the class, the field, the value and what
is allowed; so do :func:`boolean` (True/False only) and :func:`text` (strings). Inside, every component offers a
cached SI view (:attr:`Component.si`) of plain floats/arrays; no Quantity reaches
the models or the numba kernels.

Examples
--------
>>> from camcontact.units import Q_, to_quantity
>>> to_quantity("15 mm", "[length]", where="Body.radius").to("m")
<Quantity(0.015, 'meter')>
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Iterable, Iterator, Mapping
from typing import Any

import attrs
import numpy as np
import pint

from .errors import InputError

__all__ = [
    "Component",
    "Q_",
    "Quantity",
    "SIView",
    "above_absolute_zero",
    "boolean",
    "format_quantity",
    "in_range",
    "instance_of",
    "integer_in_range",
    "non_negative",
    "number_field",
    "one_of",
    "parse_quantity",
    "parse_unit",
    "positive",
    "quantity_field",
    "si_value",
    "text",
    "to_float",
    "to_quantity",
    "ureg",
]

#: The one unit registry of camcontact (also pint's application registry).
ureg = pint.UnitRegistry()
pint.set_application_registry(ureg)
#: bearing rating lives (ISO 281) count revolutions: a dimension of their own, so that a life never converts to
#: pint's ``revolution``, an angle of 2 pi rad (a factor 2 pi off); shown in millions (``Mrev``)
ureg.define("revolution_count = [revolution_count] = rev_count")
ureg.define("million_revolutions = 1e6 * revolution_count = Mrev")
#: pint Quantity class of the camcontact unit registry (``Q_(15, "mm")``)
Q_ = ureg.Quantity
#: pint's Quantity class (``pint.Quantity``): the type of the Quantity fields of components
Quantity = pint.Quantity

#: An example unit per dimensionality, used in error messages.
_EXAMPLE_UNITS = {
    "[length]": "mm",
    "[pressure]": "GPa",
    "1/[pressure]": "1/GPa",
    "[temperature]": "degC",
    "[viscosity]": "Pa*s",
    "[kinematic_viscosity]": "cSt",
    "[density]": "kg/m^3",
    "[velocity]": "m/s",
    "[force]": "N",
    "[force]/[length]": "N/mm",
    "1/[time]": "rpm",
    "[power]/[length]/[temperature]": "W/(m*K)",
    "[energy]/[mass]/[temperature]": "J/(kg*K)",
    "[]": "",
}

_NUMBER_THEN_UNIT = re.compile(
    r"^\s*([-+]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|(?:nan|inf(?:inity)?)(?![A-Za-z])))\s*(.*?)\s*$",
    re.IGNORECASE,
)


#: pseudo-dimension of plane angles: dimensionless in pint, but a unit (deg, rad, rev) is required
ANGLE = "[angle]"


def _dimensionality(dimension: str):
    return ureg.get_dimensionality(dimension) if dimension not in ("[]", ANGLE) else ureg.get_dimensionality("")


def _example(dimension: str) -> str:
    unit = "deg" if dimension == ANGLE else _EXAMPLE_UNITS.get(dimension)
    if unit is None:
        for key, value in _EXAMPLE_UNITS.items():
            if key != "[]" and _dimensionality(key) == _dimensionality(dimension):
                unit = value
                break
    return f"'1 {unit}'" if unit else "a plain number"


#: the longest unit text read (a unit expression is short; a long one is an attack or a mistake)
MAX_UNIT_TEXT = 64
#: the largest |exponent| in a unit expression (m^3, s^-2; no unit has m^1000)
MAX_UNIT_POWER = 6
_UNIT_CHARACTERS = re.compile(r"^[A-Za-zµμΩ°%_(][A-Za-z0-9µμΩ°%_ */^().\-·]*$")
_UNIT_POWER = re.compile(r"(\*\*|\^)\s*\(?\s*([-+]?\d+(?:\.\d+)?)\s*\)?")


def parse_unit(text: str, *, where: str = "value") -> pint.Unit:
    """A unit expression (``"mm"``, ``"1/GPa"``, ``"W/(m*K)"``, ``"kg/m^3"``) as a pint Unit, or an
    InputError: letters, products, quotients, brackets and small integer powers only (|power| <= 6), at
    most 64 characters; no other numbers, so nothing is evaluated."""
    unit = text.strip()
    body = re.sub(r"^1\s*/\s*", "", unit)  # "1/Pa"
    powers = [float(p) for _, p in _UNIT_POWER.findall(body)]
    bare = _UNIT_POWER.sub("", body)
    if (len(unit) > MAX_UNIT_TEXT or not _UNIT_CHARACTERS.match(body) or any(ch.isdigit() for ch in bare)
            or any(abs(p) > MAX_UNIT_POWER for p in powers)):
        raise InputError(f"{where}: unit {text!r} is not a unit expression; allowed: unit names with *, /, brackets "
                         f"and powers up to {MAX_UNIT_POWER} (e.g. 'mm', '1/GPa', 'W/(m*K)', 'kg/m^3')")
    try:
        return ureg.parse_units(unit)
    except Exception as exc:  # pint raises several kinds on unknown or odd units
        raise InputError(f"{where}: cannot read the unit {text!r} ({str(exc) or type(exc).__name__})") from None


def parse_quantity(text: str, *, where: str = "value") -> pint.Quantity:
    """Parse ``"15 mm"``, ``"85 degC"``, ``"2.2e-8 1/Pa"`` into a Quantity: a number, then a unit
    expression (:func:`parse_unit`; none for a plain number). Nothing is evaluated: a unit alone
    (``"mm"``), an expression (``"(10**400) N"``) or a number in the unit is an InputError."""
    match = _NUMBER_THEN_UNIT.match(text) if len(text) <= 2 * MAX_UNIT_TEXT else None
    if match is None:
        raise InputError(f"{where} = {text!r}: cannot read this as a quantity; allowed: a number then a unit, "
                         "e.g. '15 mm', '85 degC', '2.2e-8 1/Pa'")
    unit = match.group(2)
    return Q_(float(match.group(1)), parse_unit(unit, where=f"{where} = {text!r}") if unit else "dimensionless")


def _is_number(value: Any) -> bool:
    if isinstance(value, bool):
        return False
    if isinstance(value, (int, float, np.integer, np.floating)):
        return True
    if isinstance(value, np.ndarray) and value.dtype.kind in "iuf":
        return True
    if isinstance(value, (list, tuple)) and value and all(_is_number(v) for v in value):
        return True
    return False


def _finite(magnitude: Any) -> bool:
    try:
        return bool(np.all(np.isfinite(np.asarray(magnitude, dtype=float))))
    except (TypeError, ValueError):
        return False


def _magnitude_of(value: Any, where: str) -> float | np.ndarray:
    """A number or an array of numbers as floats (an int beyond the float range is an InputError)."""
    try:
        return float(value) if np.isscalar(value) else np.asarray(value, dtype=float)
    except OverflowError:
        raise InputError(f"{where} = {value!r}: too large for a float (at most about 1.8e308)") from None


def to_quantity(value: Any, dimension: str, *, where: str) -> pint.Quantity:
    """Convert ``value`` to a Quantity of ``dimension`` (e.g. ``"[length]"``) or raise.

    Parameters
    ----------
    value : Quantity, str or (magnitude, unit) tuple
        A bare number is accepted only when ``dimension`` is ``"[]"``.
    dimension : str
        A pint dimensionality expression such as ``"[pressure]"`` or ``"1/[pressure]"``.
    where : str
        ``"Class.field"``, used in the error message.
    """
    if isinstance(value, str):
        quantity = parse_quantity(value, where=where)
    elif isinstance(value, pint.Quantity):
        quantity = value if value._REGISTRY is ureg else Q_(value.magnitude, str(value.units))
    elif (
        isinstance(value, tuple)
        and len(value) == 2
        and isinstance(value[1], str)
        and _is_number(value[0])
    ):
        quantity = Q_(_magnitude_of(value[0], where), parse_unit(value[1], where=f"{where} = {value!r}"))
    elif _is_number(value) and dimension == "[]":
        quantity = Q_(_magnitude_of(value, where), "")
    elif _is_number(value):
        raise InputError(
            f"{where} = {value!r}: a bare number is not accepted for a field of dimension "
            f"{dimension}; give it with a unit, e.g. {_example(dimension)} or camcontact.Q_(value, unit)"
        )
    else:
        raise InputError(
            f"{where} = {value!r} (type {type(value).__name__}): expected a quantity of "
            f"dimension {dimension}, e.g. {_example(dimension)}"
        )
    if not quantity.check(_dimensionality(dimension)):
        raise InputError(
            f"{where} = {format_quantity(quantity)}: wrong dimension {quantity.dimensionality}; "
            f"expected {dimension}, e.g. {_example(dimension)}"
        )
    if dimension == ANGLE and quantity.unitless:
        raise InputError(
            f"{where} = {format_quantity(quantity)}: an angle needs its unit, e.g. '90 deg' or '1.5 rad'"
        )
    if not _finite(quantity.magnitude):
        raise InputError(f"{where} = {format_quantity(quantity)}: must be finite (got NaN or inf)")
    return quantity


def to_float(value: Any, *, where: str) -> float:
    """Convert a dimensionless input (number, numeric string or dimensionless Quantity) to float."""
    if isinstance(value, (str, pint.Quantity)):
        quantity = to_quantity(value, "[]", where=where)
        result = float(quantity.to("").magnitude)
    elif _is_number(value) and np.ndim(value) == 0:
        result = _magnitude_of(value, where)
    else:
        raise InputError(f"{where} = {value!r}: expected a plain number (dimensionless)")
    if not math.isfinite(result):
        raise InputError(f"{where} = {result!r}: must be finite (got NaN or inf)")
    return result


def si_value(quantity: pint.Quantity) -> float | np.ndarray:
    """Magnitude of ``quantity`` in SI base units (temperatures in kelvin)."""
    magnitude = quantity.to_base_units().magnitude
    if np.ndim(magnitude) == 0:
        return float(magnitude)
    return np.asarray(magnitude, dtype=float)


def format_quantity(quantity: Any) -> str:
    """Short human form of a Quantity (``'210 GPa'``); other values as ``repr``."""
    if isinstance(quantity, pint.Quantity):
        if np.ndim(quantity.magnitude) == 0:
            unit = f"{quantity.units:~P}"
            return f"{quantity.magnitude:.6g} {unit}" if unit else f"{quantity.magnitude:.6g}"
        magnitude = np.asarray(quantity.magnitude)
        unit = f"{quantity.units:~P}"
        return f"array(shape={magnitude.shape}, {magnitude.min():g}..{magnitude.max():g}) {unit}"
    return repr(quantity)


def _quantity_eq(a: Any, b: Any) -> bool:
    if a is None or b is None:
        return a is b
    if isinstance(a, pint.Quantity) and isinstance(b, pint.Quantity):
        if a.dimensionality != b.dimensionality:
            return False
        return bool(np.array_equal(np.asarray(si_value(a)), np.asarray(si_value(b))))
    return bool(np.array_equal(a, b))


# ---------------------------------------------------------------- range validators
def _name(instance: Any, attribute: attrs.Attribute) -> str:
    return f"{type(instance).__name__}.{attribute.name}"


def _magnitude(value: Any) -> Any:
    return si_value(value) if isinstance(value, pint.Quantity) else value


def in_range(
    lower: float | None = None,
    upper: float | None = None,
    *,
    lower_inclusive: bool = True,
    upper_inclusive: bool = True,
    unit: str = "",
):
    """attrs validator: ``lower (<=|<) value (<=|<) upper`` on the SI magnitude.

    ``unit`` is the SI unit of the bounds, printed in the error message.
    """

    def _validate(instance, attribute, value):
        if value is None:
            return
        magnitude = np.asarray(_magnitude(value), dtype=float)
        ok = np.ones(magnitude.shape, dtype=bool)
        if lower is not None:
            ok &= magnitude >= lower if lower_inclusive else magnitude > lower
        if upper is not None:
            ok &= magnitude <= upper if upper_inclusive else magnitude < upper
        if not bool(np.all(ok)):
            parts = []
            if lower is not None:
                parts.append(f"{lower:g} {'<=' if lower_inclusive else '<'} ")
            parts.append(attribute.name)
            if upper is not None:
                parts.append(f" {'<=' if upper_inclusive else '<'} {upper:g}")
            allowed = "".join(parts) + (f" [{unit}]" if unit else "")
            raise InputError(
                f"{_name(instance, attribute)} = {format_quantity(value)} is out of range; "
                f"allowed: {allowed}"
            )

    return _validate


def positive(unit: str = ""):
    """attrs validator: strictly positive (SI magnitude > 0)."""
    return in_range(0.0, lower_inclusive=False, unit=unit)


def non_negative(unit: str = ""):
    """attrs validator: SI magnitude >= 0."""
    return in_range(0.0, unit=unit)


def above_absolute_zero():
    """attrs validator: a temperature above 0 K."""
    return in_range(0.0, lower_inclusive=False, unit="K")


def one_of(*choices: Any):
    """attrs validator: the value is one of ``choices`` (InputError naming field, value, choices)."""

    def _validate(instance, attribute, value):
        # compared only with choices of its own type: an array or a dict is named, not an ambiguous truth value
        if not any(isinstance(value, type(choice)) and value == choice for choice in choices):
            raise InputError(f"{_name(instance, attribute)} = {value!r}; allowed: {', '.join(map(repr, choices))}")

    return _validate


def boolean(instance, attribute, value):
    """attrs validator: True or False only (a string such as ``"false"`` is not read as a boolean)."""
    if not isinstance(value, (bool, np.bool_)):
        raise InputError(f"{_name(instance, attribute)} = {value!r}; allowed: true or false (a boolean)")


def integer_in_range(lower: int, upper: int):
    """attrs validator: an integer (not a boolean) with lower <= value <= upper (InputError naming the field,
    the value and the range)."""

    def _validate(instance, attribute, value):
        if not (isinstance(value, (int, np.integer)) and not isinstance(value, bool) and lower <= value <= upper):
            raise InputError(f"{_name(instance, attribute)} = {value!r}; allowed: an integer {lower}..{upper}")

    return _validate


def text(instance, attribute, value):
    """attrs validator: a string."""
    if not isinstance(value, str):
        raise InputError(f"{_name(instance, attribute)} = {value!r}; allowed: a string")


def instance_of(cls: type):
    """attrs validator: the value is a ``cls`` (InputError naming the field, the value and the class)."""

    def _validate(instance, attribute, value):
        if not isinstance(value, cls):
            raise InputError(f"{type(instance).__name__}.{attribute.name} = {value!r}: expected a {cls.__name__}")

    return _validate


# ---------------------------------------------------------------- attrs field helpers
def _converting_field(convert, *, default, optional, validators, metadata, **options):
    """attrs field whose converter is ``convert(value, "Class.field")`` (None passes if optional)."""

    def _convert(value, instance, field):
        if value is None and optional:
            return None
        return convert(value, f"{type(instance).__name__}.{field.name}")

    if optional and default is attrs.NOTHING:
        default = None
    return attrs.field(
        default=default,
        converter=attrs.Converter(_convert, takes_self=True, takes_field=True),
        validator=list(validators),
        metadata=metadata,
        **options,
    )


def quantity_field(
    dimension: str,
    *,
    default: Any = attrs.NOTHING,
    optional: bool = False,
    validators: Iterable = (),
    doc: str = "",
    array: bool = False,
):
    """An attrs field that holds a pint Quantity of ``dimension``.

    Accepts Quantities, strings (``"15 mm"``) and ``(magnitude, unit)`` tuples;
    converts once at construction, checks dimension and finiteness, then runs the
    range ``validators`` (on the SI magnitude). ``optional=True`` admits ``None``;
    ``array=True`` admits a 1-D array of values (otherwise one value only).
    """

    def convert(value, where):
        if value is None:
            raise InputError(f"{where} is required (a quantity of dimension {dimension})")
        quantity = to_quantity(value, dimension, where=where)
        shape = np.shape(quantity.magnitude)
        if (not array and shape != ()) or (array and len(shape) > 1):
            raise InputError(f"{where} = {format_quantity(quantity)}: shape {shape}; allowed: "
                             f"{'a 1-D array of values' if array else 'one value (not an array)'}")
        return quantity

    return _converting_field(
        convert, default=default, optional=optional, validators=validators,
        metadata={"dimension": dimension, "doc": doc},
        repr=format_quantity, eq=attrs.cmp_using(eq=_quantity_eq), hash=False,
    )


def number_field(
    *,
    default: Any = attrs.NOTHING,
    optional: bool = False,
    validators: Iterable = (),
    doc: str = "",
):
    """An attrs field for a dimensionless float (rejects NaN, inf and non-numbers)."""
    return _converting_field(
        lambda value, where: to_float(value, where=where), default=default, optional=optional,
        validators=validators, metadata={"dimension": "[]", "doc": doc},
    )


# ---------------------------------------------------------------- SI views
class SIView(Mapping):
    """Read-only SI magnitudes of a component's quantity and number fields.

    Attribute and item access both work: ``material.si.E`` or ``material.si["E"]``
    (floats, or float arrays; temperatures in K; ``None`` for unset optional fields).
    """

    __slots__ = ("_owner", "_values")

    def __init__(self, owner: str, values: dict[str, Any]):
        object.__setattr__(self, "_owner", owner)
        object.__setattr__(self, "_values", dict(values))

    def __getitem__(self, key: str) -> Any:
        return self._values[key]

    def __getattr__(self, key: str) -> Any:
        try:
            return self._values[key]
        except KeyError:
            raise AttributeError(f"{self._owner}.si has no field {key!r}") from None

    def __setattr__(self, key: str, value: Any) -> None:
        raise AttributeError(f"{self._owner}.si is read-only")

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __repr__(self) -> str:
        inner = ", ".join(f"{k}={v!r}" for k, v in self._values.items())
        return f"SIView[{self._owner}]({inner})"


class Component:
    """Mixin for attrs components: :attr:`si` is the cached SI view of the fields; in Jupyter a component shows
    as a table of its fields (nested components by their type and name, expandable)."""

    def _repr_html_(self) -> str:
        import html

        rows = []
        for field in attrs.fields(type(self)):
            value = getattr(self, field.name)
            if isinstance(value, Component):
                label = f"{type(value).__name__} {getattr(value, 'name', '')!r}"
                cell = f"<details><summary>{html.escape(label)}</summary>{value._repr_html_()}</details>"
            else:
                cell = html.escape("—" if value is None else format_quantity(value))
            rows.append(f"<tr><td style='text-align:left'>{html.escape(field.name)}</td>"
                        f"<td style='text-align:left'>{cell}</td></tr>")
        return (f"<table><caption style='text-align:left'><b>{html.escape(type(self).__name__)}</b></caption>"
                + "".join(rows) + "</table>")

    @functools.cached_property
    def si(self) -> SIView:
        values: dict[str, Any] = {}
        for field in attrs.fields(type(self)):
            if "dimension" not in field.metadata:
                continue
            value = getattr(self, field.name)
            values[field.name] = si_value(value) if isinstance(value, pint.Quantity) else value
        return SIView(type(self).__name__, values)
