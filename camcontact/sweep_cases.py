"""Sweep cases: a grid of field values -> cases -> one analysis each, on any executor, into one table.

The machinery behind :meth:`camcontact.analysis.Analysis.sweep` and :func:`camcontact.sweep.sweep_frame`
(the user-facing functions and the full description are in :mod:`camcontact.sweep`). It does not import
the analysis: every function that runs cases takes the *runner*, a picklable callable
``runner(scene, outputs=..., models=..., effects=...)`` with a ``run()`` returning a result, i.e. the
:class:`~camcontact.analysis.Analysis` class.

A *grid* names scene fields by *paths* — a field of the scene component, or through dots a field of a
component inside it (``"speed"``, ``"cam.base_radius"``, ``"cvt.material.E"``) — and gives the values
to try: a mapping ``{path: [values, ...]}`` (the cartesian product is swept) or a pandas DataFrame
whose columns are paths and whose rows are the cases. Values are what the field accepts
(Quantities, strings with units, numbers).

Each case is one run of the runner (an :class:`~camcontact.analysis.Analysis`) with the sweep's outputs,
models and effects, by :func:`run_case` — a plain top-level function of picklable arguments, so any
:class:`concurrent.futures.Executor` runs it: none (serial, in this process), a
``ProcessPoolExecutor``, or ``dask.distributed.Client.get_executor()`` (the ``[dask]`` extra). The
rows come back in case order whatever the executor, so every executor gives the same table.

The table is tidy: one row per case (and variant), or per case × index value (cam angle, roller) for
a scene with an index when ``table="index"``; first ``case`` (the case's number in the grid's order,
from 0), then the swept values, in columns ``"path [unit]"`` (magnitudes in the unit of the path's
first value; plain numbers ``"path [-]"``), then the outputs ``"name [unit]"``, then — when some row of
a report has it (a step that failed inside an analysis) — ``failed`` (bool: the row's own flag, else
whether its error is non-empty), and last ``error``: the row's own reason, ``""``, or
``"ExceptionType: message"`` of a case that failed — its parameters stay in the row, and the other
cases are not lost. Text columns hold ``""`` where a row has no text.

Nothing finished is lost (:func:`run_sweep`): a ``timeout`` [s] per case (:class:`CaseAlarm`) records a
case that runs too long as failed; ``stream=path.csv`` appends each finished case's rows to a file at
once (:mod:`camcontact.sweep_stream`) and ``resume=True`` runs only the cases not in it; a SIGINT or
a broken process pool returns the finished cases with ``frame.attrs["missing_cases"]`` and a
:class:`~camcontact.errors.SweepInterruptedWarning`.

>>> import camcontact as cc
>>> steel = cc.Material(E="210 GPa", nu=0.3)
>>> evolve_path(steel, "E", "200 GPa").si.E
200000000000.0
"""

from __future__ import annotations

import itertools
import math
import pickle
import signal
import sys
import threading
import warnings
from collections.abc import Callable, Iterable, Mapping, Sequence
from concurrent.futures import BrokenExecutor, Executor, Future, as_completed
from numbers import Real
from pathlib import Path
from typing import Any, Self

import attrs
import numpy as np
import pint

from .errors import CamcontactWarning, CaseTimeout, InputError, SweepInterruptedWarning
from .units import ureg

__all__ = ["MAX_SWEEP_CASES", "TABLES", "CaseAlarm", "case_rows", "cases_of", "check_case_count", "check_path",
           "evolve_path", "finished_cases", "has_index", "run_case", "run_cases", "run_sweep"]

TABLES = ("auto", "cases", "index")
#: the largest sweep (cases), checked before any case is built: a bigger grid is an InputError
MAX_SWEEP_CASES = 100_000


def check_path(component: Any, path: str) -> None:
    """InputError unless ``path`` names a field of ``component`` (through nested components)."""
    current = component
    for depth, head in enumerate(path.split(".")):
        if not attrs.has(type(current)):
            raise InputError(f"sweep path {path!r}: {'.'.join(path.split('.')[:depth])} is not a component "
                             f"({type(current).__name__}) and has no field {head!r}")
        names = [field.name for field in attrs.fields(type(current))]
        if head not in names:
            raise InputError(f"sweep path {path!r}: {type(current).__name__} has no field {head!r}; "
                             f"fields: {', '.join(names)}")
        current = getattr(current, head)


