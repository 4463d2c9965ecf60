"""Numerical film of a point (elliptical) contact: the FAS multigrid point-contact solver as a film model.

Registered as ``multigrid_point`` in the ``film_models`` family (geometry ``"point"``); scenes with
point contacts (the ball-cone CVT) take the name ``"multigrid"`` in their film slot to mean this
model. Accuracy is chosen by ``levels`` (16 2^(levels-1) + 1 nodes per direction: 4 = 129^2,
5 = 257^2) and ``tolerance``; the solver, its validity and its convergence record are in
:mod:`camcontact.ehl.point_multigrid`.
"""

from __future__ import annotations

import attrs

from .base import FilmModel, builtin
from .film_multigrid import solver_laws
from .film_point import POINT_INPUTS

__all__ = ["MultigridPoint"]


@builtin
@attrs.frozen
class MultigridPoint(FilmModel):
    """Central and minimum film of an elliptical contact from the numerical EHL solution.

    Steady isothermal 2-D Reynolds with cavitation, elastic half-space deformation (FFT),
    load balance through H0, Roelands or Barus viscosity, Dowson–Higginson density or none,
    FAS multigrid; inputs Rx, Ry [m] (entrainment along x), F [N], E' [Pa], u_m [m/s],
    eta0 [Pa*s], alpha [1/Pa] and optionally the lubricant's state and density law.

    Parameters
    ----------
    levels : int
        Finest grid level (4: 129^2, 5: 257^2, 6: 513^2).
    tolerance : float
        Convergence tolerance (relative changes of the films between cycles).
    strict : bool
        Raise ConvergenceError when the solver does not converge (default: warn).

    Validity: measured to converge for Moes M = 10..100, L = 5..25, D = Rx/Ry = 0.25..4, and at
    heavy load (M = 1000, L = 10: 5-9 cycles; M = 3000: 257^2 and 513^2), but the heavy-load film
    needs fine grids: at M = 1000 H_c is 38 % below Nijenbanning on 129^2, 12 % on 257^2 and 5 % on
    513^2; at M = 3000 31 % (257^2) and 11 % (513^2). At M ~ 1e4 the film closes on 257^2 and the
    solve ends in a ConvergenceWarning (ConvergenceError when strict) saying so.

    References
    ----------
    Venner, C.H. & Lubrecht, A.A. (2000) Multilevel Methods in Lubrication, ch. 8;
    Nijenbanning, Venner & Moes (1994) Wear 176:217-229 (the central-film check).
    """

    name = "multigrid_point"
    reference = "Venner & Lubrecht (2000) Multilevel Methods in Lubrication, ch. 8"
    geometry = "point"
    requires = POINT_INPUTS
    optional_requires = ("lubricant_state", "density_law")
    provides = ("h_c", "h_min")
    validity = {"M": (10.0, 100.0), "L": (5.0, 25.0)}

    levels: int = 5
    tolerance: float = 1e-5
    strict: bool = False

    def evaluate(self, Rx, Ry, F, E_reduced, u_m, eta0, alpha, lubricant_state=None, density_law="dowson_higginson"):
        """Films [m] (h_c at the contact centre, h_min) with the solution and its convergence record."""
        from ..ehl.point_multigrid import solve_point_multigrid
        from ..ehl.point_problem import PointEHLProblem

        viscosity, density = solver_laws(self.name, lubricant_state, density_law)
        z = getattr(lubricant_state, "roelands_z", None) if viscosity == "roelands" else None
        problem = PointEHLProblem.from_contact(Rx=float(Rx), Ry=float(Ry), F=float(F), E_reduced=float(E_reduced),
                                               u_m=float(u_m), eta0=float(eta0), alpha=float(alpha), z=z,
                                               viscosity=viscosity, density=density)
        solution = solve_point_multigrid(problem, self.levels, tolerance=self.tolerance, strict=self.strict)
        values = solution.dimensional(float(Rx), float(F), float(E_reduced))
        return {"h_c": values["h_c"], "h_min": values["h_min"], "ehl_solution": solution,
                "convergence": solution.record, "M": problem.M, "L": problem.L}
