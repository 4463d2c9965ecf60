"""What the thermal and non-Newtonian line EHL costs, rung by rung: isothermal Newtonian solve -> thermal formula
factors -> full thermal Eyring solve, for the film and the traction.

The contact: steel rollers, R = 10 mm, w = 200 kN/m (p_h = 0.85 GPa), E' = 226 GPa, u_m = 5 m/s, mineral oil
eta0 = 0.04 Pa s, alpha = 20/GPa, beta = 0.03/K, k = 0.14 W/(m K), rho c = 1.74 MJ/(m^3 K), Eyring stress 5 MPa;
slide-to-roll ratios S = 0, 0.1, 0.25, 0.5, 1 (quick: 0, 0.5, 1). Per S and grid level (medians of ``--repeats`` runs):

* ``isothermal``: :func:`camcontact.ehl.line_multigrid.solve_multigrid` and the lumped isothermal Eyring traction
  over its pressure and film (:func:`camcontact.contact.fluid_traction.fluid_traction`);
* ``formula``: the same films times the inlet shear-heating factors of Murch & Wilson, Wilson & Sheu and Gupta et
  al. (Zhu & Cheng) (:mod:`camcontact.models.film_thermal`) and the lumped thermal Eyring traction (Hertz pressure,
  flash and film temperature) — the cost of the isothermal solve plus the formulas;
* ``thermal``: :func:`camcontact.ehl.line_thermal.solve_thermal` (energy equation, Eyring film): films, traction,
  temperature, iterations, and its time over the isothermal solve's (the issue's target: <= 10 at level 10);
* ``thermal starved``: the same with a starved inlet, an oil layer of half the thermal flooded central film
  (``ThermalLineContact.oil_layer``; its h_c / iso against the isothermal starved film of the same layer);
* ``thermal expanding``: the flooded thermal solve with the compression work and thermal expansion of an oil of
  expansivity 6.5e-4 1/K entering at 353 K (``ThermalLineContact.thermal_expansivity``).

    python benchmarks/thermal_ehl_cost.py            # levels 8 and 10, 3 repeats
    python benchmarks/thermal_ehl_cost.py --quick    # level 6, one repeat (the tests run this)

Writes ``thermal_ehl_cost.csv`` and ``thermal_ehl_cost.png`` into ``--out``. Timings are reported, never asserted.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import attrs
import numpy as np
import pandas as pd

from camcontact.contact.fluid_traction import TractionThermal, fluid_traction
from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_thermal import ThermalLineContact, solve_thermal
from camcontact.errors import ConvergenceWarning
from camcontact.models.film_thermal import thermal_reduction

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the shared benchmarks/_output.py
from _output import arguments, timed, write_results  # noqa: E402

SLIDE_ROLL = (0.0, 0.1, 0.25, 0.5, 1.0)
QUICK_SLIDE_ROLL = (0.0, 0.5, 1.0)
TAU0 = 5e6
FACTORS = {"murch_wilson": "MW", "wilson_sheu": "WS", "zhu_cheng": "ZC"}
#: the starved rung's oil layer, a fraction of the thermal flooded central film
STARVED_LAYER = 0.5
#: the expanding rung's expansivity [1/K] and inlet temperature [K]
EXPANSIVITY, INLET_TEMPERATURE = 6.5e-4, 353.0


def contact(S: float) -> ThermalLineContact:
    u_m = 5.0
    return ThermalLineContact(R=0.01, w=2e5, E_reduced=2.26e11, u1=u_m * (1 + S / 2), u2=u_m * (1 - S / 2), eta0=0.04,
                              alpha=2e-8, beta=0.03, conductivity=0.14, heat_capacity=1.74e6, effusivity_1=12900.0,
                              effusivity_2=12900.0, eyring_stress=TAU0)


def lumped(c: ThermalLineContact, h_c: float, profile=None, thermal: bool = False) -> float:
    """The lumped Eyring traction coefficient of ``c`` with the central film h_c [m]."""
    problem = c.problem()
    scales = problem.scales(c.R, c.w, c.E_reduced)
    options = dict(entrainment_speed=c.u_m, half_width=scales["b"],
                   thermal=TractionThermal(c.conductivity, c.beta, c.effusivity_1, c.effusivity_2)) if thermal else {}
    result = fluid_traction(c.sliding_speed, p_h=scales["p_h"], film_thickness=h_c, eta0=c.eta0,
                            log_viscosity_ratio=lambda p: problem.log_viscosity(np.asarray(p) / scales["p_h"]),
                            rheology="eyring", eyring_stress=TAU0, profile=profile, **options)
    return float(result.coefficient)


def rows_of(S: float, level: int, repeats: int) -> list[dict]:
    c = contact(S)
    problem = c.problem()
    h_scale = problem.scales(c.R, c.w, c.E_reduced)["h_scale"]

    def isothermal():
        solution = solve_multigrid(problem, level)
        return solution, lumped(c, solution.H_c * h_scale, solution.traction_profile())

    (iso, mu_iso), t_iso = timed(isothermal, repeats)
    h_c, h_min = iso.H_c * h_scale, iso.H_min * h_scale
    base = {"S [-]": S, "level": level, "nodes": iso.X.size}
    rows = [base | {"rung": "isothermal", "h_c [nm]": 1e9 * h_c, "h_min [nm]": 1e9 * h_min, "h_c / iso [-]": 1.0,
                    "traction [-]": mu_iso, "time [s]": t_iso, "time / isothermal [-]": 1.0}]

    def formula():
        p_h = problem.p_h
        factors = {short: thermal_reduction(method, c.beta, c.eta0, c.u1, c.u2, c.conductivity, p_h=p_h,
                                            E_reduced=c.E_reduced)[1] for method, short in FACTORS.items()}
        return factors, lumped(c, factors["WS"] * h_c, thermal=S > 0)

    (factors, mu_formula), t_formula = timed(formula, repeats)
    rows.append(base | {"rung": "formula", "h_c [nm]": 1e9 * factors["WS"] * h_c,
                        "h_min [nm]": 1e9 * factors["WS"] * h_min, "h_c / iso [-]": factors["WS"],
                        **{f"h_c / iso {short} [-]": value for short, value in factors.items()},
                        "traction [-]": mu_formula, "time [s]": t_iso + t_formula,
                        "time / isothermal [-]": (t_iso + t_formula) / t_iso})
    def thermal_row(rung: str, solution, seconds: float, **extra) -> dict:
        """The row of a thermal solve (its films, traction, film temperature, convergence and time)."""
        return base | {"rung": rung, **extra, "h_c [nm]": 1e9 * solution.h_c, "h_min [nm]": 1e9 * solution.h_min,
                       "h_c / iso [-]": solution.film_reduction, "traction [-]": solution.traction_coefficient,
                       "max film rise [K]": solution.max_temperature_rise, "converged": solution.record.converged,
                       "time [s]": seconds, "time / isothermal [-]": seconds / t_iso}

    thermal, t_thermal = timed(lambda: solve_thermal(c, level), repeats)
    rows.append(thermal_row("thermal", thermal, t_thermal, iterations=thermal.record.cycles))
    layer = STARVED_LAYER * thermal.h_c
    starved, t_starved = timed(lambda: solve_thermal(attrs.evolve(c, oil_layer=layer), level), repeats)
    rows.append(thermal_row("thermal starved", starved, t_starved, **{"layer [nm]": 1e9 * layer}))
    expanding_contact = attrs.evolve(c, thermal_expansivity=EXPANSIVITY, temperature=INLET_TEMPERATURE)
    expanding, t_expanding = timed(lambda: solve_thermal(expanding_contact, level), repeats)
    rows.append(thermal_row("thermal expanding", expanding, t_expanding, iterations=expanding.record.cycles))
    return rows


def plot(frame: pd.DataFrame, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    finest = frame[frame["level"] == frame["level"].max()]
    fig, (films, traction) = plt.subplots(1, 2, figsize=(10, 4))
    thermal = finest[finest["rung"] == "thermal"]
    films.plot(thermal["S [-]"], thermal["h_c / iso [-]"], "o-", label="thermal solver")
    expanding = finest[finest["rung"] == "thermal expanding"]
    films.plot(expanding["S [-]"], expanding["h_c / iso [-]"], "d-", label="thermal solver, compression work")
    formula = finest[finest["rung"] == "formula"]
    names = (("MW", "Murch & Wilson (rolling)"), ("WS", "Wilson & Sheu"), ("ZC", "Gupta et al. (Zhu & Cheng)"))
    for short, name in names:
        films.plot(formula["S [-]"], formula[f"h_c / iso {short} [-]"], "s--", label=name)
    films.set(xlabel="slide-to-roll ratio S", ylabel="h_c / h_c isothermal", title="Thermal film reduction")
    films.legend(fontsize=8)
    for rung, style in (("isothermal", "^:"), ("formula", "s--"), ("thermal", "o-"), ("thermal starved", "v-."),
                        ("thermal expanding", "d-")):
        part = finest[finest["rung"] == rung]
        traction.plot(part["S [-]"], part["traction [-]"], style, label=f"{rung} ({part['time [s]'].median():.2f} s)")
    traction.set(xlabel="slide-to-roll ratio S", ylabel="traction coefficient", title="Eyring traction (5 MPa)")
    traction.legend(fontsize=8)
    fig.suptitle(f"Roller contact, p_h 0.85 GPa, u_m 5 m/s, level {int(finest['level'].iloc[0])}")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def summary(frame: pd.DataFrame) -> pd.DataFrame:
    columns = ["S [-]", "level", "rung", "h_c [nm]", "h_min [nm]", "h_c / iso [-]", "traction [-]", "time [s]",
               "time / isothermal [-]"]
    return frame[columns]


def main(argv=None) -> pd.DataFrame:
    args = arguments(__doc__, "level 6, one repeat", argv)
    levels = (6,) if args.quick else (8, 10)
    repeats = 1 if args.quick else args.repeats
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        ratios = QUICK_SLIDE_ROLL if args.quick else SLIDE_ROLL
        rows = [row for level in levels for S in ratios for row in rows_of(S, level, repeats)]
    return write_results(pd.DataFrame(rows), args.out, "thermal_ehl_cost", plot, summary)


if __name__ == "__main__":
    main()
