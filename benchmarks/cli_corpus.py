"""Run the bad scene / CLI corpus (tests/cli_corpus.py) in child processes and print its counts.

Every case runs as ``python -m camcontact ...`` in its own temporary directory with a time bound and is
classified by what it did wrong (a case can count in several columns):

``tracebacks``
    "Traceback" on stderr or stdout;
``hangs``
    no exit within ``--timeout`` seconds (the child is killed);
``zero exits``
    exit status 0 where an error was due;
``wrong status``
    another status than the case's (2 bad input, 1 failure while running, 141 stdout closed);
``multi-line errors``
    not exactly one ``camcontact: error: ...`` line on stderr (none after a closed stdout).

The marker scenes (code that would create a file, in every string slot) run too with ``--markers``; the
marker file must not exist afterwards. The tests (tests/unit/test_cli_corpus.py) run the same corpus
mostly in-process::

    python benchmarks/cli_corpus.py                  # the corpus, 2 at a time
    python benchmarks/cli_corpus.py --markers --jobs 4
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

import cli_corpus

COLUMNS = ("tracebacks", "hangs", "zero exits", "wrong status", "multi-line errors")


def classify(case: cli_corpus.Case, outcome: cli_corpus.Outcome) -> set[str]:
    """The columns ``outcome`` counts in."""
    found = set()
    if outcome.status is None:
        return {"hangs"}
    if "Traceback" in outcome.stderr or "Traceback" in outcome.stdout:
        found.add("tracebacks")
    if outcome.status == 0 and case.status != 0:
        found.add("zero exits")
    if outcome.status != case.status:
        found.add("wrong status")
    if any(not problem.startswith(("exit status", "traceback")) for problem in cli_corpus.problems(case, outcome)):
        found.add("multi-line errors")
    return found


def run_one(case: cli_corpus.Case, timeout: float, marker: str | None) -> tuple[cli_corpus.Case, cli_corpus.Outcome, set[str]]:
    """One case in a fresh temporary directory (the marker, if any, is looked for there)."""
    with tempfile.TemporaryDirectory(prefix="camcontact-corpus-") as tmp:
        outcome = cli_corpus.run_subprocess(case, Path(tmp), timeout=timeout)
        found = classify(case, outcome)
        if marker is not None and (Path(tmp) / marker).exists():
            found.add("marker created")
    return case, outcome, found


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--timeout", type=float, default=60.0, help="time bound per case [s] (default 60)")
    parser.add_argument("--jobs", type=int, default=2, help="cases run at once (default 2)")
    parser.add_argument("--markers", action="store_true", help="also the marker scenes (code in every string slot)")
    parser.add_argument("--verbose", action="store_true", help="print every case's stderr line")
    args = parser.parse_args(argv)

    marker = "MARKER"
    jobs = [(case, None) for case in cli_corpus.CASES]
    if args.markers:
        jobs += [(case, marker) for case in cli_corpus.marker_cases(marker)]
    counts = dict.fromkeys(COLUMNS + ("marker created",), 0)
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for case, outcome, found in pool.map(lambda job: run_one(job[0], args.timeout, job[1]), jobs):
            for column in found:
                counts[column] += 1
            line = outcome.stderr.strip().splitlines()[:1]
            if found or args.verbose:
                status = "hang" if outcome.status is None else outcome.status
                print(f"{'BAD ' if found else 'ok  '}{case.name} [{status}, {outcome.seconds:.1f} s] "
                      f"{sorted(found) if found else ''} {line[0][:160] if line else ''}")
    print(f"cases: {len(jobs)} ({len(cli_corpus.CASES)} corpus"
          + (f" + {len(jobs) - len(cli_corpus.CASES)} marker" if args.markers else "") + ")")
    for column, count in counts.items():
        if column != "marker created" or args.markers:
            print(f"{column}: {count}")
    return 1 if any(counts.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
