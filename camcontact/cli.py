"""The ``camcontact`` command.

``camcontact run [SCENE.toml] [--csv F] [--units NAME=UNIT] [--plot PNG] [--strict]``
    run a scene (default: the embedded default scene), print the report and the steps that
    ran, write the report as CSV (and a plot with ``--plot``). A step that fails leaves NaN in
    its outputs with the reason (the report's ``failed``/``error`` columns, one warning line);
    ``--strict`` stops at it instead.
``camcontact sweep SCENE.toml [--workers N] [--csv F] [--resume] [--timeout S] [--parquet F] [--strict]``
    run the scene over its [sweep] table (the cartesian product of field values) into one
    table, serially or on N worker processes (capped at the cases and CPUs), with a progress
    bar; the CSV is written as cases finish and ``--resume`` goes on from it; failing cases keep
    their error; a case past ``--timeout`` seconds is recorded as such.
``camcontact plugins [--family F]``
    list every model of the registry: name, family, source distribution, reference, status.
``camcontact default-scene``
    print the embedded default scene, a template for your own.

Everything a run needs is checked before it starts: the scene file (a regular UTF-8 file of at
most 1 MB, see :mod:`camcontact.scene_file`), the report units (``--units h_min=nm``, repeated or
comma-separated, and the scene's [report] units: outputs of the planned analysis, units of their
dimension) and the output paths (``--csv``, ``--plot``). Every error is one line on stderr,
``camcontact: error: ...`` (``--debug``, before or after the command, prints the traceback too);
exit status 0 success, 2 bad input, 1 a failure while running, 130 interrupted, 141 stdout closed
early (``camcontact run | head``: quietly, as a shell reports a SIGPIPE).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import traceback
import warnings
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Any

from . import __version__
from .errors import InputError, StepFailureWarning

__all__ = ["EXIT_BROKEN_PIPE", "EXIT_FAILURE", "EXIT_INPUT", "EXIT_INTERRUPTED", "main"]


#: exit status of bad input (an InputError, bad arguments: as argparse's usage errors)
EXIT_INPUT = 2
#: exit status of a failure while running (any other exception; an output file that cannot be written)
EXIT_FAILURE = 1
#: exit status after Ctrl-C (128 + SIGINT, as a shell reports it)
EXIT_INTERRUPTED = 130
#: exit status when stdout is closed early (``camcontact run | head``): 128 + SIGPIPE, as a shell reports it
EXIT_BROKEN_PIPE = 141
#: error lines longer than this are cut (a value quoted from a huge scene file must not flood the terminal)
MAX_ERROR_TEXT = 4000


class _OutputError(Exception):
    """An output file could not be written (its message names the option and the path)."""


class _Parser(argparse.ArgumentParser):
    """argparse with one-line usage errors: ``camcontact: error: ...`` and exit status 2."""

    def error(self, message: str):  # argparse's hook for usage errors
        self.exit(EXIT_INPUT, f"camcontact: error: {_one_line(message)} (see '{self.prog} --help')\n")


def _one_line(message: str) -> str:
    """``message`` on one line: control characters (newlines, escapes) as spaces, cut at MAX_ERROR_TEXT."""
    text = _printable(message, mark=" ")
    if len(text) > MAX_ERROR_TEXT:
        text = f"{text[:MAX_ERROR_TEXT]}... ({len(text) - MAX_ERROR_TEXT} more characters)"
    return text


def _unit_pairs(text: str) -> list[tuple[str, str]]:
    """One ``--units`` value: ``NAME=UNIT``, or several separated by commas (``h_min=nm,p_h=GPa``)."""
    pairs = []
    for item in text.split(","):
        name, sep, unit = item.partition("=")
        if not sep or not name.strip() or not unit.strip():
            raise argparse.ArgumentTypeError(f"{item.strip()!r} is not NAME=UNIT; give e.g. --units h_min=nm "
                                             f"(repeat --units, or separate pairs with commas: h_min=nm,p_h=GPa)")
        pairs.append((name.strip(), unit.strip()))
    return pairs


def _planned(analysis: Any) -> tuple[set[str], str | None]:
    """The outputs the planned variants of ``analysis`` give (any variant), and its index (cam angle, roller)
    or None — from the plan, without running anything."""
    outputs = {name for _, names, _ in analysis.plans.values() for name in names}
    index = next((graph.index for graph, _, _ in analysis.plans.values()), None)
    return outputs, index


def _display_units(scene: Any, where: str, pairs: list[tuple[str, str]], outputs: set[str],
                   index: str | None) -> dict[str, str]:
    """The report units of the scene's [report] table and of ``--units`` (which wins), each checked against
    the planned outputs and its quantity's dimension — before anything runs."""
    from .scene_file import check_report_unit

    known = outputs | ({index} if index else set())
    units = {}
    for source, name, unit in [(f"{where} [report] units", *item) for item in scene.units.items()] + [
            ("--units", *item) for item in pairs]:
        if name not in known:
            raise InputError(f"{source}: {name!r} is not an output of this analysis; outputs: {', '.join(sorted(known))}")
        check_report_unit(name, unit, source)
        units[name] = unit
    return units