def evolve_path(component: Any, path: str, value: Any) -> Any:
    """A copy of ``component`` with the field at the dotted ``path`` set to ``value`` (validated anew)."""
    check_path(component, path)
    head, _, rest = path.partition(".")
    new = value if not rest else evolve_path(getattr(component, head), rest, value)
    return attrs.evolve(component, **{head: new})


def cases_of(grid: Any) -> tuple[list[str], list[tuple]]:
    """(paths, cases) of a grid: a mapping of path -> values (cartesian product) or a DataFrame of cases;
    more than :data:`MAX_SWEEP_CASES` cases is an InputError, said before any case is built."""
    import pandas as pd

    if isinstance(grid, pd.DataFrame):
        check_case_count([len(grid)], "sweep grid")
        paths = [str(c) for c in grid.columns]
        cases = [tuple(row) for row in grid.itertuples(index=False, name=None)]
    elif isinstance(grid, Mapping):
        paths = [str(p) for p in grid]
        values = []
        for path in paths:
            entry = grid[path]
            if isinstance(entry, (str, bytes)) or not isinstance(entry, Iterable):
                raise InputError(f"sweep grid: {path!r} = {entry!r}; give a list of values")
            values.append(list(itertools.islice(entry, MAX_SWEEP_CASES + 1)))  # a longer one is refused below
        check_case_count([len(v) for v in values], "sweep grid")
        cases = list(itertools.product(*values))
    else:
        raise InputError(f"sweep grid: expected a mapping {{path: [values]}} or a DataFrame of cases, got "
                         f"{type(grid).__name__}")
    if not paths or not cases:
        raise InputError("sweep grid: no cases (give at least one path with at least one value)")
    return paths, cases


def check_case_count(lengths: Sequence[int], where: str) -> None:
    """InputError naming ``where`` when the cartesian product of value lists of these ``lengths`` (or a
    table of that many rows) makes more than :data:`MAX_SWEEP_CASES` cases."""
    cases = math.prod(lengths)
    if cases > MAX_SWEEP_CASES:
        raise InputError(f"{where} makes {cases:.3g} cases ({' x '.join(map(str, lengths))}); allowed: at most "
                         f"{MAX_SWEEP_CASES} (split the study into several sweeps)")


def _parameter_columns(paths: Sequence[str], cases: Sequence[tuple]) -> list[tuple[str, Any]]:
    """Per path: (column header, converter of a value to the cell) — units in the header."""
    columns = []
    for k, path in enumerate(paths):
        values = [case[k] for case in cases]
        unit = None
        if all(isinstance(v, (str, pint.Quantity)) for v in values):
            try:
                quantities = [v if isinstance(v, pint.Quantity) else ureg.Quantity(v) for v in values]
                # a unit each (angles and percentages too, which pint counts dimensionless): numeric cells
                if all(str(q.units) != "dimensionless" for q in quantities) \
                        and len({q.dimensionality for q in quantities}) == 1:
                    unit = quantities[0].units
            except Exception:
                unit = None
        if unit is not None:
            label = f"{unit:~P}".replace(" ", "")

            def cell(v, unit=unit, path=path):
                q = v if isinstance(v, pint.Quantity) else ureg.Quantity(v)  # parsed once already, above
                return float(q.to(unit).magnitude)

            columns.append((f"{path} [{label}]", cell))
        elif all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
            columns.append((f"{path} [-]", lambda v: v))
        else:
            columns.append((path, lambda v: v if isinstance(v, (int, float, str, bool)) else str(v)))
    return columns


def _case_rows(runner: Any, scene: Any, paths: Sequence[str], values: Sequence[Any], outputs, models, effects,
               table: str, units) -> list[dict[str, Any]]:
    """The report rows (dicts) of one case: the scene with ``values`` at ``paths``, analysed by ``runner``."""
    case = scene
    for path, value in zip(paths, values):
        case = evolve_path(case, path, value)
    result = runner(case, outputs=outputs, models=models, effects=effects).run()
    if result.index is not None and table != "index":
        frame = result.summary_frame(units)
    else:
        frame = result.to_frame(units)
        if result.index is not None:  # the case's summaries (cycle minima, lives) beside its per-index rows
            frame = _with_summaries(frame, result.summary_frame(units))
    return frame.to_dict(orient="records")


