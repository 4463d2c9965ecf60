"""Reports: pandas DataFrames with ``"name [unit]"`` columns, CSV and printed tables."""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np
import pandas as pd

from .errors import InputError
from .quantities import QUANTITIES, spec
from .units import Q_, ureg

if TYPE_CHECKING:  # pragma: no cover
    from .analysis import Result

__all__ = ["column_name", "convert", "result_frame", "steps_frame", "text_table", "unexplained_values", "unit_label"]


_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


#: names whose pint symbol is not what a label should show (pint's micron symbol is the bare prefix "µ")
_SYMBOL_OVERRIDES = {"micron": "µm", "microns": "µm", "dimensionless": "-"}


def _symbol(match: re.Match) -> str:
    name = match.group(0)
    if name in _SYMBOL_OVERRIDES:
        return _SYMBOL_OVERRIDES[name]
    try:
        return ureg.get_symbol(name)
    except Exception:  # pint: not a unit name (cannot happen for a unit that parsed)
        return name


def _exponent(match: re.Match) -> str:
    """An integer exponent as superscript (``²``, ``⁻¹``); a fractional one stays ``^0.5``."""
    power = match.group(1)
    return power.translate(_SUPERSCRIPT) if "." not in power else f"^{power}"


def unit_label(unit: str) -> str:
    """A unit as engineers write it, in the order it is given: ``"N*m"`` -> ``"N·m"``, ``"W/(m*K)"`` ->
    ``"W/(m·K)"``, ``"mm^2/s"`` -> ``"mm²/s"``, ``"um"`` -> ``"µm"``, ``""`` -> ``"-"`` (pint's own format
    sorts the factors: "m·N", "W/K/m"). InputError for a unit pint does not know."""
    if unit == "":
        return "-"
    try:
        ureg.parse_units(unit)
    except Exception as exc:  # pint: undefined unit or syntax
        raise InputError(f"unknown unit {unit!r}: {exc}") from None
    text = re.sub(r"\s*(\*\*|[*/^()])\s*", r"\1", unit.strip())  # no spaces around operators
    text = re.sub(r"(?:\^|\*\*)(-?[0-9.]+)", _exponent, text)
    text = re.sub(r"[A-Za-zµΩ_]+", _symbol, text)
    return re.sub(r"\*|\s+", "·", text)


def column_name(name: str, unit: str | None) -> str:
    """``"h_min [µm]"``; text quantities keep their bare name."""
    return name if unit is None else f"{name} [{unit_label(unit)}]"


def convert(value: Any, si_unit: str, unit: str, name: str) -> Any:
    """Convert an SI value (float/array) of quantity ``name`` to ``unit``."""
    if value is None:
        return np.nan
    if si_unit == unit:
        return value
    try:
        return Q_(np.asarray(value, dtype=float), si_unit).to(unit).magnitude
    except Exception as exc:  # pint errors: wrong dimension or unknown unit
        raise InputError(f"cannot report {name} [{si_unit}] in {unit!r}: {exc}") from None


def result_frame(result: Result, units: Mapping[str, str] | None = None, *, scalars: bool = False) -> pd.DataFrame:
    """DataFrame of a :class:`~camcontact.analysis.Result`: one row per variant.

    ``units`` maps quantity names to display units (``{"h_min": "nm"}``); others use the
    catalogue's display unit. A result with an index (a cam cycle) gives one row per variant
    and index value with its per-index outputs, or with ``scalars=True`` one row per variant
    with its scalar outputs (cycle summaries).
    """
    units = dict(units or {})
    unknown = sorted(set(units) - set(result.outputs) - ({result.index} if result.index else set()))
    if unknown:
        raise InputError(f"units given for {unknown}, which are not outputs of this result {result.outputs}")

    def cell(name: str, value: Any) -> tuple[str, Any]:
        quantity = spec(name)
        if quantity.si_unit is None:
            return column_name(name, None), value
        unit = units.get(name, quantity.display_unit)
        return column_name(name, unit), convert(value, quantity.si_unit, unit, name)

    indexed = result.index is not None and not scalars
    names = [n for n in result.outputs if (n in result.per_index) == indexed] if result.index else list(result.outputs)
    if indexed and result.index in names:
        names.remove(result.index)
    tails = _status_cells(result, names)
    records = []
    for label, row, tail in zip(result.variants, result.rows, tails):
        head: dict[str, Any] = {"variant": label} if label else {}
        if not indexed:
            records.append(head | dict(cell(name, row.get(name)) for name in names) | tail)
            continue
        index_column, index_values = cell(result.index, row[result.index])
        index_values = np.atleast_1d(index_values)
        # an output this variant does not give (None -> NaN) is broadcast over the index
        columns = {column: np.broadcast_to(np.asarray(values, dtype=object if np.ndim(values) else None), index_values.shape)
                   for column, values in (cell(name, row.get(name)) for name in names)}
        for i, position in enumerate(index_values):
            records.append(head | {index_column: position} | {column: values[i] for column, values in columns.items()}
                           | tail)
    return pd.DataFrame.from_records(records)


