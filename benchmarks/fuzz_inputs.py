"""Fuzz the door: every field of every public component with bad values — what escapes, what is named.

Each probe sets one field of a valid component (from the built-in default scene and the tutorials' scene
files, and every component inside them) to one value with ``attrs.evolve`` and classifies the outcome:

``accepted``
    the component was built (the value is valid, or converted);
``named``
    an :class:`~camcontact.errors.InputError` naming the class and the field (``Class.field``, or the class and
    the field's name, as the checks across fields say ``Follower 'f': pin_radius = ... must be smaller than
    roller_radius``);
``unnamed``
    an InputError that does not name the field;
``leak``
    any other exception (ValueError, TypeError, OverflowError, ...);
``hang``
    the probe ran past its time bound (``--timeout``, default 2 s; SIGALRM).

With ``--reports`` every *accepted* probe of a field of a scene (the line contact, raceway, bearing and
CVT scenes of the tutorials, through their nested components) is also run by an Analysis, and its report
is checked: every NaN or infinite number must have its reason beside it
(:func:`camcontact.report.unexplained_values`); outcomes ``reported`` (clean), ``unflagged``, ``leak``
(an exception out of ``run()``, which isolates step failures) and ``hang``. The cam scene is left out
for its cost (a second per run); its failure isolation is tested on its own.

The values are a fixed corpus of known-bad inputs (units alone, expressions, huge powers, arrays for
scalars, strings for booleans, wrong types, NaN/inf, out-of-range numbers) and, with hypothesis, drawn
text, numbers, units and containers. A hypothesis property test (tests/unit/test_fuzz_inputs.py) runs a
bounded number of probes in CI; this script runs the long version and prints its counts::

    python benchmarks/fuzz_inputs.py                 # corpus x every field + 5000 hypothesis probes
    python benchmarks/fuzz_inputs.py --quick         # corpus only
    python benchmarks/fuzz_inputs.py --reports       # and run the accepted probes of the scenes (corpus and
                                                     # as many hypothesis probes), checking their reports
"""

from __future__ import annotations

import argparse
import collections
import math
import re
import signal
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import attrs
import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SCENE_FILES = ("pellet_mill_bearing.toml", "pellet_mill_line_contact.toml", "pellet_mill_raceway_contact.toml",
               "forti_ball_cone_cvt.toml")
OUTCOMES = ("accepted", "named", "unnamed", "leak", "hang")


class ProbeTimeout(BaseException):
    """A probe ran past its time bound (a BaseException, so no ``except Exception`` swallows it)."""


def components() -> dict[str, Any]:
    """One valid instance of every component class reachable from the default scene and the tutorials' scene
    files (keyed by class name; the first found)."""
    from camcontact.scene_file import load_scene

    roots = [load_scene().component] + [load_scene(ROOT / "tutorials" / name).component for name in SCENE_FILES]
    found: dict[str, Any] = {}

    def visit(value):
        if attrs.has(type(value)) and type(value).__module__.startswith("camcontact.components"):
            found.setdefault(type(value).__name__, value)
            for field in attrs.fields(type(value)):
                visit(getattr(value, field.name))

    for root in roots:
        visit(root)
    return found


def corpus() -> list[Any]:
    """Known-bad (and some borderline) inputs of every kind."""
    from camcontact.units import Q_

    return [None, True, False, "false", "true", "", " ", "mm", "kN", "deg", "(10**400) N", "(10**10**8) N",
            "10**8 mm", "1e400 N", "-1e400 mm", "nan mm", "inf mm", "5 mm mm", "5 furlong", "5 parsec", "5",
            "abc", "5 mm; import os", "__import__('os')", "5 m**(10**10)", "5 m^1000", "5 degC", "-300 degC",
            "1/0 mm", "0x10 mm", "1_000 mm", "5e-400 mm", 0, -1, 1, 3, 0.5, 1e308, -1e308, 10**400, 2**64,
            float("nan"), float("inf"), -0.0, np.float64(2.0), np.int64(3), [1, 2], (5, "mm"), (5, "parsec"),
            ("5", "mm"), (float("nan"), "mm"), {}, {"a": 1}, object(), b"5 mm", Q_([3.0, 4.0], "kN"),
            Q_([3.0, 4.0], "mm"), Q_(5.0, "kg"), Q_(5.0, "mm"), Q_(-5.0, "mm"), Q_(5.0, ""), Q_(90.0, "deg"),
            Q_(float("nan"), "mm"), np.array([1.0, 2.0]), np.array(3.0), "flat-faced", "roller", "ester",
            "gold", "reduction", "thesis", 1j, math.pi]