def _with_summaries(rows: Any, summary: Any) -> Any:
    """The per-index ``rows`` of a result with its scalar outputs (``summary``, one row per variant) on each of
    the variant's rows; ``failed`` and ``error`` stay the per-index frame's (both frames have them alike), the
    ``not_given`` of both are joined (a variant without a summary says so beside its NaN)."""
    scalars = [c for c in summary.columns if c not in rows.columns and c not in ("variant", "failed", "error",
                                                                                  "not_given")]
    variants = "variant" in rows
    if "not_given" in summary:  # per variant (None: the one variant of a result without labels)
        extra = dict(zip(summary["variant"] if variants else [None], summary["not_given"]))
        own = rows["not_given"] if "not_given" in rows else [""] * len(rows)
        keys = rows["variant"] if variants else [None] * len(rows)
        rows = rows.assign(not_given=[", ".join(part for part in (mine, extra[key]) if part)
                                      for mine, key in zip(own, keys)])
    if not scalars:
        return rows
    if variants:
        return rows.merge(summary[["variant", *scalars]], on="variant", how="left", sort=False)
    return rows.assign(**{c: summary[c].iloc[0] for c in scalars})


def run_case(runner: Any, scene: Any, paths: Sequence[str], values: Sequence[Any], outputs, models, effects,
             table: str, units, *, timeout: float | None = None, errors: str = "record",
             number: int | None = None) -> list[dict[str, Any]] | str:
    """One case: the scene with ``values`` at ``paths``, analysed by ``runner``; its report rows (dicts),
    or the error text ``"ExceptionType: message"`` when the case fails (the sweep keeps it with the case).

    ``timeout`` [s]: a case still running after it fails with ``"CaseTimeout: case exceeded 5 s"`` (see
    :class:`CaseAlarm`). ``errors="raise"``: the case's exception itself propagates, with the note
    ``"sweep case {number}: {path: value, ...}"``.
    """
    alarm = CaseAlarm(timeout)
    error: Exception | None = None
    try:
        with alarm:
            rows = _case_rows(runner, scene, paths, values, outputs, models, effects, table, units)
    except Exception as exc:
        error = exc
    if error is None and not alarm.fired:
        return rows
    # a timeout that the analysis caught in a step (and went on, or failed otherwise) is still the timeout
    failure = error if error is not None and (not alarm.fired or isinstance(error, CaseTimeout)) \
        else CaseTimeout(alarm.message)
    if errors != "raise":
        return f"{type(failure).__name__}: {failure}"
    failure.add_note(f"sweep case {number}: {dict(zip(paths, values))}")
    if failure is error:
        raise failure
    raise failure from error


def run_cases(runner: Any, scene: Any, paths: Sequence[str], chunk: Sequence[Sequence[Any]], *rest: Any,
              numbers: Sequence[int] | None = None, **options: Any) -> list:
    """:func:`run_case` for a chunk of cases (one task of an executor: less shipping per case); ``numbers``
    are the cases' numbers in the grid (for the note of a raised exception), ``options`` those of
    :func:`run_case`. A case's exception (``errors="raise"``) that would not pickle back comes back as a
    RuntimeError ``"ExceptionType: message"`` with the same notes."""
    numbers = range(len(chunk)) if numbers is None else numbers
    try:
        return [run_case(runner, scene, paths, values, *rest, number=number, **options)
                for number, values in zip(numbers, chunk)]
    except Exception as exc:
        if _pickles(exc):
            raise
        stand_in = RuntimeError(f"{type(exc).__name__}: {exc}")
        for note in getattr(exc, "__notes__", ()):
            stand_in.add_note(note)
    raise stand_in  # here, not in the except block: no __context__ (that some picklers ship too) to fail


def _pickles(exc: BaseException) -> bool:
    """True when ``exc`` survives pickling (the way an executor ships it back)."""
    try:
        pickle.loads(pickle.dumps(exc))
    except Exception:
        return False
    return True