def _status_cells(result: Result, names: list[str]) -> list[dict[str, Any]]:
    """Per variant: ``not_given`` (the outputs among ``names`` its models do not give, when another variant
    gives them) and ``failed``/``error`` (its failed steps) — columns present only when some row needs them."""
    failures = result.failures
    failed_outputs = {(f.variant, name) for f in failures for name in f.outputs}
    # not given: an output this variant's models do not give, or one a step gives as None (no value: the
    # lubricant's conductivity when the data sheet has none)
    absent = [[name for name in names if row.get(name) is None and (label, name) not in failed_outputs]
              for label, row in zip(result.variants, result.rows)]
    tails: list[dict[str, Any]] = [{} for _ in result.variants]
    if any(absent):
        for tail, missing in zip(tails, absent):
            tail["not_given"] = ", ".join(missing)
    if failures:
        for tail, label in zip(tails, result.variants):
            mine = [f for f in failures if f.variant == label]
            tail["failed"] = bool(mine)
            tail["error"] = "; ".join(f.describe() for f in mine if not f.skipped)
    return tails


def steps_frame(result: Result) -> pd.DataFrame:
    """The step record of a result as a DataFrame (wall time in ms); when a step failed, an ``error``
    column says why."""
    frame = pd.DataFrame(
        {
            "step": [r.step for r in result.records],
            "model": [r.model for r in result.records],
            "version": [r.version for r in result.records],
            "variant": [r.variant for r in result.records],
            "wall time [ms]": [1e3 * r.wall_time for r in result.records],
        }
    )
    if any(r.error for r in result.records):
        frame["error"] = [r.error for r in result.records]
    return frame


def text_table(frame: pd.DataFrame, transpose: bool = True) -> str:
    """A readable text table (quantities as rows when ``transpose``), 5 significant digits."""
    shown = frame.set_index("variant").T if transpose and "variant" in frame else (frame.T if transpose else frame)
    if transpose and "variant" not in frame:
        shown.columns = ["value"] * len(shown.columns) if len(shown.columns) == 1 else shown.columns

    def fmt(value: Any) -> str:
        if isinstance(value, (float, np.floating)):
            return "nan" if np.isnan(value) else f"{value:.5g}"
        return str(value)

    return shown.map(fmt).to_string()


def unexplained_values(frame: pd.DataFrame) -> list[tuple[int, str]]:
    """(row position, column) of every NaN or infinite number in a report frame without its reason beside it.

    A non-finite cell is explained when its row ``failed`` or has an ``error`` (a step or a sweep's case
    failed, and says why), when its
    quantity is listed in the row's ``not_given`` (this variant's models do not give it), or by a status
    cell of its quantity's :attr:`~camcontact.quantities.QuantitySpec.nan_when` in the row (an unloaded
    roller, a traction drive in gross slip, a friction correlation outside its validity). Reports of
    camcontact have none; the fuzz harness and the tests check it.
    """
    unexplained = []
    for column in frame.columns:
        try:
            values = np.asarray(frame[column], dtype=float)
        except (TypeError, ValueError):  # text and object columns
            continue
        name = column.split(" [", 1)[0]
        reasons = QUANTITIES[name].nan_when if name in QUANTITIES else ()
        for position in np.flatnonzero(~np.isfinite(values)):
            row = frame.iloc[position]
            failed = bool(row.get("failed", False)) or str(row.get("error", "") or "") not in ("", "nan")
            if failed or name in str(row.get("not_given", "")).split(", "):
                continue
            if any(status in row.index and row[status] == value for status, value in reasons):
                continue
            unexplained.append((int(position), column))
    return unexplained