def probe(component: Any, field: str, value: Any, timeout: float) -> tuple[str, str]:
    """(outcome, message) of setting ``field`` of ``component`` to ``value``."""
    from camcontact.errors import InputError

    def alarm(signum, frame):
        raise ProbeTimeout

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, timeout)
    try:
        attrs.evolve(component, **{field: value})
        return "accepted", ""
    except ProbeTimeout:
        return "hang", f"over {timeout} s"
    except InputError as error:
        text = str(error)
        cls = type(component).__name__
        named = f"{cls}.{field}" in text or (cls in text and re.search(rf"\b{field}\b", text) is not None)
        return ("named" if named else "unnamed"), text
    except Exception as error:  # noqa: BLE001 — what the fuzz looks for
        return "leak", f"{type(error).__name__}: {error}"
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, previous)


REPORT_SCENES = ("pellet_mill_line_contact.toml", "pellet_mill_raceway_contact.toml", "pellet_mill_bearing.toml",
                 "forti_ball_cone_cvt.toml")
REPORT_OUTCOMES = ("reported", "unflagged", "leak", "hang")


def scene_paths(component: Any, prefix: str = "") -> Iterator[str]:
    """Dotted paths of every field of a scene component and of the components inside it."""
    for field in attrs.fields(type(component)):
        if not field.init:
            continue
        path = prefix + field.name
        yield path
        value = getattr(component, field.name)
        if attrs.has(type(value)) and type(value).__module__.startswith("camcontact.components"):
            yield from scene_paths(value, path + ".")


def report_probe(scene: Any, path: str, value: Any, timeout: float) -> tuple[str, str]:
    """(outcome, message) of running the scene with ``value`` at ``path`` (None when the value is refused at
    the door: the corpus probes count those) and checking its report for unexplained NaN/inf."""
    import warnings

    from camcontact import Analysis
    from camcontact.errors import InputError
    from camcontact.report import unexplained_values
    from camcontact.sweep_cases import evolve_path

    try:
        case = evolve_path(scene, path, value)
    except Exception:  # noqa: BLE001 — refused at the door: the corpus probes classify it
        return "refused", ""

    def alarm(signum, frame):
        raise ProbeTimeout

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, timeout)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = Analysis(case).run()
            frames = [result.to_frame()] + ([result.summary_frame()] if result.index is not None else [])
        bad = [f"{column} row {row}" for frame in frames for row, column in unexplained_values(frame)]
        return ("unflagged", "; ".join(bad[:4])) if bad else ("reported", "")
    except ProbeTimeout:
        return "hang", f"over {timeout} s"
    except InputError as error:  # the scene refused it when planning (outputs it cannot give, a missing input)
        return "reported", f"refused when planned: {error}"
    except Exception as error:  # noqa: BLE001 — what the fuzz looks for
        return "leak", f"{type(error).__name__}: {error}"
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, previous)


def report_counts(values: list[Any], timeout: float, scenes=REPORT_SCENES) -> tuple[collections.Counter, list]:
    """Every value at every path of the report scenes; the accepted ones run and checked."""
    from camcontact.scene_file import load_scene

    counts: collections.Counter = collections.Counter()
    bad = []
    for name in scenes:
        scene = load_scene(ROOT / "tutorials" / name).component
        for path in scene_paths(scene):
            for value in values:
                outcome, message = report_probe(scene, path, value, timeout)
                if outcome == "refused":
                    continue
                counts[outcome] += 1
                if outcome != "reported":
                    bad.append((outcome, f"{name}:{path}", repr(value)[:60], message[:200]))
    return counts, bad


def report_hypothesis_counts(probes: int, timeout: float, seed: int = 0, scenes=REPORT_SCENES):
    """``probes`` hypothesis probes (scene, path, drawn value); the accepted ones run and checked."""
    from hypothesis import HealthCheck, given, seed as fix_seed, settings
    from hypothesis import strategies as st

    from camcontact.scene_file import load_scene

    loaded = {name: load_scene(ROOT / "tutorials" / name).component for name in scenes}
    targets = [(name, path) for name, scene in loaded.items() for path in scene_paths(scene)]
    counts: collections.Counter = collections.Counter()
    bad: list[tuple] = []

    @fix_seed(seed)
    @settings(max_examples=probes, deadline=None, database=None, suppress_health_check=list(HealthCheck))
    @given(st.sampled_from(targets), values())
    def run_one(target, value):
        name, path = target
        outcome, message = report_probe(loaded[name], path, value, timeout)
        counts[outcome] += 1
        if outcome not in ("reported", "refused"):
            bad.append((outcome, f"{name}:{path}", repr(value)[:60], message[:200]))

    run_one()
    return counts, bad


def fields_of(instance: Any) -> list[str]:
    return [f.name for f in attrs.fields(type(instance)) if f.init]


def corpus_probes(found: dict[str, Any]) -> Iterator[tuple[str, str, Any]]:
    for name, instance in found.items():
        for field in fields_of(instance):
            for value in corpus():
                yield name, field, value


