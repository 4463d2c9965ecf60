"""Export of report tables: CSV, Parquet (``[parquet]`` extra) and unit-carrying pint-pandas frames.

Report tables (results, sweeps) hold plain float columns named ``"name [unit]"`` and text columns
with bare names. :func:`write_csv` and :func:`write_parquet` keep that form, so the units travel in
the headers; :func:`to_pint_frame` turns every ``"name [unit]"`` column into a pint-pandas column
``name`` of dtype ``pint[unit]`` (the ``[pint]`` extra) for unit-aware work downstream.
"""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import pandas as pd

from .errors import InputError
from .units import ureg

__all__ = ["split_header", "to_pint_frame", "write_csv", "write_parquet"]

_HEADER = re.compile(r"^(?P<name>.+?) \[(?P<unit>[^\[\]]*)\]$")


def split_header(header: str) -> tuple[str, str | None]:
    """(name, unit) of a report header ``"h_min [µm]"``; (header, None) without a unit; "-" is ``""``."""
    match = _HEADER.match(str(header))
    if match is None:
        return str(header), None
    unit = match["unit"]
    return match["name"], "" if unit == "-" else unit


def _pint_unit(text: str, header: str) -> str:
    """A unit string pint parses, from a report header's display unit (``mPa·s``, ``1/GPa``, ``°C``)."""
    candidate = text.replace("·", "*")
    try:
        return str(ureg.Unit(candidate)) if candidate else "dimensionless"
    except Exception as exc:  # noqa: BLE001  (pint's parse errors differ by version)
        raise InputError(f"column {header!r}: unit {text!r} is not a pint unit ({exc})") from None


def write_csv(frame: pd.DataFrame, path) -> Path:
    """Write ``frame`` as CSV (UTF-8, no index) and return the path."""
    path = Path(path)
    frame.to_csv(path, index=False, encoding="utf-8")
    return path


def write_parquet(frame: pd.DataFrame, path) -> Path:
    """Write ``frame`` as Parquet (needs pyarrow: ``pip install camcontact[parquet]``) and return the path."""
    if importlib.util.find_spec("pyarrow") is None:
        raise InputError("Parquet export needs pyarrow: install the extra, pip install 'camcontact[parquet]'")
    path = Path(path)
    frame.to_parquet(path, index=False)
    return path


def to_pint_frame(frame: pd.DataFrame) -> pd.DataFrame:
    """``frame`` with each ``"name [unit]"`` column as a pint-pandas column ``name`` of dtype
    ``pint[unit]`` (needs pint-pandas: ``pip install camcontact[pint]``); other columns unchanged."""
    try:
        import pint_pandas
    except ImportError:
        raise InputError("pint-pandas frames need pint-pandas: install the extra, "
                         "pip install 'camcontact[pint]'") from None
    pint_pandas.PintType.ureg = ureg
    columns = {}
    for header in frame.columns:
        name, unit = split_header(header)
        if unit is None or not pd.api.types.is_numeric_dtype(frame[header]):
            columns[header] = frame[header]
        else:
            dtype = f"pint[{_pint_unit(unit, header)}]"
            columns[name] = pint_pandas.PintArray(frame[header].to_numpy(dtype=float), dtype=dtype)
    return pd.DataFrame(columns, index=frame.index)