def _check_output(path: Path, option: str) -> None:
    """InputError unless a file can be written at ``path``: not a directory, its directory exists and a file
    can be created there (tried, then removed) or the existing file is writable — checked before the run."""
    where = f"{option} {str(path)!r}"
    if path.is_dir():
        raise InputError(f"{where}: is a directory; give a file name")
    if path.exists():
        if not os.access(path, os.W_OK):
            raise InputError(f"{where}: the file is not writable")
        return
    if not path.parent.is_dir():
        raise InputError(f"{where}: the directory {str(path.parent)!r} does not exist")
    try:
        descriptor = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL)
    except OSError as exc:
        raise InputError(f"{where}: cannot create the file ({exc.strerror or exc})") from None
    os.close(descriptor)
    path.unlink()


def _check_plot(path: Path) -> None:
    """InputError unless matplotlib is installed and knows the image format of ``path``'s suffix."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        from matplotlib.backend_bases import FigureCanvasBase
    except ImportError:
        raise InputError("--plot needs matplotlib: pip install 'camcontact[plot]'") from None
    formats = FigureCanvasBase.get_supported_filetypes()
    suffix = path.suffix.lstrip(".").lower()
    if suffix and suffix not in formats:
        raise InputError(f"--plot {str(path)!r}: unknown image format {suffix!r}; allowed: {', '.join(sorted(formats))}")
    _check_output(path, "--plot")


def _write(path: Path, option: str, write: Callable[[Path], Any]) -> None:
    """``write(path)``; an OSError (disk full, ...) becomes an error line naming the option and the path."""
    try:
        write(path)
    except OSError as exc:
        raise _OutputError(f"cannot write the {option} file {str(path)!r}: {exc.strerror or exc}") from exc


def _printable(text: str, mark: str = "?") -> str:
    """``text`` with control characters (terminal escapes, newlines) shown as ``mark``."""
    return "".join(ch if ch.isprintable() else mark for ch in text)


def _print_before_run(*lines: str) -> bool:
    """Print ``lines`` (and flush); False when stdout is closed (broken pipe): stdout then goes to devnull, and
    the command still runs and writes its files before it ends with EXIT_BROKEN_PIPE."""
    try:
        for line in lines:
            print(line)
        sys.stdout.flush()
    except BrokenPipeError:
        _quiet_stdout()
        return False
    return True


def _run(args: argparse.Namespace) -> int:
    """``camcontact run``: everything is checked (scene, units, output paths) before the analysis runs; the
    files are written before the tables are printed, so a closed stdout loses nothing."""
    import pandas as pd

    from .report import text_table
    from .scene_file import load_scene

    scene = load_scene(args.scene)
    analysis = scene.analysis(strict=args.strict)  # plans the steps (and checks them); runs nothing
    outputs, index = _planned(analysis)
    units = _display_units(scene, args.scene or "default scene", [p for ps in args.units or [] for p in ps],
                           outputs, index)
    default_csv = f"{Path(args.scene).stem if args.scene else 'default_scene'}_report.csv"
    csv_path = Path(args.csv if args.csv is not None else default_csv)
    summary_path = csv_path.with_name(csv_path.stem + "_summary.csv") if index is not None else None
    _check_output(csv_path, "--csv")
    if summary_path is not None:
        _check_output(summary_path, "--csv (its cycle summary)")
    if args.plot is not None:
        _check_plot(Path(args.plot))

    swept = ([f"[sweep] table of {math.prod(len(v) for v in scene.sweep.values())} cases over "
              f"{', '.join(scene.sweep)}: this runs the base case; camcontact sweep {args.scene} runs them all"]
             if scene.sweep else [])
    stdout_closed = not args.quiet and not _print_before_run(
        f"camcontact {__version__} — scene: {_printable(scene.name)}", *map(_printable, swept),
        f"steps: {', '.join(analysis.steps())}" + (f"; {len(analysis.variants)} variants" if len(analysis.variants) > 1 else ""))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", StepFailureWarning)
        result = analysis.run()
    for warning in caught:  # a failed step: one line each (the report's failed/error columns say it too)
        if issubclass(warning.category, StepFailureWarning):
            print(f"camcontact: warning: {_printable(str(warning.message))}", file=sys.stderr)
        else:
            warnings.warn_explicit(warning.message, warning.category, warning.filename, warning.lineno)
    frame = result.to_frame(units=units)
    _write(csv_path, "--csv", lambda path: frame.to_csv(path, index=False))
    if index is not None:
        summary = result.summary_frame(units={k: v for k, v in units.items() if k in result.outputs})
        _write(summary_path, "--csv (its cycle summary)", lambda path: summary.to_csv(path, index=False))
    if args.plot is not None:
        figure = result.plot()
        _write(Path(args.plot), "--plot", lambda path: figure.savefig(path, dpi=120))
    if stdout_closed:
        return EXIT_BROKEN_PIPE
    if args.quiet:  # the files are written; nothing on stdout
        return 0

    print()
    if index is None:
        print(text_table(frame))
    else:
        print("cycle summary:")
        print(text_table(summary))
        print()
        every = max(1, len(frame) // (24 * max(1, len(result.variants))))
        shown = frame.iloc[::every] if every > 1 else frame
        print(f"per {result.index}" + (f" (one row in {every} of {len(frame)}; all rows in the CSV)" if every > 1 else "") + ":")
        with pd.option_context("display.width", 250, "display.max_columns", 40, "display.max_colwidth", 28):
            print(shown.to_string(index=False, float_format=lambda v: f"{v:.5g}"))
    print()
    steps = result.steps_frame()
    print(f"{len(steps)} steps ran in {1e3 * result.wall_time:.1f} ms:")
    print(steps.to_string(index=False, float_format=lambda v: f"{v:.3f}"))
    print(f"\nreport written to {csv_path}" + (f" (cycle summary: {summary_path})" if index is not None else ""))
    if args.plot is not None:
        print(f"plot written to {args.plot}")
    return 0


def _sweep(args: argparse.Namespace) -> int:
    """``camcontact sweep``: the scene, its report units and the output paths are checked before anything
    runs; the CSV file is written as cases finish (``--resume`` goes on from it), the Parquet file at the
    end. Interrupted (Ctrl-C, a worker process killed): one line says how many cases are on disk and the
    command that resumes; exit status 130 (Ctrl-C) or 1 (a broken process pool)."""
    import importlib.util
    from concurrent.futures import ProcessPoolExecutor

    from . import sweep as sweeps
    from .errors import SweepInterruptedWarning
    from .report_export import write_parquet
    from .scene_file import load_scene

    scene = load_scene(args.scene)
    if not scene.sweep:
        raise InputError(f"{args.scene}: no [sweep] table (give path = [values, ...] per swept field)")
    if args.workers < 0:
        raise InputError(f"--workers {args.workers}: allowed 0 (serial, here) or more")
    analysis = scene.analysis()  # plans the steps (and checks them); runs nothing
    units = _display_units(scene, args.scene, [], *_planned(analysis))
    csv_path = Path(args.csv) if args.csv else Path(f"{Path(args.scene).stem}_sweep.csv")
    _check_output(csv_path, "--csv")
    if args.parquet:
        if importlib.util.find_spec("pyarrow") is None:
            raise InputError("--parquet needs pyarrow: install the extra, pip install 'camcontact[parquet]'")
        _check_output(Path(args.parquet), "--parquet")
    if args.plot is not None:
        _check_plot(Path(args.plot))
    count = math.prod(len(values) for values in scene.sweep.values())
    workers = sweeps.worker_count(args.workers, count) if args.workers else 0
    capped = (f"; --workers {args.workers} capped to {workers} ({os.cpu_count() or 1} CPUs, {count} cases)"
              if workers != args.workers else "")
    if not args.quiet:
        print(f"camcontact {__version__} — sweep of {_printable(scene.name)}: {count} cases over "
              f"{', '.join(scene.sweep)}" + (f" on {workers} worker processes{capped}" if workers else ", serial"))
    options = {"outputs": analysis.requested, "models": analysis.models, "effects": analysis.effects, "units": units,
               "progress": None if not (args.no_progress or args.quiet) else False, "table": args.table, "timeout": args.timeout,
               "stream": csv_path, "resume": args.resume, "strict": args.strict}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SweepInterruptedWarning)  # said below, in one line
        if workers:
            with ProcessPoolExecutor(max_workers=workers) as pool:
                frame = sweeps.run_sweep(analysis.scene, scene.sweep, executor=pool, **options)
        else:
            frame = sweeps.run_sweep(analysis.scene, scene.sweep, **options)
    missing = frame.attrs["missing_cases"]
    if missing:
        print(f"camcontact: interrupted: {count - len(missing)} of {count} cases on disk in {csv_path}; resume "
              f"with: {_sweep_resume_command(args, csv_path)}", file=sys.stderr)
        return EXIT_INTERRUPTED if frame.attrs["interrupted"] else EXIT_FAILURE
    failed = frame.loc[frame["failed"] if "failed" in frame else frame["error"] != "", "case"].nunique()
    if args.plot is not None:
        from .sweep_plot import plot_sweep

        figure = plot_sweep(frame)
        _write(Path(args.plot), "--plot", lambda path: figure.savefig(path, dpi=120))
    if args.quiet:
        if args.parquet:
            _write(Path(args.parquet), "--parquet", lambda path: write_parquet(frame, path))
        if failed:  # quiet, not silent about what did not run
            print(f"camcontact: warning: {failed} of {count} cases failed (their reasons are in {csv_path})",
                  file=sys.stderr)
        return 0
    with __import__("pandas").option_context("display.width", 250, "display.max_columns", 30):
        print(frame.head(40).to_string(index=False, float_format=lambda v: f"{v:.5g}"))
    if len(frame) > 40:
        print(f"... {len(frame) - 40} more rows in the files")
    print(f"\n{len(frame)} rows ({failed} failed cases) written to {csv_path}")
    if args.parquet:
        _write(Path(args.parquet), "--parquet", lambda path: write_parquet(frame, path))
        print(f"Parquet written to {args.parquet}")
    if args.plot is not None:
        print(f"plot written to {args.plot}")
    return 0


def _sweep_resume_command(args: argparse.Namespace, csv_path: Path) -> str:
    """The shell command that resumes an interrupted ``camcontact sweep`` from its CSV file."""
    import shlex

    command = ["camcontact", "sweep", args.scene, "--csv", str(csv_path), "--resume"]
    if args.workers:
        command += ["--workers", str(args.workers)]
    if args.timeout is not None:
        command += ["--timeout", repr(args.timeout)]
    if args.table != "auto":
        command += ["--table", args.table]
    if args.parquet:
        command += ["--parquet", args.parquet]
    if args.no_progress:
        command.append("--no-progress")
    return shlex.join(command)


def _plugins(args: argparse.Namespace) -> int:
    from . import registry

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        rows = registry.entries(args.family)
    keys = ("name", "family", "source", "status", "reference")
    print(_left_aligned(keys, [[getattr(row, k) for k in keys] for row in rows], rule=True))
    for warning in caught:
        print(f"warning: {warning.message}", file=sys.stderr)
    return 0


def _outputs(args: argparse.Namespace) -> int:
    """``camcontact outputs``: what a scene file's scene can report (Analysis.available_outputs), the defaults
    marked, and what the unavailable ones need."""
    import pandas as pd

    from .scene_file import load_scene

    scene = load_scene(args.scene)
    table = scene.analysis().available_outputs()
    shown = pd.DataFrame({"output": table["output"], "unit": table["unit"].where(table["unit"] != "", "text"),
                          "default": table["default"].map({True: "yes", False: ""}),
                          "per": table["per_index"].map({True: "index", False: ""}), "step": table["step"],
                          "description": table["description"]})
    ready = table["available"]
    print(f"{_printable(scene.name)}: {int(ready.sum())} outputs (default: {int((ready & table['default']).sum())}); "
          "ask for any with outputs = [...] in the scene file or Analysis(outputs=[...])")
    print(_left_aligned(shown.columns, shown[ready].itertuples(index=False)))
    if not ready.all():
        print(f"\nneed more input ({int((~ready).sum())}):")
        print(_left_aligned(("output", "missing"), table.loc[~ready, ["output", "missing"]].itertuples(index=False)))
    return 0


def _left_aligned(header: Sequence[str], rows: Iterable[Sequence[Any]], *, rule: bool = False) -> str:
    """Rows of text as left-aligned columns under ``header`` (pandas right-aligns them), a line of dashes under
    the header with ``rule``; no trailing spaces."""
    rows = [[str(v) for v in row] for row in rows]
    width = [max([len(str(h))] + [len(row[k]) for row in rows]) for k, h in enumerate(header)]
    head = "  ".join(str(h).ljust(w) for h, w in zip(header, width)).rstrip()
    lines = [head, *(["-" * len(head)] if rule else [])]
    lines += ["  ".join(v.ljust(w) for v, w in zip(row, width)).rstrip() for row in rows]
    return "\n".join(lines)


def _default_scene(args: argparse.Namespace) -> int:
    from .scene_file import default_scene_text

    print(default_scene_text(), end="")
    return 0


def _failure(exc: BaseException) -> tuple[int, str] | None:
    """(exit status, error text) of an exception that ended a command; None: not ours to handle."""
    if isinstance(exc, InputError):
        return EXIT_INPUT, str(exc)
    if isinstance(exc, _OutputError):
        return EXIT_FAILURE, str(exc)
    if isinstance(exc, KeyboardInterrupt):
        return EXIT_INTERRUPTED, "interrupted"
    if isinstance(exc, SystemExit):
        return EXIT_FAILURE, f"sys.exit({exc.code!r}) was called while running (a plugin?); run with --debug for the traceback"
    if isinstance(exc, OSError) and exc.filename is not None:
        return EXIT_FAILURE, f"{exc.strerror or exc}: {exc.filename!r} (run with --debug for the traceback)"
    if isinstance(exc, Exception):
        return EXIT_FAILURE, f"{type(exc).__name__}: {exc} (run with --debug for the traceback)"
    return None


def _error(message: str) -> None:
    """Print ``camcontact: error: <message>`` as one line on stderr (quietly nothing if stderr is gone)."""
    try:
        print(f"camcontact: error: {_one_line(message)}", file=sys.stderr, flush=True)
    except (OSError, ValueError):
        pass


def _quiet_stdout() -> None:
    """After a broken pipe: point stdout at devnull, so the flush at exit does not raise again (the recipe of
    the Python docs, signal module, "Note on SIGPIPE")."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        pass


