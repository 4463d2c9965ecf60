"""Sweep tables on disk: a CSV file that grows as cases finish, and reading it back.

A sweep with ``stream=path`` (see :mod:`camcontact.sweep_cases`) appends the rows of every finished
case to a plain CSV file at once — header first, then one block of rows per case, in the order the
cases finish — so a sweep stopped by SIGINT, a killed worker or a power cut keeps every finished case.
When a case brings a column the file has not got yet (the first cases failed, a row with ``failed``),
the file is rewritten once with the wider header (to a temporary file, then renamed), its cells kept
as they were written. When the sweep ends (complete or not), the file is put in case order the same
way (:meth:`CsvStream.sort`).

:func:`read_sweep` reads such a file back as the table the sweep returns (equal under
``pandas.testing.assert_frame_equal``): rows sorted by ``case`` (each case's rows in their order),
``case`` first, ``failed`` and ``error`` last; floats exact (written in shortest round-trip form);
``error`` text, ``""`` where a row has none; text columns ``""`` where a row has no text; ``failed``
(when present) the row's own flag, else whether its ``error`` is non-empty; True/False columns bool.
A text column whose every value looks like a number comes back as numbers.

>>> import pandas as pd, tempfile, pathlib
>>> path = pathlib.Path(tempfile.mkdtemp()) / "sweep.csv"
>>> stream = CsvStream(path)
>>> stream.append([{"case": 1, "load [kN]": 2.0, "p_h [MPa]": 0.1 + 0.2, "error": ""}])
>>> stream.append([{"case": 0, "load [kN]": -1.0, "error": "InputError: load < 0"}])
>>> table = read_sweep(path)
>>> table["case"].tolist(), table["error"].tolist()
([0, 1], ['InputError: load < 0', ''])
>>> list(table.columns), bool(table["p_h [MPa]"][1] == 0.1 + 0.2)
(['case', 'load [kN]', 'p_h [MPa]', 'error'], True)
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from .errors import InputError

__all__ = ["CsvStream", "check_stream_path", "ordered_columns", "read_sweep", "tidy_table"]

LAST = ("failed", "error")  # the status columns: always last, in this order


def check_stream_path(stream: Any) -> Path:
    """``stream`` as a Path; InputError unless it is a path (str or os.PathLike) ending in ``.csv``."""
    if isinstance(stream, bool) or not isinstance(stream, (str, os.PathLike)):
        raise InputError(f"sweep: stream = {stream!r}; allowed: a path ending in .csv (or None)")
    path = Path(stream)
    if path.suffix.lower() != ".csv":
        raise InputError(f"sweep: stream = {str(stream)!r}; allowed: a path ending in .csv (write Parquet from "
                         "the returned table)")
    return path


def ordered_columns(columns: Iterable[str]) -> list[str]:
    """``columns`` (without repeats) with ``case`` first and ``failed``, ``error`` last."""
    names = list(dict.fromkeys(columns))
    head = [c for c in names if c == "case"]
    return head + [c for c in names if c != "case" and c not in LAST] + [c for c in LAST if c in names]


def tidy_table(frame: pd.DataFrame) -> pd.DataFrame:
    """``frame`` in the form a sweep returns (and :func:`read_sweep` gives back): columns ordered by
    :func:`ordered_columns`, ``error`` text (``""`` for none), ``failed`` bool (the row's own flag, else
    whether ``error`` is non-empty), text columns ``""`` where a row has no text."""
    frame = frame[ordered_columns(frame.columns)].copy()
    if "error" in frame:
        frame["error"] = frame["error"].map(lambda v: v if isinstance(v, str) else "").astype(str)
    if "failed" in frame:
        flags = [bool(f) if isinstance(f, (bool, np.bool_)) else e != ""
                 for f, e in zip(frame["failed"], frame["error"] if "error" in frame else [""] * len(frame))]
        frame["failed"] = pd.Series(flags, index=frame.index, dtype=bool)
    for column in frame.columns:
        if column not in LAST and _is_text(frame[column]):
            frame[column] = frame[column].fillna("")
    return frame.reset_index(drop=True)


def _is_text(column: pd.Series) -> bool:
    """True for a column whose non-missing values are all strings (at least one)."""
    if pd.api.types.is_numeric_dtype(column.dtype) or pd.api.types.is_bool_dtype(column.dtype):
        return False
    values = column.dropna()
    return len(values) > 0 and all(isinstance(v, str) for v in values)


def read_sweep(path: Any) -> pd.DataFrame:
    """The sweep table in the CSV file at ``path`` (written by a sweep with ``stream=path``), equal to the
    table the sweep returned (see the module docstring); an empty DataFrame for an empty file."""
    path = Path(path)
    if not path.exists() or path.stat().st_size == 0:
        return pd.DataFrame()
    header = pd.read_csv(path, nrows=0, encoding="utf-8").columns
    options: dict[str, Any] = {}
    if int(pd.__version__.split(".")[0]) < 3:
        options["float_precision"] = "round_trip"  # pandas 3 parses floats exactly by default
    frame = pd.read_csv(path, encoding="utf-8", keep_default_na=False,
                        na_values={c: [""] for c in header if c != "error"},
                        dtype={"error": str} if "error" in header else None, **options)
    if "case" in frame:
        frame = frame.sort_values("case", kind="stable")
    return tidy_table(frame)


class CsvStream:
    """The CSV file of a sweep, appended to as cases finish (see the module docstring).

    ``resume=False`` empties the file (or creates it); ``resume=True`` keeps what is there and goes on
    appending under its header (after dropping a torn last line, left by a stop in the middle of a write).
    An InputError names the path when it cannot be written.
    """

    def __init__(self, path: Any, *, resume: bool = False):
        self.path = Path(path)
        try:
            if resume and self.path.exists():
                self._drop_torn_tail()
            else:
                self.path.write_bytes(b"")
            self.columns = self._header()
        except OSError as exc:
            raise InputError(f"sweep: stream = {str(path)!r} cannot be written ({exc.strerror or exc})") from None
        except ValueError as exc:  # pandas' ParserError, UnicodeDecodeError: not a sweep's CSV file
            raise InputError(f"sweep: stream = {str(path)!r} is not a sweep's CSV file ({exc})") from None

    def _header(self) -> list[str]:
        if self.path.stat().st_size == 0:
            return []
        return [str(c) for c in pd.read_csv(self.path, nrows=0, encoding="utf-8").columns]

    def _drop_torn_tail(self) -> None:
        """Cut an incomplete last line and the rows of the case it belonged to (written last)."""
        data = self.path.read_bytes()
        if not data or data.endswith(b"\n"):
            return
        self.path.write_bytes(data[:data.rfind(b"\n") + 1])
        raw = self._raw()
        if len(raw) and "case" in raw:
            self._rewrite(raw[raw["case"] != raw["case"].iloc[-1]], list(raw.columns))

    def _raw(self) -> pd.DataFrame:
        """The file's cells as written (text), for rewriting it unchanged."""
        if self.path.stat().st_size == 0:
            return pd.DataFrame()
        return pd.read_csv(self.path, dtype=str, keep_default_na=False, encoding="utf-8")

    def _rewrite(self, raw: pd.DataFrame, columns: Sequence[str]) -> None:
        """Replace the file by ``raw`` under ``columns`` (new columns empty), atomically."""
        text = raw.reindex(columns=list(columns), fill_value="").to_csv(index=False, lineterminator="\n")
        handle, temporary = tempfile.mkstemp(dir=self.path.parent, prefix=self.path.name, suffix=".tmp")
        try:
            with os.fdopen(handle, "w", encoding="utf-8", newline="") as file:
                file.write(text)
            os.replace(temporary, self.path)
        finally:
            if os.path.exists(temporary):
                os.unlink(temporary)

    def append(self, rows: Sequence[Mapping[str, Any]]) -> None:
        """Append the rows of one finished case and flush them to the file (one write)."""
        if not rows:
            return
        columns = ordered_columns([*self.columns, *(key for row in rows for key in row)])
        header = not self.columns
        if self.columns and columns != self.columns:
            self._rewrite(self._raw(), columns)
        self.columns = columns
        block = pd.DataFrame(list(rows)).reindex(columns=columns)
        self._write(block.to_csv(index=False, header=header, lineterminator="\n").encode("utf-8"))

    def sort(self) -> None:
        """Rewrite the file with its rows in case order (each case's rows in their order), if they are not:
        done when the sweep ends, so the file reads as the table with any CSV reader."""
        raw = self._raw()
        if not len(raw) or "case" not in raw:
            return
        numbers = pd.to_numeric(raw["case"], errors="coerce")
        if numbers.is_monotonic_increasing or numbers.isna().any():
            return
        self._rewrite(raw.iloc[numbers.argsort(kind="stable")], list(raw.columns))

    def _write(self, data: bytes) -> None:
        descriptor = os.open(self.path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o666)
        try:
            view = memoryview(data)
            while view:
                view = view[os.write(descriptor, view):]
        finally:
            os.close(descriptor)
