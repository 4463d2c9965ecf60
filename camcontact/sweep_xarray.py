"""A gridded sweep as an xarray Dataset: one dimension per swept path (and the index, the variant), one
variable per output, units in the attributes.

A sweep's table (:func:`camcontact.sweep.run_sweep`) is long: one row per case (per case and cam angle or
roller). For a full grid, :func:`to_xarray` turns it into the labelled array a study is plotted and sliced
from — ``ds["h_min_cycle"].sel(speed=2000)`` — with ``"name [unit]"`` headers split into the name and a
``units`` attribute. The table records which columns are its dimensions (``frame.attrs["dimensions"]``); a
table read back from a CSV file (:func:`~camcontact.sweep_stream.read_sweep`) names them with ``dims=``.
Needs xarray (the ``[xarray]`` extra).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from .errors import InputError
from .report_export import split_header

__all__ = ["to_xarray"]


def to_xarray(frame: Any, dims: Sequence[str] | None = None, index: str | None = None) -> Any:
    """The sweep table ``frame`` as an :class:`xarray.Dataset` over ``dims`` (column headers; default the
    table's own, ``frame.attrs["dimensions"]``): coordinates and variables named without their units, which
    go to each one's ``units`` attribute (``"-"`` for a plain number); ``case``, ``error`` and ``failed``
    stay variables. A variable that does not vary along the ``index`` dimension (default
    ``frame.attrs["index"]``: the cam angle or roller of a per-index table) — a case's summary — is kept
    without it, so ``ds["h_min_cycle"].sel(speed=2000)`` is one number. A failed case whose rows have no
    index value cannot sit on the grid: ``ds.attrs["failed_cases"]`` lists ``"case N: reason"``.
    InputError for a table that is not a grid over ``dims`` (a repeated combination) or names a column it
    lacks.

    >>> import camcontact as cc
    >>> steel = cc.Material(E="210 GPa", nu=0.3)
    >>> contact = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm"),
    ...                          body2=cc.Body(material=steel, radius="10 mm"), load="1 kN", length="10 mm")
    >>> table = cc.sweep_frame(contact, {"load": ["1 kN", "2 kN"], "length": ["10 mm", "20 mm"]},
    ...                        outputs=["p_h"], progress=False)
    >>> ds = to_xarray(table)
    >>> dict(ds.sizes), ds["p_h"].attrs["units"], round(float(ds["p_h"].sel(load=2.0, length=10.0)), 1)
    ({'load': 2, 'length': 2}, 'MPa', 1049.7)
    """
    try:
        import xarray  # noqa: F401  (pandas' to_xarray needs it)
    except ImportError:
        raise InputError("to_xarray needs xarray: pip install 'camcontact[xarray]'") from None
    dims = list(dims if dims is not None else frame.attrs.get("dimensions", []))
    if not dims:
        raise InputError("to_xarray: the table does not record its dimensions (a table read from a file): give "
                         f"dims=[...], column headers of {list(frame.columns)}")
    missing = [d for d in dims if d not in frame.columns]
    if missing:
        raise InputError(f"to_xarray: dims {missing} are not columns of the table; allowed: {list(frame.columns)}")
    index = index if index is not None else frame.attrs.get("index")
    off_grid = frame[dims].isna().any(axis=1)
    failed = [f"case {int(c)}: {e}" for c, e in zip(frame.loc[off_grid, "case"], frame.loc[off_grid, "error"])] \
        if {"case", "error"} <= set(frame.columns) else []
    frame = frame[~off_grid]
    repeated = frame.duplicated(subset=dims)
    if repeated.any():
        raise InputError(f"to_xarray: {int(repeated.sum())} rows repeat a combination of {dims}: the table is not a "
                         "grid over them (add the variant or index column to dims)")
    dataset = frame.set_index(dims).to_xarray()
    if index in dataset.dims:
        for name in list(dataset.data_vars):
            values = dataset[name]
            if index not in values.dims:
                continue
            first = values.isel({index: 0})
            if bool(((values == first) | (values.isnull() & first.isnull())).all()):
                dataset[name] = first.drop_vars(index)
    renames, units = {}, {}
    for header in [*dataset.coords, *dataset.data_vars]:
        name, unit = split_header(str(header))
        if name != header:
            renames[header] = name
        if unit is not None:
            units[name] = unit or "-"  # split_header reads a plain number's "-" as no unit
    dataset = dataset.rename(renames)
    for name, unit in units.items():
        dataset[name].attrs["units"] = unit
    dataset.attrs["failed_cases"] = failed
    return dataset