def _dispatch(args: argparse.Namespace) -> int:
    """Run the command's handler: its status, or the status and one error line of what stopped it."""
    try:
        status = args.handler(args)
        sys.stdout.flush()
        return status
    except BrokenPipeError:  # stdout closed by the reader (camcontact run | head): exit quietly
        if args.debug:
            traceback.print_exc()
        _quiet_stdout()
        return EXIT_BROKEN_PIPE
    except BaseException as exc:  # every failure is one line and an exit status
        failure = _failure(exc)
        if failure is None:
            raise
        if args.debug:
            traceback.print_exc()
        _error(failure[1])
        return failure[0]


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``camcontact`` console script; returns the exit status.

    0 success; 2 bad input (an :class:`~camcontact.errors.InputError`, bad arguments); 1 a failure while
    running (any other exception, an output file that cannot be written); 130 interrupted (Ctrl-C); 141
    stdout closed early (``camcontact run | head``, quietly). Every error is one line on stderr,
    ``camcontact: error: ...``; ``--debug`` prints the traceback too.
    """
    parser = _Parser(prog="camcontact", description="Lubricated contacts of machine elements.")
    parser.add_argument("--version", action="version", version=f"camcontact {__version__}")
    parser.add_argument("--debug", action="store_true", help="print the traceback of an error")
    parser.add_argument("-v", "--verbose", action="count", default=0,
                        help="log each step as it runs, with its model and time, on stderr (-vv: debug)")
    parser.add_argument("-q", "--quiet", action="store_true",
                        help="run and sweep print nothing but errors and failed cases (the files are written)")
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser("run", help="run a scene file (default: the embedded default scene)")
    run.add_argument("scene", nargs="?", help="scene TOML file")
    run.add_argument("--csv", help="where to write the report (default: <scene>_report.csv)")
    run.add_argument("--units", action="append", type=_unit_pairs, metavar="NAME=UNIT",
                     help="a display unit, e.g. h_min=nm; repeat it or separate pairs with commas (h_min=nm,p_h=GPa)")
    run.add_argument("--plot", metavar="PNG", help="also save a plot of the result")
    run.add_argument("--strict", action="store_true",
                     help="stop at the first failing step (default: its outputs are NaN, the report says why)")
    run.set_defaults(handler=_run)
    sweep = commands.add_parser("sweep", help="run a scene file over its [sweep] table into one table")
    sweep.add_argument("scene", help="scene TOML file with a [sweep] table")
    sweep.add_argument("--workers", type=int, default=0,
                       help="worker processes (default 0: serial, here); at most the cases and the CPUs")
    sweep.add_argument("--csv", help="where the table is written as cases finish (default: <scene>_sweep.csv)")
    sweep.add_argument("--resume", action="store_true",
                       help="go on from the --csv file of an interrupted sweep: run only the cases not in it")
    sweep.add_argument("--timeout", type=float, metavar="SECONDS",
                       help="a case still running after SECONDS is recorded as failed (CaseTimeout); the sweep goes on")
    sweep.add_argument("--parquet", help="also write the table as Parquet at the end (needs the [parquet] extra)")
    sweep.add_argument("--plot", metavar="PNG", help="also save a plot of the outputs against the first swept value")
    sweep.add_argument("--table", choices=("auto", "cases", "index"), default="auto",
                       help="rows per case, or per case and cam angle/roller (default: auto)")
    sweep.add_argument("--no-progress", action="store_true", help="no progress bar")
    sweep.add_argument("--strict", action="store_true",
                       help="a failing step fails its case (default: NaN in its outputs, the row says why)")
    sweep.set_defaults(handler=_sweep)
    plugins = commands.add_parser("plugins", help="list the models of the plugin registry")
    plugins.add_argument("--family", help="only this family")
    plugins.set_defaults(handler=_plugins)
    outputs = commands.add_parser("outputs", help="list the outputs a scene file's scene can give")
    outputs.add_argument("scene", nargs="?", help="scene TOML file (default: the embedded default scene)")
    outputs.set_defaults(handler=_outputs)
    default = commands.add_parser("default-scene", help="print the embedded default scene (a template)")
    default.set_defaults(handler=_default_scene)
    for command in commands.choices.values():  # --debug, -v and -q also after the command
        command.add_argument("--debug", action="store_true", default=argparse.SUPPRESS, help="print the traceback of an error")
        command.add_argument("-v", "--verbose", action="count", default=argparse.SUPPRESS,
                             help="log each step as it runs on stderr (-vv: debug)")
        command.add_argument("-q", "--quiet", action="store_true", default=argparse.SUPPRESS,
                             help="print nothing but errors and failed cases" if command in (run, sweep) else
                             "not for this command: it only prints (refused)")
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version, or a usage error (its line is printed)
        return exc.code if isinstance(exc.code, int) else EXIT_INPUT * (exc.code is not None)
    if args.verbose and args.quiet:
        _error("-v and -q: choose one")
        return EXIT_INPUT
    if args.quiet and args.command not in ("run", "sweep"):
        _error(f"-q with {args.command}: it prints its list and nothing else; -q is for run and sweep")
        return EXIT_INPUT
    import logging

    logger = logging.getLogger("camcontact")
    saved = (logger.level, logger.disabled)
    _configure_logging(args.verbose)
    try:
        return _dispatch(args)
    finally:  # main() leaves the logger as it found it (a notebook or test calling it keeps its own settings)
        _configure_logging(0)
        logger.setLevel(saved[0])
        logger.disabled = saved[1]


def _configure_logging(verbosity: int) -> None:
    """``-v``: the package's INFO records (each step, its model and time) on stderr; ``-vv``: DEBUG too."""
    import logging

    logger = logging.getLogger("camcontact")
    for handler in [h for h in logger.handlers if getattr(h, "camcontact_cli", False)]:
        logger.removeHandler(handler)
    if verbosity <= 0:
        return
    handler = logging.StreamHandler(sys.stderr)
    handler.camcontact_cli = True  # ours: replaced, not stacked, when main() runs again in one process
    handler.setFormatter(logging.Formatter("camcontact: %(message)s"))
    logger.addHandler(handler)
    logger.setLevel(logging.INFO if verbosity == 1 else logging.DEBUG)
    logger.disabled = False  # a library's logging.config (dask's) may have disabled the loggers it found


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