class CaseAlarm:
    """A context that raises :class:`~camcontact.errors.CaseTimeout` in its block after ``timeout`` [s]
    (None: never) and again every :attr:`REPEAT` s until the block is left — so a step that catches the
    first one (an analysis isolating failing steps) is stopped too; :attr:`fired` says whether it rang.

    It uses SIGALRM and the process's real-time interval timer (``signal.setitimer``), so it can only
    interrupt the main thread of a process — a serial sweep, and the worker processes of a
    ``ProcessPoolExecutor`` — and only between Python-level calls: one long numba kernel call is not
    interrupted mid-call, the timeout is noticed when it returns. Where no alarm is possible (another
    thread, e.g. a thread pool or a Dask worker; a platform without SIGALRM) it warns once and the case
    runs without a timeout. On leaving, the timer is stopped and the previous SIGALRM handler restored.
    """

    REPEAT = 0.2  # [s] between the alarms after the first one
    warned = False  # the "no alarm possible here" warning was given (it is given once per process)

    def __init__(self, timeout: float | None):
        self.timeout = timeout
        self.fired = False
        self._armed = False
        self._installed = False
        self._previous: Any = None

    @property
    def message(self) -> str:
        """The timeout's message: ``"case exceeded 5 s"``."""
        return f"case exceeded {self.timeout:g} s"

    def __enter__(self) -> Self:
        if self.timeout is None:
            return self
        if not (hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()):
            self._warn_unavailable()
            return self
        self._previous = signal.signal(signal.SIGALRM, self._ring)
        self._installed = True
        try:
            self._armed = True
            signal.setitimer(signal.ITIMER_REAL, self.timeout, self.REPEAT)
        except BaseException:  # a very short timeout rang already: the block is not entered, the timer stops
            self.__exit__()
            raise
        return self

    def _ring(self, signum: int, frame: Any) -> None:
        if self._armed:
            self.fired = True
            raise CaseTimeout(self.message)

    def __exit__(self, *exc_info: object) -> bool:
        if not self._installed:
            return False
        while True:  # an alarm may ring once more before the timer stops: it is ignored once disarmed
            try:
                self._armed = False
                signal.setitimer(signal.ITIMER_REAL, 0)
                break
            except CaseTimeout:
                continue
        self._installed = False
        signal.signal(signal.SIGALRM, signal.SIG_DFL if self._previous is None else self._previous)
        return False

    @classmethod
    def _warn_unavailable(cls) -> None:
        if cls.warned:
            return
        cls.warned = True
        where = "this platform has no SIGALRM" if not hasattr(signal, "setitimer") else \
            f"cases run in thread {threading.current_thread().name!r}, not the main thread of their process"
        warnings.warn(f"sweep timeout not applied: {where}; the cases run without a time limit (a "
                      "ProcessPoolExecutor or a serial sweep can apply it)", CamcontactWarning, stacklevel=4)