def run(probes, found, timeout: float) -> tuple[collections.Counter, list[tuple]]:
    counts: collections.Counter = collections.Counter()
    bad = []
    for name, field, value in probes:
        outcome, message = probe(found[name], field, value, timeout)
        counts[outcome] += 1
        if outcome in ("unnamed", "leak", "hang"):
            bad.append((outcome, f"{name}.{field}", repr(value)[:60], message[:160]))
    return counts, bad


def values():
    """The hypothesis strategy of bad (and good) values: the corpus, text (free and number-then-unit), numbers of
    every size, booleans, None, containers and quantities of drawn magnitudes and units."""
    from hypothesis import strategies as st

    from camcontact.units import Q_

    units = st.sampled_from(["mm", "m", "um", "N", "kN", "GPa", "MPa", "Pa", "1/GPa", "degC", "K", "deg", "rad", "rpm",
                             "cSt", "Pa*s", "kg/m^3", "W/(m*K)", "J/(kg*K)", "m/s", "kg", "", "furlong", "N/m",
                             "kg*m^2", "1/m^2", "W", "m^1000", "**8", "(10**400)", "fortnight"])
    numbers = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**30, 10**30),
                        st.integers(10**300, 10**400))
    return st.one_of(
        st.sampled_from(corpus()), numbers, st.booleans(), st.none(), st.text(max_size=24),
        st.builds(lambda x, u: f"{x!r} {u}", numbers, units), st.tuples(numbers, units),
        st.builds(lambda x, u: Q_(x, u), st.floats(-1e12, 1e12), units.filter(lambda u: u not in ("m^1000", "**8",
                                                                                                 "(10**400)"))),
        st.lists(numbers, max_size=3), st.dictionaries(st.text(max_size=3), numbers, max_size=2))


def hypothesis_counts(found: dict[str, Any], probes: int, timeout: float, seed: int = 0):
    """``probes`` hypothesis probes (component, field, value) classified: (counts, failures)."""
    from hypothesis import HealthCheck, given, seed as fix_seed, settings
    from hypothesis import strategies as st

    counts: collections.Counter = collections.Counter()
    bad: list[tuple] = []
    targets = [(name, field) for name, instance in found.items() for field in fields_of(instance)]

    @fix_seed(seed)
    @settings(max_examples=probes, deadline=None, database=None, derandomize=False,
              suppress_health_check=list(HealthCheck))
    @given(st.sampled_from(targets), values())
    def run_one(target, value):
        name, field = target
        outcome, message = probe(found[name], field, value, timeout)
        counts[outcome] += 1
        if outcome in ("unnamed", "leak", "hang"):
            bad.append((outcome, f"{name}.{field}", repr(value)[:60], message[:160]))

    run_one()
    return counts, bad


def main(argv: list[str] | None = None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the corpus only")
    parser.add_argument("--timeout", type=float, default=2.0, help="time bound of one probe [s]")
    parser.add_argument("--show", type=int, default=40, help="failures to print")
    parser.add_argument("--probes", type=int, default=5000, help="hypothesis probes (beyond the corpus)")
    parser.add_argument("--seed", type=int, default=0, help="hypothesis seed")
    parser.add_argument("--reports", action="store_true",
                        help="also run the accepted corpus probes of the scenes and check their reports")
    parser.add_argument("--report-timeout", type=float, default=60.0, help="time bound of one scene run [s]")
    args = parser.parse_args(argv)
    found = components()
    counts, bad = run(corpus_probes(found), found, args.timeout)
    if not args.quick:
        drawn, more = hypothesis_counts(found, args.probes, args.timeout, args.seed)
        print(f"{sum(drawn.values())} hypothesis probes: " + ", ".join(f"{k} {drawn[k]}" for k in OUTCOMES))
        counts, bad = counts + drawn, bad + more
    print(f"{sum(counts.values())} probes over {len(found)} components "
          f"({sum(len(fields_of(i)) for i in found.values())} fields): "
          + ", ".join(f"{k} {counts[k]}" for k in OUTCOMES))
    if args.reports:
        ran, unflagged = report_counts(corpus(), args.report_timeout)
        print(f"{sum(ran.values())} accepted corpus probes run as scenes: "
              + ", ".join(f"{k} {ran[k]}" for k in REPORT_OUTCOMES))
        counts, bad = counts + ran, bad + unflagged
        if not args.quick:
            drawn, more = report_hypothesis_counts(args.probes, args.report_timeout, args.seed)
            print(f"{sum(drawn.values())} hypothesis probes of the scenes' fields ({drawn['refused']} refused at the "
                  f"door): " + ", ".join(f"{k} {drawn[k]}" for k in REPORT_OUTCOMES))
            drawn.pop("refused", None)
            counts, bad = counts + drawn, bad + more
    for row in bad[:args.show]:
        print("  ", *row)
    return counts, bad


if __name__ == "__main__":
    main()
    sys.exit(0)
