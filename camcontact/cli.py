"""The ``camcontact`` command.

``camcontact run [SCENE.toml]``
    run a scene (default: the embedded default scene), print the report and the steps that
    ran, write the report as CSV (and a plot with ``--plot``).
``camcontact sweep SCENE.toml [--workers N] [--csv F] [--parquet F]``
    run the scene over its [sweep] table (the cartesian product of field values) into one
    table, serially or on N worker processes, with a progress bar; failing cases keep their error.
``camcontact plugins [--family F]``
    list every model of the registry: name, family, source distribution, reference, status.
``camcontact default-scene``
    print the embedded default scene, a template for your own.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import __version__
from .errors import InputError

__all__ = ["main"]


def _units(pairs: list[str]) -> dict[str, str]:
    units = {}
    for pair in pairs:
        name, sep, unit = pair.partition("=")
        if not sep or not name or not unit:
            raise InputError(f"--units expects name=unit (e.g. h_min=nm), got {pair!r}")
        units[name.strip()] = unit.strip()
    return units


def _run(args: argparse.Namespace) -> int:
    import pandas as pd

    from .report import text_table
    from .scene_file import load_scene

    scene = load_scene(args.scene)
    print(f"camcontact {__version__} — scene: {scene.name}")
    analysis = scene.analysis()
    print(f"steps: {', '.join(analysis.steps())}"
          + (f"; {len(analysis.variants)} variants" if len(analysis.variants) > 1 else ""))
    result = analysis.run()
    units = {**scene.units, **_units(args.units or [])}
    known = set(result.outputs) | ({result.index} if result.index else set())
    frame = result.to_frame(units={k: v for k, v in units.items() if k in known})
    csv_path = Path(args.csv) if args.csv else Path(f"{Path(args.scene).stem if args.scene else 'default_scene'}_report.csv")
    print()
    if result.index is None:
        print(text_table(frame))
    else:
        summary = result.summary_frame(units={k: v for k, v in units.items() if k in result.outputs})
        print("cycle summary:")
        print(text_table(summary))
        print()
        every = max(1, len(frame) // (24 * max(1, len(result.variants))))
        shown = frame.iloc[::every] if every > 1 else frame
        print(f"per {result.index}" + (f" (every {every}th row of {len(frame)}; all rows in the CSV)" if every > 1 else "") + ":")
        with pd.option_context("display.width", 250, "display.max_columns", 40, "display.max_colwidth", 28):
            print(shown.to_string(index=False, float_format=lambda v: f"{v:.5g}"))
        summary_path = csv_path.with_name(csv_path.stem + "_summary.csv")
        summary.to_csv(summary_path, index=False)
    print()
    steps = result.steps_frame()
    print(f"{len(steps)} steps ran in {1e3 * result.wall_time:.1f} ms:")
    print(steps.to_string(index=False, float_format=lambda v: f"{v:.3f}"))
    frame.to_csv(csv_path, index=False)
    print(f"\nreport written to {csv_path}" + (f" (cycle summary: {summary_path})" if result.index is not None else ""))
    if args.plot:
        try:
            import matplotlib

            matplotlib.use("Agg")
        except ImportError:
            raise InputError("--plot needs matplotlib: pip install 'camcontact[plot]'") from None
        figure = result.plot()
        figure.savefig(args.plot, dpi=120)
        print(f"plot written to {args.plot}")
    return 0


def _sweep(args: argparse.Namespace) -> int:
    from concurrent.futures import ProcessPoolExecutor

    from .report_export import write_csv, write_parquet
    from .scene_file import load_scene

    scene = load_scene(args.scene)
    if not scene.sweep:
        raise InputError(f"{args.scene}: no [sweep] table (give path = [values, ...] per swept field)")
    if args.workers < 0:
        raise InputError(f"--workers {args.workers}: allowed 0 (serial, here) or more")
    count = 1
    for values in scene.sweep.values():
        count *= len(values)
    print(f"camcontact {__version__} — sweep of {scene.name}: {count} cases over {', '.join(scene.sweep)}"
          + (f" on {args.workers} worker processes" if args.workers else ", serial"))
    analysis = scene.analysis()
    options = dict(progress=None if not args.no_progress else False, table=args.table, units=scene.units)
    if args.workers:
        with ProcessPoolExecutor(max_workers=args.workers) as pool:
            frame = analysis.sweep(scene.sweep, executor=pool, **options)
    else:
        frame = analysis.sweep(scene.sweep, **options)
    failed = int((frame["error"] != "").sum())
    with __import__("pandas").option_context("display.width", 250, "display.max_columns", 30):
        print(frame.head(40).to_string(index=False, float_format=lambda v: f"{v:.5g}"))
    if len(frame) > 40:
        print(f"... {len(frame) - 40} more rows in the files")
    csv_path = Path(args.csv) if args.csv else Path(f"{Path(args.scene).stem}_sweep.csv")
    write_csv(frame, csv_path)
    print(f"\n{len(frame)} rows ({failed} failed cases) written to {csv_path}")
    if args.parquet:
        write_parquet(frame, args.parquet)
        print(f"Parquet written to {args.parquet}")
    return 0


def _plugins(args: argparse.Namespace) -> int:
    import warnings

    from . import registry

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        rows = registry.entries(args.family)
    width = {key: max([len(key)] + [len(str(getattr(r, key))) for r in rows]) for key in ("name", "family", "source", "status")}
    header = "  ".join(k.ljust(width[k]) for k in ("name", "family", "source", "status")) + "  reference"
    print(header)
    print("-" * len(header))
    for row in rows:
        cells = "  ".join(str(getattr(row, k)).ljust(width[k]) for k in ("name", "family", "source", "status"))
        print(f"{cells}  {row.reference}")
    for warning in caught:
        print(f"warning: {warning.message}", file=sys.stderr)
    return 0


def _default_scene(args: argparse.Namespace) -> int:
    from .scene_file import default_scene_text

    print(default_scene_text(), end="")
    return 0


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``camcontact`` console script."""
    parser = argparse.ArgumentParser(prog="camcontact", description="Lubricated contacts of machine elements.")
    parser.add_argument("--version", action="version", version=f"camcontact {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser("run", help="run a scene file (default: the embedded default scene)")
    run.add_argument("scene", nargs="?", help="scene TOML file")
    run.add_argument("--csv", help="where to write the report (default: <scene>_report.csv)")
    run.add_argument("--units", nargs="*", metavar="NAME=UNIT", help="display units, e.g. h_min=nm p_h=GPa")
    run.add_argument("--plot", metavar="PNG", help="also save a plot of the result")
    run.set_defaults(handler=_run)
    sweep = commands.add_parser("sweep", help="run a scene file over its [sweep] table into one table")
    sweep.add_argument("scene", help="scene TOML file with a [sweep] table")
    sweep.add_argument("--workers", type=int, default=0, help="worker processes (default 0: serial, here)")
    sweep.add_argument("--csv", help="where to write the table (default: <scene>_sweep.csv)")
    sweep.add_argument("--parquet", help="also write the table as Parquet (needs the [parquet] extra)")
    sweep.add_argument("--table", choices=("auto", "cases", "index"), default="auto",
                       help="rows per case, or per case and cam angle/roller (default: auto)")
    sweep.add_argument("--no-progress", action="store_true", help="no progress bar")
    sweep.set_defaults(handler=_sweep)
    plugins = commands.add_parser("plugins", help="list the models of the plugin registry")
    plugins.add_argument("--family", help="only this family")
    plugins.set_defaults(handler=_plugins)
    default = commands.add_parser("default-scene", help="print the embedded default scene (a template)")
    default.set_defaults(handler=_default_scene)
    args = parser.parse_args(argv)
    try:
        return args.handler(args)
    except InputError as exc:
        print(f"camcontact: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