def _chunk_size(cases: int, requested: int | None) -> int:
    if requested is not None:
        if not (isinstance(requested, int) and requested >= 1):
            raise InputError(f"sweep: chunksize = {requested!r}; allowed: an integer >= 1")
        return requested
    return max(1, min(16, cases // 32))  # about 32+ tasks: balanced over workers, little shipping


def _progress(total: int, enabled: bool | None, done: int = 0):
    if enabled is None:
        enabled = total > 1 and sys.stderr.isatty()
    if not enabled:
        return None
    from tqdm.auto import tqdm

    return tqdm(total=total, initial=done, desc="sweep", unit="case", file=sys.stderr)


def _check_options(errors: str, table: str, timeout: Any, stream: Any, resume: Any) -> None:
    """InputError for an option of :func:`run_sweep` outside what it allows (the stream path: by
    :func:`~camcontact.sweep_stream.check_stream_path`)."""
    if errors not in ("record", "raise"):
        raise InputError(f"sweep: errors = {errors!r}; allowed: 'record', 'raise'")
    if table not in TABLES:
        raise InputError(f"sweep: table = {table!r}; allowed: {', '.join(map(repr, TABLES))}")
    if timeout is not None and (isinstance(timeout, bool) or not isinstance(timeout, Real)
                                or not math.isfinite(timeout) or timeout <= 0):
        raise InputError(f"sweep: timeout = {timeout!r}; allowed: None or a finite number of seconds > 0")
    if not isinstance(resume, bool):
        raise InputError(f"sweep: resume = {resume!r}; allowed: True or False")
    if resume and stream is None:
        raise InputError("sweep: resume = True needs stream = the CSV file of the sweep to resume")


def _parameters(columns: Sequence[tuple[str, Any]], values: Sequence[Any]) -> dict[str, Any]:
    """The parameter cells of a case: {column header: cell}."""
    return {header: cell(value) for (header, cell), value in zip(columns, values)}


def case_rows(number: int, parameters: Mapping[str, Any], outcome: list[dict[str, Any]] | str) -> list[dict]:
    """The table rows of case ``number``: ``case``, its parameter cells, then its report rows (a row's own
    ``failed`` flag and ``error`` text kept, ``error`` ``""`` when it has none) — or, for a case that
    failed (``outcome`` its error text), one row with the error."""
    if isinstance(outcome, str):
        return [{"case": number, **parameters, "error": outcome}]
    rows = []
    for row in outcome:
        status = {"failed": row["failed"]} if "failed" in row else {}
        error = row.get("error")
        rows.append({"case": number, **parameters, **{k: v for k, v in row.items() if k not in ("failed", "error")},
                     **status, "error": error if isinstance(error, str) else ""})
    return rows


def _same_cell(found: Any, expected: Any) -> bool:
    """True when a cell read from a stream file is the grid's cell (numbers exactly, else as text)."""
    if isinstance(found, Real) and isinstance(expected, Real):
        if isinstance(found, (bool, np.bool_)) or isinstance(expected, (bool, np.bool_)):
            return bool(found) == bool(expected)
        return float(found) == float(expected) or (math.isnan(float(found)) and math.isnan(float(expected)))
    return str(found) == str(expected)


def finished_cases(path: Any, columns: Sequence[tuple[str, Any]], cases: Sequence[tuple]) -> set[int]:
    """The numbers of the cases already in the stream file at ``path``; InputError when the file belongs to
    another sweep (no ``case`` or parameter column, a case number beyond the grid, or parameter cells
    that are not the grid's for that case number)."""
    import pandas as pd

    from .sweep_stream import read_sweep

    frame = read_sweep(path)
    if frame.empty:
        return set()
    where = f"sweep: stream = {str(path)!r} belongs to another sweep"
    headers = ["case", *(header for header, _ in columns)]
    absent = [h for h in headers if h not in frame]
    if absent or not pd.api.types.is_integer_dtype(frame["case"]):
        raise InputError(f"{where}: {'no column(s) ' + ', '.join(map(repr, absent)) if absent else 'case not integer'}; "
                         "remove it or give another stream (or resume=False to start it anew)")
    numbers_in = [int(n) for n in frame["case"]]
    beyond = [n for n in numbers_in if not 0 <= n < len(cases)]
    if beyond:
        raise InputError(f"{where}: case {beyond[0]} there, this grid has cases 0 to {len(cases) - 1}; "
                         "remove it or give another stream (or resume=False to start it anew)")
    expected = {number: _parameters(columns, cases[number]) for number in set(numbers_in)}
    for header, _ in columns:
        for number, found in zip(numbers_in, frame[header].tolist()):
            if not _same_cell(found, expected[number][header]):
                raise InputError(f"{where}: case {number} has {header} = {found!r} there, {expected[number][header]!r} in this "
                                 "grid; remove it or give another stream (or resume=False to start it anew)")
    return set(numbers_in)


def _run_here(pending: Sequence[int], run: Callable[[int], Any], record: Callable[[int, Any], None]) -> str | None:
    """Run the ``pending`` cases one after the other; None, or ``"interrupt"`` after a KeyboardInterrupt."""
    try:
        for number in pending:
            record(number, run(number))
    except KeyboardInterrupt:
        return "interrupt"
    return None


def _collect(future: Future, numbers: Sequence[int], record: Callable[[int, Any], None]) -> str | None:
    """Record the outcomes of a finished task; ``"broken"`` when its executor broke (a worker process died),
    ``"interrupt"`` when the worker got the SIGINT (a terminal's Ctrl-C reaches the whole process group)."""
    try:
        outcomes = future.result()
    except BrokenExecutor:
        return "broken"
    except KeyboardInterrupt:
        return "interrupt"
    for number, outcome in zip(numbers, outcomes):
        record(number, outcome)
    return None


def _run_on(executor: Executor, chunks: Sequence[list[int]], submit: Callable[[list[int]], Future],
            record: Callable[[int, Any], None]) -> str | None:
    """Run the ``chunks`` of case numbers as tasks of ``executor``, recording each as it finishes; None, or
    why it stopped early (``"interrupt"``: SIGINT; ``"broken"``: the executor broke). On a stop — or a
    case's exception with ``errors="raise"`` — the pending tasks are cancelled (the executor itself is
    left to its owner) and the tasks that did finish are still recorded."""
    futures: dict[Future, list[int]] = {}
    seen: set[Future] = set()
    stop = None
    try:
        for chunk in chunks:
            futures[submit(chunk)] = chunk
        for future in as_completed(futures):
            seen.add(future)
            outcome = _collect(future, futures[future], record)
            stop = stop or outcome
            if outcome == "interrupt":
                break
    except KeyboardInterrupt:
        stop = "interrupt"
    except BrokenExecutor:  # from submit: the executor was broken already
        stop = "broken"
    finally:
        if stop is not None or len(seen) < len(futures):
            _salvage(futures, seen, record)
    return stop


def _salvage(futures: Mapping[Future, list[int]], seen: set[Future], record: Callable[[int, Any], None]) -> None:
    """Cancel the tasks not started and record those that finished but were not collected yet."""
    for future in futures:
        future.cancel()
    for future, numbers in futures.items():
        if future not in seen and future.done() and not future.cancelled() and future.exception() is None:
            seen.add(future)
            _collect(future, numbers, record)


def _empty_table(columns: Sequence[tuple[str, Any]]):
    """The table of a sweep that finished no case: its columns, no rows."""
    import pandas as pd

    return pd.DataFrame(columns=["case", *(header for header, _ in columns), "error"])


def _report_missing(frame, total: int, stop: str | None, stream: Path | None, stacklevel: int = 3) -> None:
    """Set ``frame.attrs`` (``missing_cases``, ``interrupted``, ``executor_broken``) and warn when cases are
    missing."""
    missing = sorted(set(range(total)) - {int(n) for n in frame["case"]})
    frame.attrs.update(missing_cases=missing, interrupted=stop == "interrupt", executor_broken=stop == "broken")
    if not missing:
        return
    why = "SIGINT" if stop == "interrupt" else "the executor broke: a worker process died"
    if stream is not None:
        how = (f"the {total - len(missing)} finished cases are in {str(stream)!r}; run the same sweep with "
               f"stream={str(stream)!r}, resume=True to finish it")
    else:
        how = "give stream='sweep.csv' to keep finished cases on disk, and run again with resume=True to finish"
    warnings.warn(f"sweep interrupted ({why}): {len(missing)} of {total} cases missing "
                  f"(frame.attrs['missing_cases']); {how}", SweepInterruptedWarning, stacklevel=stacklevel)


def run_sweep(runner: Any, scene: Any, grid: Any, *, outputs=None, models=None, effects=None, executor: Executor | None = None,
              progress: bool | None = None, errors: str = "record", table: str = "auto", units=None,
              chunksize: int | None = None, timeout: float | None = None, stream: Any = None, resume: bool = False):
    """The sweep of ``scene`` over ``grid`` (see :mod:`camcontact.sweep`) as a pandas DataFrame, each case
    run by ``runner`` (the :class:`~camcontact.analysis.Analysis` class).

    ``executor``: None runs the cases here, one after the other; any ``concurrent.futures.Executor``
    runs them there, ``chunksize`` cases per task (default: about 32 tasks or more, at most 16 cases
    each). ``progress``: a tqdm bar on stderr (None: when stderr is a terminal).
    ``errors="raise"``: the first failing case's own exception propagates (its type kept, through an
    executor too), with the note ``"sweep case 2: {'load': '-1 kN'}"``; serially that is the first in
    the grid's order, on an executor the first to finish.
    ``table``: ``"cases"`` (one row per case and variant; cycle summaries for indexed scenes),
    ``"index"`` (per case and index value) or ``"auto"`` (``"index"`` when outputs per index value are
    asked for, or by default).
    ``timeout`` [s]: a case still running after it is recorded as failed, ``"CaseTimeout: case exceeded
    5 s"``, and the sweep goes on (checked between Python-level calls, in serial sweeps and process-pool
    workers; see :class:`CaseAlarm`).
    ``stream``: a ``.csv`` path; every finished case's rows are appended to it at once (see
    :mod:`camcontact.sweep_stream`; :func:`~camcontact.sweep_stream.read_sweep` reads it back as this
    table). Without ``resume`` the file is started anew.
    ``resume=True``: the cases already in ``stream`` (matched by case number and parameter cells; a file
    of another sweep is an InputError) are not run again; the others are appended, and the complete
    table is returned, equal to an uninterrupted sweep's.

    A SIGINT (KeyboardInterrupt) or a broken executor (a worker process killed) stops the sweep: the
    pending tasks are cancelled, the finished cases are returned (and are on disk with ``stream``), a
    :class:`~camcontact.errors.SweepInterruptedWarning` says how many are missing and how to resume, and
    ``frame.attrs`` holds ``missing_cases`` (the numbers of the cases not finished — those of a task
    whose worker died among them), ``interrupted`` (SIGINT) and ``executor_broken`` (all three also set,
    empty/False, on a complete sweep).
    """
    import pandas as pd

    from .sweep_stream import CsvStream, check_stream_path, read_sweep, tidy_table

    _check_options(errors, table, timeout, stream, resume)
    path = None if stream is None else check_stream_path(stream)
    paths, cases = cases_of(grid)
    for name in paths:  # a wrong path is the grid's error, not a case's: said before anything runs
        check_path(scene, name)
    columns = _parameter_columns(paths, cases)
    if table == "auto":
        table = "index" if has_index(runner(scene, outputs=outputs, models=models, effects=effects)) else "cases"
    rest = (None if outputs is None else list(outputs), None if models is None else dict(models),
            None if effects is None else list(effects), table, None if units is None else dict(units))
    options = {"timeout": timeout, "errors": errors}
    sink = None if path is None else CsvStream(path, resume=resume)
    done = set() if path is None else finished_cases(path, columns, cases)
    pending = [number for number in range(len(cases)) if number not in done]
    collected: dict[int, list[dict[str, Any]]] = {}
    bar = _progress(len(cases), progress, done=len(done))

    def record(number: int, outcome: Any) -> None:
        rows = case_rows(number, _parameters(columns, cases[number]), outcome)
        if sink is not None:
            sink.append(rows)
        collected[number] = rows
        if bar is not None:
            bar.update(1)

    try:
        if executor is None:
            stop = _run_here(pending, lambda n: run_case(runner, scene, paths, cases[n], *rest, number=n, **options),
                             record)
        else:
            size = _chunk_size(len(pending), chunksize)
            chunks = [pending[i:i + size] for i in range(0, len(pending), size)]
            stop = _run_on(executor, chunks, lambda chunk: executor.submit(
                run_cases, runner, scene, paths, [cases[n] for n in chunk], *rest, numbers=chunk, **options), record)
    finally:
        if bar is not None:
            bar.close()
    if sink is not None:
        sink.sort()
        frame = read_sweep(path)
    else:
        frame = tidy_table(pd.DataFrame([row for n in sorted(collected) for row in collected[n]]))
    if frame.empty and "case" not in frame:
        frame = _empty_table(columns)
    frame.attrs["dimensions"], frame.attrs["index"] = _dimensions(frame, [header for header, _ in columns], table)
    _report_missing(frame, len(cases), stop, path)
    return frame


def _dimensions(frame: Any, parameters: list[str], table: str) -> tuple[list[str], str | None]:
    """The columns a full grid of this table is indexed by — the swept paths, the variant (several models in a
    slot) and, for a per-index table, the index column (cam angle, roller), the first after them — and that
    index column (None: a table per case, or one where every case failed)."""
    dims = list(parameters) + (["variant"] if "variant" in frame.columns else [])
    others = [c for c in frame.columns if c not in ("case", "failed", "error", "not_given", *dims)]
    index = others[0] if table == "index" and others else None
    return dims + ([index] if index else []), index


def has_index(analysis: Any) -> bool:
    """True when a planned analysis reports outputs per index value (cam angle, roller)."""
    return any(graph.index is not None and set(planned) & graph.per_index
               for graph, planned, _ in analysis.plans.values())
