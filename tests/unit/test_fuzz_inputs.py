"""Bad inputs at the door (issue 18): every field of every public component, a corpus of known-bad values and
hypothesis-drawn ones — each rejected input an InputError naming the class and the field, nothing else escapes,
nothing hangs (benchmarks/fuzz_inputs.py is the harness; its long run prints the counts)."""

import importlib.util
import math
import time
from pathlib import Path

import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.units import Q_

HARNESS = Path(__file__).resolve().parents[2] / "benchmarks" / "fuzz_inputs.py"


def _harness():
    spec = importlib.util.spec_from_file_location("fuzz_inputs", HARNESS)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def fuzz():
    module = _harness()
    return module, module.components()


def test_the_corpus_over_every_field_is_named(fuzz):
    """About 90 bad values x every field of the 13 components (11 000+ probes): 0 leaks, 0 unnamed, 0 hangs."""
    module, found = fuzz
    assert len(found) == 13
    counts, bad = module.run(module.corpus_probes(found), found, timeout=2.0)
    assert sum(counts.values()) > 10_000 and counts["named"] > 10_000
    assert bad == []


def test_hypothesis_probes_are_named(fuzz):
    """1500 drawn (component, field, value) probes: only accepted or named."""
    module, found = fuzz
    counts, bad = module.hypothesis_counts(found, probes=1500, timeout=2.0, seed=18)
    assert sum(counts.values()) >= 1500 and bad == []


def test_accepted_probes_run_to_reports_without_a_silent_nan(fuzz):
    """Every third corpus value at every field path of the line-contact, raceway, bearing and CVT tutorial
    scenes; the accepted ones run: no exception out of run(), no hang, and every NaN/inf in their reports has
    its reason beside it (the full corpus and hypothesis run: benchmarks/fuzz_inputs.py --reports)."""
    module, _ = fuzz
    counts, bad = module.report_counts(module.corpus()[::3], timeout=60.0)
    assert counts["reported"] > 200 and bad == []


STEEL = cc.Material(E="210 GPa", nu=0.3)


def body(**changes):
    return cc.Body(**({"material": STEEL, "radius": "20 mm"} | changes))


@pytest.mark.parametrize("build, match", [
    (lambda: cc.Follower(kind="flat-faced", material=STEEL), r"Follower.kind = 'flat-faced'; allowed: 'roller', 'flat'"),
    (lambda: cc.Lubricant(eta0="0.04 Pa*s", base_oil="castor"), r"Lubricant.base_oil = 'castor'; allowed"),
    (lambda: cc.Lubricant(eta0="0.04 Pa*s", alpha_correlation="silver"), r"Lubricant.alpha_correlation = 'silver'"),
    (lambda: body(radius="mm"), r"Body.radius = 'mm': cannot read this as a quantity; allowed: a number then a unit"),
    (lambda: body(radius="(10**400) mm"), r"Body.radius = '\(10\*\*400\) mm': cannot read"),
    (lambda: body(radius="5 m^1000"), r"Body.radius = '5 m\^1000': unit 'm\^1000' is not a unit expression"),
    (lambda: body(radius="1e400 mm"), r"Body.radius = inf mm: must be finite"),
    (lambda: body(radius=Q_([3.0, 4.0], "mm")), r"Body.radius = array.*shape \(2,\); allowed: one value"),
    (lambda: body(concave="false"), r"Body.concave = 'false'; allowed: true or false"),
    (lambda: body(name=5), r"Body.name = 5; allowed: a string"),
    (lambda: cc.Material(E="210 GPa", nu=10**400), r"Material.nu = 1000.*too large for a float"),
])
def test_the_issues_examples_are_named(build, match):
    with pytest.raises(InputError, match=match):
        build()


def test_nothing_is_evaluated_and_sizes_are_bounded():
    """pint would evaluate '(10**10**8) N' (hours); the door refuses it at once. A 1e-4 degree step (3.6 million
    angles) is refused before anything is allocated; 10^6 angles is the bound."""
    start = time.perf_counter()
    with pytest.raises(InputError, match="cannot read"):
        body(radius="(10**10**8) N")
    assert time.perf_counter() - start < 1.0
    import attrs

    from camcontact.scene_file import load_scene

    scene = load_scene().component
    with pytest.raises(InputError, match=r"CamFollower.angle_step = 0.0001 deg is out of range"):
        attrs.evolve(scene, angle_step="1e-4 deg")
    assert math.isclose(attrs.evolve(scene, angle_step="0.00036 deg").cam_angles.size, 1_000_000)
