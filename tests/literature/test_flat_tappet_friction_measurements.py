"""The flat-faced follower's friction over the cam turn against the published measurements that give numbers.

No published flat-tappet friction curve with its full inputs (cam, spring, oil, speed) was available to this
project (searched: Staron & Willermet 1983, Willermet & Pieprzak 1989, Dowson, Taylor & Zhu 1992, Teodorescu
et al. 2004, Mufti & Priest 2003, Marian et al. 2019, Orgeldinger & Tremmel 2021 — abstracts or first pages
only). Two measurements print numbers in their abstracts; both are on other cams, oils and speeds than the LS-1,
so they check the *shape* over the turn and the *order of magnitude*, not values:

* Ohmori (Toyota CRDL R&D Review 36(1), direct-acting cam-shim valve train, commercial engine oil): "the
  ramp, shoulder and nose part exhibited frictional coefficients from 0.1 to 0.15 ... only the contact area of
  the flank part showed a low frictional coefficient of around 0.05" — i.e. nose/flank about 2-3.
* Bair, Griffioen & Winer (1986, ASME J. Tribol. 108:478-486): "the loss per revolution ranged from 1.75 J to
  3.9 J for the flat followers".

camcontact (LS-1 flat follower at 1000 rpm, steel, mixed + Eyring + thermal, asperity defaults, mu_b = 0.12)
reproduces the shape at the nose and flanks: boundary/mixed lubrication and mu 0.06-0.08 over the nose (the
entrainment reverses there), full film and mu 0.013-0.04 on the flanks, nose/flank 2-6. It disagrees on the
ramp (Ohmori: high; here the base circle and ramp run at Lambda about 2.4, mu about 0.03) and its nose is
lower than Ohmori's 0.1-0.15 (the Greenwood–Tripp asperity share with the default asperity parameters, an
assumption, not data). The LS-1 dissipates about 20 J per turn, 5-10 x Bair et al.'s 1.75-3.9 J: its contact
force (up to 3.1 kN) and lift (20 mm) are several times an automotive tappet's, so the energy scales up; the
order of magnitude, not the value, is what this comparison can support.
"""

import attrs
import numpy as np
import pytest

import camcontact as cc

EFFECTS = {"elasticity", "piezoviscosity", "compressibility", "mixed", "non_newtonian", "thermal"}


@pytest.fixture(scope="module")
def turn(thermal_steel_ls1):
    flat = attrs.evolve(thermal_steel_ls1, angle_step="2 deg")
    return cc.Analysis(flat, effects=EFFECTS, outputs=["cam_angle", "lift", "friction_coefficient",
                                                       "lubrication_regime", "friction_energy_per_cycle"]).run()


def test_nose_friction_is_boundary_and_a_few_times_the_flanks(turn):
    """Ohmori's measured shape: high friction at the nose, about 0.05 on the flanks (nose/flank 2-3)."""
    lift, mu = np.asarray(turn["lift"]), np.asarray(turn["friction_coefficient"])
    regime = np.asarray(turn["lubrication_regime"])
    nose = lift > 0.7 * lift.max()
    flank = (lift > 0.05 * lift.max()) & (lift < 0.5 * lift.max())
    assert set(regime[nose]) == {"boundary"} and set(regime[flank]) <= {"mixed", "full_film"}
    ratio = np.mean(mu[nose]) / np.mean(mu[flank])
    assert 2.0 <= ratio <= 6.0
    # the magnitudes the test documents (module docstring): the nose below Ohmori's 0.1-0.15
    assert 0.05 < np.mean(mu[nose]) < 0.1 and np.mean(mu[flank]) < 0.05


def test_energy_per_turn_is_of_the_measured_order(turn):
    """Bair et al. 1.75-3.9 J per turn on an automotive flat tappet; the larger LS-1 valve train dissipates
    more, within one order of magnitude of the measured range."""
    assert 1.75 < turn["friction_energy_per_cycle"] < 39.0
