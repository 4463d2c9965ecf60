"""The thermal / non-Newtonian line solver with a starved inlet (ThermalLineContact.oil_layer): the meniscus search
of camcontact.ehl.line_starved over thermal solves of the reduced domain.

Checks: in the isothermal Newtonian limit it is the isothermal starved solver's solution (same meniscus, same film);
a layer the thermal flooded film cannot pass leaves it flooded; a thinner one passes whole, its flux constant
through the film and equal to the supply, the central film set by it (no side flow in a line contact); the
lubricant arriving at the meniscus carries less heat into the Hertz zone's film, so that the thermal film reduction
shrinks and the traction rises against the flooded film's. Steel rollers in mineral oil, 200 kN/m (p_h 0.85 GPa),
u_m 5 m/s, Eyring stress 5 MPa, level 6."""

import attrs
import numpy as np
import pytest

from camcontact.ehl.line_starved import solve_starved, wet_flux
from camcontact.ehl.line_thermal import ThermalLineContact, solve_thermal
from camcontact.errors import InputError

LEVEL = 6


def _contact(S=0.0, **changes):
    u_m = 5.0
    data = dict(R=0.01, w=2e5, E_reduced=2.26e11, u1=u_m * (1 + S / 2), u2=u_m * (1 - S / 2), eta0=0.04, alpha=2e-8,
                beta=0.03, conductivity=0.14, heat_capacity=1.74e6, effusivity_1=12900.0, effusivity_2=12900.0,
                eyring_stress=5e6)
    data.update(changes)
    return ThermalLineContact(**data)


@pytest.fixture(scope="module")
def flooded():
    return solve_thermal(_contact(S=1.0), LEVEL)


def test_oil_layer_is_checked_at_the_door():
    with pytest.raises(InputError, match="oil_layer"):
        _contact(oil_layer=-1e-7)
    assert _contact().supply is None
    contact = _contact(oil_layer=4e-7)  # H_oil = h_oil R/b^2, b^2 = 8 w R/(pi E')
    assert contact.supply == pytest.approx(4e-7 * 0.01 / (8 * 2e5 * 0.01 / (np.pi * 2.26e11)), rel=1e-14)


def test_the_isothermal_newtonian_limit_is_the_isothermal_starved_solution():
    """thermal=False, Newtonian: every trial is the isothermal flooded solve of its reduced domain, so the meniscus
    and film are solve_starved's (its meniscus search is the same function) to the flux target 1e-6."""
    contact = _contact(oil_layer=4e-7, eyring_stress=None)
    solution = solve_thermal(contact, 7, thermal=False, non_newtonian=False, output_tolerance=1e-6)
    reference = solve_starved(attrs.evolve(contact.problem(), cavitation="mass_conserving", supply=contact.supply), 7,
                              tolerance=1e-7)
    assert solution.record.converged and solution.meniscus is not None
    assert solution.isothermal.record.message == reference.record.message  # the starved isothermal solve it carries
    tail = reference.X.size - solution.ehl.X.size  # the reference continues its grid upstream of its meniscus
    np.testing.assert_allclose(solution.ehl.X, reference.X[tail:], atol=1e-6)  # measured 7e-8
    np.testing.assert_allclose(solution.ehl.H, reference.H[tail:], rtol=1e-5)  # measured 2.0e-6
    np.testing.assert_allclose(solution.ehl.P, reference.P[tail:], atol=1e-5)  # measured 6.9e-7
    assert solution.film_reduction == pytest.approx(1.0, abs=1e-5)


def test_a_layer_the_thermal_film_cannot_pass_leaves_it_flooded(flooded):
    layer = 2.0 * flooded.h_c  # the flux is about c rho_c h_c, c rho_c ~ 1.25 here: a layer of 2 h_c is more
    solution = solve_thermal(_contact(S=1.0, oil_layer=layer), LEVEL)
    assert solution.meniscus is None and solution.record.message.startswith("flooded: supply")
    assert solution.h_c == flooded.h_c and solution.traction_coefficient == flooded.traction_coefficient
    assert solution.isothermal.H_c == flooded.isothermal.H_c  # the isothermal contact is flooded too


@pytest.mark.parametrize("fraction", [0.8, 0.4])
def test_a_thin_layer_passes_whole_and_cools_the_film(flooded, fraction):
    """Mass conservation: the thermal film's flux (with its flow and Couette factors) is the same through every face
    of the pressurised film and equals the supply to the meniscus target; at the centre, where the pressure is
    nearly flat, c rho H carries it (measured within 1e-3). Less lubricant in the inlet, less heated backflow: the
    film is nearly the isothermal starved one (reduction 0.975 at 0.8, 0.963 at 0.4; flooded 0.886) and, thinner
    and cooler, shears harder (traction 0.037 and 0.047; flooded 0.029)."""
    contact = _contact(S=1.0, oil_layer=fraction * flooded.h_c)
    solution = solve_thermal(contact, LEVEL)
    ehl = solution.ehl
    assert solution.record.converged and solution.thermal and solution.cross_film
    assert solution.meniscus == pytest.approx(ehl.X[0] * solution.scales["b"], rel=1e-12)
    assert -1.6 < ehl.X[0] < -1.0  # between the flooded inlet and the Hertz edge
    assert abs(wet_flux(ehl) / contact.supply - 1.0) <= 1e-4
    faces = np.flatnonzero((ehl.P[:-1] > 0.0) & (ehl.P[1:] > 0.0))
    flux = ehl.mass_flux[faces]
    assert np.ptp(flux) < 3e-5 * flux.max()  # measured 1.1e-5: the multigrid tolerance
    centre = int(np.argmin(np.abs(ehl.X)))
    carried = ehl.couette_factor[centre] * ehl.problem.density_ratio(ehl.P[centre]) * ehl.H[centre]
    assert carried == pytest.approx(contact.supply, rel=2e-3)
    assert flooded.film_reduction < solution.film_reduction < 1.0
    assert solution.traction_coefficient > 1.2 * flooded.traction_coefficient
    assert solution.max_temperature_rise < flooded.max_temperature_rise
    # its isothermal reference is the isothermal starved contact of the same layer
    assert solution.isothermal.problem.supply == contact.supply
