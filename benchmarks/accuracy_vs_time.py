"""What accuracy costs in time: line-contact film formulas versus the multigrid solver.

For each point (M, L) of a grid over the Moes map the script solves the line-contact EHL
problem by FAS multigrid on levels 4..12 (n = 14 2^(k-1) + 1 nodes) and evaluates every line
film formula, then reports the error of the central film H_c and of the minimum film H_min
against a reference: the finest converged multigrid solution, Richardson-extrapolated from the
three finest levels (observed order, clamped to 1..3), and the median wall time of each method.

Films are compared in Moes's scaling H = (h/R)(2U)^-1/2, in which the multigrid result is
(8M/pi) H_Hertz. Formulas other than Moes's need the Hamrock groups separately: they are
evaluated at 2U = 2e-11 (W' = M (2U)^1/2, G = L (2U)^-1/4); their error depends somewhat on that
choice.

    python benchmarks/accuracy_vs_time.py                 # full: M 5..1000 x L 2..20, levels 4..12
    python benchmarks/accuracy_vs_time.py --quick         # 2 x 2 points, levels 4..7 (the tests run this)
    python benchmarks/accuracy_vs_time.py --viscosity barus --density incompressible
    python benchmarks/accuracy_vs_time.py --cam           # the cam cycle: quasi-steady vs transient
    python benchmarks/accuracy_vs_time.py --cam --quick   # 4-degree steps, level 5 (the tests run this)

``--friction`` climbs the friction ladder over the LS-1 flat-follower turn at 1000 rpm — Coulomb, mixed
lubrication with a Newtonian fluid, Eyring isothermal, mixed + Eyring, + thermal (inlet heating and the
traction's contact temperature), and the same with the multigrid film — reporting the cycle-mean friction
power, the energy per turn, the peak coefficient and the cost per angle, into ``accuracy_vs_time_friction.csv``.

    python benchmarks/accuracy_vs_time.py --friction          # 1-degree steps, multigrid level 7
    python benchmarks/accuracy_vs_time.py --friction --quick  # 4-degree steps, level 5 (the tests run this)

``--traction`` climbs the traction ladder of the ball-cone CVT at one operating point (3000 rpm, 150 W, ratio
1.5) — the thesis's constant-Ct check, FASTSIM with the Hertz (thesis) and the parabolic (Kalker) pressure, the
EHL film's Eyring traction with spin isothermal and thermal on the Hertz pressure, both with the asperities'
share (``mixed``: Greenwood–Tripp load sharing, Coulomb asperity friction), and both on the numerical
point-contact pressure — reporting creepage, capacity, margin, losses, efficiency, the asperities' share and
the cost per operating point, into ``accuracy_vs_time_traction.csv``.

    python benchmarks/accuracy_vs_time.py --traction          # numerical pressure on 257^2 (level 5)
    python benchmarks/accuracy_vs_time.py --traction --quick  # 65^2 (level 3), one run each (the tests run this)

``--point`` does the same for circular point contacts: the numerical solution on 65^2 .. 513^2
(levels 3-6; incompressible, Roelands) against the finest level, and the Nijenbanning–Venner–Moes
and Hamrock–Dowson formulas against it, with the wall time of each, into ``accuracy_vs_time_point.csv``.

    python benchmarks/accuracy_vs_time.py --point         # M 10, 20, 50, 100 x L 5, 10; levels 3-6
    python benchmarks/accuracy_vs_time.py --point --quick # M 20 x L 10; levels 3-4 (the tests run this)

``--cam`` measures the LS-1 cam with a flat-faced follower at 1000 rpm (entrainment reversal at the
nose) over one turn in 0.5-degree steps (720 instants): the quasi-steady Pan–Hamrock formula, the
quasi-steady multigrid film at levels 6-8 and the transient multigrid film with the squeeze term
(``effects={"squeeze"}``) at levels 6-8 — the smallest film over the turn, the smallest film within
5 degrees of each reversal, and the wall time of each (median of ``--repeats``) — into
``accuracy_vs_time_cam.csv``.

Writes ``accuracy_vs_time.csv`` (one row per point x method x level; a ``status`` column says
converged / not converged / failed) and ``accuracy_vs_time.png`` (log-log error vs time, the
Pareto front of each method) into ``--out`` (default ``benchmarks/results``).
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import time
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the shared benchmarks/_output.py
from _output import write_results  # noqa: E402

from camcontact import registry
from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem, grid_points
from camcontact.errors import ConvergenceError, ConvergenceWarning

FORMULAS = ("grubin", "dowson_higginson", "dowson_toyoda", "pan_hamrock", "moes")
TWO_U = 2e-11


def richardson(values: list[float]) -> tuple[float, float]:
    """(extrapolated value, observed order) from the three finest of ``values`` (coarse to fine)."""
    a, b, c = values[-3:]
    if b == c:
        return c, float("nan")
    ratio = abs((b - a) / (c - b)) if c != b else 4.0
    order = min(max(math.log2(ratio), 1.0), 3.0) if ratio > 0 else 2.0
    return c + (c - b) / (2.0**order - 1.0), order


def formula_films(M: float, L: float) -> dict[str, tuple[float | None, float | None, float]]:
    """(H_c, H_min) in Moes scaling and the median time [s] of each formula at (M, L)."""
    R, E = 0.01, 2.2e11
    U = 0.5 * TWO_U
    W = M * TWO_U**0.5
    G = L * TWO_U**-0.25
    state = dict(R=R, w=W * E * R, E_reduced=E, u_m=U * E * R / 0.05, eta0=0.05, alpha=G / E)
    results = {}
    for name in FORMULAS:
        model = registry.get("film_models", name)
        if L == 0 and name != "moes":
            continue
        out = model(state)
        scale = 1.0 / (R * TWO_U**0.5)
        calls = 200
        start = time.perf_counter()
        for _ in range(calls):
            model(state)
        seconds = (time.perf_counter() - start) / calls
        results[name] = (out.get("h_c", None) and out["h_c"] * scale, out.get("h_min", None) and out["h_min"] * scale,
                         seconds)
    return results


def run(Ms, Ls, levels, repeats, viscosity, density, progress=True) -> pd.DataFrame:
    rows = []
    points = [(M, L) for M in Ms for L in Ls]
    for index, (M, L) in enumerate(points, 1):
        problem = LineEHLProblem(M=M, L=L, viscosity=viscosity, density=density, alpha=2.2e-8, z=0.68,
                                 pressure_scale=None if L > 0 or density == "incompressible" else 1e9)
        factor = 8.0 * M / math.pi
        results = {}
        for level in levels:
            times, status, solution = [], "converged", None
            for _ in range(repeats):
                start = time.perf_counter()
                try:
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore", ConvergenceWarning)
                        solution = solve_multigrid(problem, level)
                except ConvergenceError as error:
                    status = f"failed: {str(error).split(':')[-1].strip()[:60]}"
                    solution = None
                    break
                times.append(time.perf_counter() - start)
                if not solution.record.converged:
                    status = "not converged"
            results[level] = (solution, status, statistics.median(times) if times else float("nan"))
        converged = [k for k in levels if results[k][1] == "converged"]
        if len(converged) >= 3:
            ref_c, order_c = richardson([results[k][0].H_c * factor for k in converged])
            ref_m, order_m = richardson([results[k][0].H_min * factor for k in converged])
        else:
            ref_c = ref_m = order_c = order_m = float("nan")
        for level in levels:
            solution, status, seconds = results[level]
            rows.append({
                "M": M, "L": L, "method": "multigrid", "level": level, "nodes": grid_points(level),
                "H_c": solution.H_c * factor if solution else float("nan"),
                "H_min": solution.H_min * factor if solution else float("nan"),
                "time [s]": seconds, "cycles": solution.record.cycles if solution else 0, "status": status,
            })
        for name, (H_c, H_min, seconds) in formula_films(M, L).items():
            rows.append({"M": M, "L": L, "method": name, "level": 0, "nodes": 0,
                         "H_c": np.nan if H_c is None else H_c, "H_min": np.nan if H_min is None else H_min,
                         "time [s]": seconds, "cycles": 0, "status": "formula"})
        for row in rows:
            if row["M"] == M and row["L"] == L:
                row["reference H_c"], row["reference H_min"] = ref_c, ref_m
                row["observed order H_c"], row["observed order H_min"] = order_c, order_m
        if progress:
            print(f"[{index}/{len(points)}] M = {M:g}, L = {L:g}: reference H_c = {ref_c:.5g}, "
                  f"H_min = {ref_m:.5g} ({len(converged)}/{len(levels)} levels converged)", flush=True)
    frame = pd.DataFrame(rows)
    frame["error H_c [%]"] = 100 * (frame["H_c"] / frame["reference H_c"] - 1)
    frame["error H_min [%]"] = 100 * (frame["H_min"] / frame["reference H_min"] - 1)
    return frame


def summary(frame: pd.DataFrame) -> pd.DataFrame:
    """Median |error| and median time per method (and level) over the map."""
    keyed = frame.assign(key=np.where(frame["method"] == "multigrid", "multigrid L" + frame["level"].astype(str),
                                      frame["method"]))
    table = keyed.groupby("key").agg(**{
        "median |error H_c| [%]": ("error H_c [%]", lambda s: s.abs().median()),
        "median |error H_min| [%]": ("error H_min [%]", lambda s: s.abs().median()),
        "median time [s]": ("time [s]", "median"),
        "failed or not converged": ("status", lambda s: int(((s != "converged") & (s != "formula")).sum())),
    })
    return table.sort_values("median time [s]")


def plot(frame: pd.DataFrame, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    table = summary(frame)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, column in zip(axes, ("median |error H_c| [%]", "median |error H_min| [%]")):
        grid = table[table.index.str.startswith("multigrid")]
        order = sorted(grid.index, key=lambda k: int(k.split("L")[-1]))
        ax.plot(grid.loc[order, "median time [s]"], grid.loc[order, column], "o-", label="multigrid (levels)")
        for key in order:
            ax.annotate(key.split(" ")[-1], (grid.loc[key, "median time [s]"], grid.loc[key, column]), fontsize=7)
        formulas = table[~table.index.str.startswith("multigrid")].dropna(subset=[column])
        ax.scatter(formulas["median time [s]"], formulas[column], marker="s", color="tab:red", label="formulas")
        for key in formulas.index:
            ax.annotate(key, (formulas.loc[key, "median time [s]"], formulas.loc[key, column]), fontsize=7)
        ax.set(xscale="log", yscale="log", xlabel="median wall time per film [s]", ylabel=column,
               title=column.replace("median |error ", "").replace("| [%]", "") + " error vs time")
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def point_rows(Ms, Ls, levels, repeats: int) -> pd.DataFrame:
    """Point contacts (D = 1): multigrid levels against the finest, formulas against it, and their cost."""
    from camcontact.ehl.point_multigrid import solve_point_multigrid
    from camcontact.ehl.point_problem import PointEHLProblem, point_grid_points
    from camcontact.models.film_point import nijenbanning_film

    def hamrock_dowson(M, L, speed_group=1e-11):  # Moes scaling at 2U = 1e-11 (its weak 2U dependence)
        U, W, G = speed_group / 2, M * speed_group**0.75, L * speed_group**-0.25
        k = 1.03
        h_min = 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1 - math.exp(-0.68 * k))
        h_c = 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1 - 0.61 * math.exp(-0.73 * k))
        return h_c / math.sqrt(speed_group), h_min / math.sqrt(speed_group)

    rows = []
    for M in Ms:
        for L in Ls:
            problem = PointEHLProblem(M=M, L=L, density="incompressible")
            results = {}
            for level in levels:
                times, solution = [], None
                for _ in range(repeats):
                    start = time.perf_counter()
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        solution = solve_point_multigrid(problem, level)
                    times.append(time.perf_counter() - start)
                results[level] = (*solution.moes_film(), statistics.median(times), solution.record.converged)
            ref_c, ref_min = results[max(levels)][:2]
            for level, (hc, hmin, seconds, converged) in results.items():
                n = point_grid_points(level)
                rows.append({"M": M, "L": L, "method": f"multigrid {n}x{n}", "level": level,
                             "error H_c [%]": 100 * (hc / ref_c - 1), "error H_min [%]": 100 * (hmin / ref_min - 1),
                             "median time [s]": seconds, "status": "converged" if converged else "not converged"})
            formulas = {"nijenbanning": (nijenbanning_film(M, L, 1.0), float("nan")),
                        "hamrock_dowson": hamrock_dowson(M, L)}
            for name, (hc, hmin) in formulas.items():
                start = time.perf_counter()
                for _ in range(100):
                    nijenbanning_film(M, L, 1.0) if name == "nijenbanning" else hamrock_dowson(M, L)
                rows.append({"M": M, "L": L, "method": name, "level": np.nan,
                             "error H_c [%]": 100 * (hc / ref_c - 1), "error H_min [%]": 100 * (hmin / ref_min - 1),
                             "median time [s]": (time.perf_counter() - start) / 100, "status": "formula"})
    return pd.DataFrame(rows)


def cam_cycle_rows(step_deg: float, levels, repeats: int) -> pd.DataFrame:
    """Quasi-steady formula / quasi-steady multigrid / transient multigrid over the flat-follower LS-1 turn."""
    import attrs

    import camcontact as cc
    from camcontact.models.film_multigrid import Multigrid
    from camcontact.scene_file import load_scene

    scene = load_scene()
    flat = attrs.evolve(scene.component, follower=cc.Follower.flat(material=scene.component.follower.material),
                        cam=attrs.evolve(scene.component.cam, base_radius="49.7494 mm"), angle_step=f"{step_deg} deg")
    steady_effects = {"elasticity", "piezoviscosity", "compressibility"}
    methods = [("pan_hamrock (quasi-steady)", "pan_hamrock", steady_effects)]
    for level in levels:
        model = Multigrid(levels=level, tolerance=1e-5)
        methods.append((f"multigrid L{level} (quasi-steady)", model, steady_effects))
        methods.append((f"multigrid L{level} (transient, squeeze)", model, steady_effects | {"squeeze"}))
    rows = []
    for label, film, effects in methods:
        times, result = [], None
        for _ in range(repeats):
            start = time.perf_counter()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                result = cc.Analysis(flat, outputs=["cam_angle", "u_m", "h_min"], models={"film": film},
                                     effects=effects).run()
            times.append(time.perf_counter() - start)
        theta, u, h = (np.asarray(result[k], dtype=float) for k in ("cam_angle", "u_m", "h_min"))
        flips = np.flatnonzero(np.sign(u[:-1]) * np.sign(u[1:]) < 0)
        near = np.zeros(theta.size, dtype=bool)
        for i in flips:
            near |= np.abs(theta - theta[i]) <= math.radians(5.0)
        rows.append({"method": label, "angles": theta.size, "h_min over the turn [nm]": 1e9 * np.nanmin(h),
                     "h_min near reversal [nm]": 1e9 * np.nanmin(h[near]) if near.any() else np.nan,
                     "h_min at 90 deg [nm]": 1e9 * float(np.interp(math.pi / 2, theta, h)),
                     "median time [s]": statistics.median(times)})
    return pd.DataFrame(rows)


#: the friction ladder: (label, effects beyond elasticity/piezoviscosity/compressibility, film model)
FRICTION_LADDER = (
    ("coulomb mu 0.05", set(), "pan_hamrock"),
    ("mixed, newtonian fluid", {"mixed"}, "pan_hamrock"),
    ("eyring isothermal", {"non_newtonian"}, "pan_hamrock"),
    ("mixed + eyring isothermal", {"mixed", "non_newtonian"}, "pan_hamrock"),
    ("mixed + eyring + thermal", {"mixed", "non_newtonian", "thermal"}, "pan_hamrock"),
    ("mixed + eyring + thermal, multigrid film", {"mixed", "non_newtonian", "thermal"}, "multigrid"),
)


def friction_rows(step_deg: float, level: int, repeats: int) -> pd.DataFrame:
    """The friction ladder over the LS-1 flat-follower turn at 1000 rpm (steel with thermal data, an oil with
    beta = 0.03 1/K and k = 0.13 W/(m K)): cycle-mean friction power, energy per turn, peak coefficient and
    the cost per angle of each rung. The multigrid rung shears the numerical film and integrates the shear
    stress over the numerical pressure at every angle with a solution (the Hertz pressure elsewhere)."""
    import attrs

    import camcontact as cc
    from camcontact.models.film_multigrid import Multigrid
    from camcontact.scene_file import load_scene

    scene = load_scene().component
    steel = cc.Material(E="210 GPa", nu=0.3, density="7850 kg/m^3", specific_heat="460 J/kg/K",
                        thermal_conductivity="47 W/m/K")
    oil = attrs.evolve(scene.lubricant, thermoviscous_coefficient="0.03 1/K", thermal_conductivity="0.13 W/m/K")
    flat = attrs.evolve(scene, lubricant=oil, cam=attrs.evolve(scene.cam, material=steel),
                        follower=cc.Follower.flat(material=steel, roughness="0.2 um"), angle_step=f"{step_deg} deg")
    base = {"elasticity", "piezoviscosity", "compressibility"}
    rows = []
    for label, effects, film in FRICTION_LADDER:
        model = Multigrid(levels=level, tolerance=1e-5) if film == "multigrid" else film
        times, result = [], None
        for _ in range(repeats):
            start = time.perf_counter()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                result = cc.Analysis(flat, effects=base | effects, models={"film": model},
                                     outputs=["cam_angle", "friction_coefficient", "friction_power_mean",
                                              "friction_energy_per_cycle", "friction_torque_mean"]).run()
            times.append(time.perf_counter() - start)
        angles = np.asarray(result["cam_angle"]).size
        rows.append({"rung": label, "angles": angles, "friction power mean [W]": result["friction_power_mean"],
                     "energy per turn [J]": result["friction_energy_per_cycle"],
                     "friction torque mean [N m]": result["friction_torque_mean"],
                     "peak coefficient": float(np.max(result["friction_coefficient"])),
                     "median time [s]": statistics.median(times),
                     "time per angle [ms]": 1e3 * statistics.median(times) / angles})
    frame = pd.DataFrame(rows)
    reference = frame["friction power mean [W]"].iloc[-1]
    frame["power vs last rung [%]"] = 100.0 * (frame["friction power mean [W]"] / reference - 1.0)
    return frame


#: the traction ladder of the ball-cone CVT: (rung, traction model, film, effects beyond the defaults)
TRACTION_LADDER = (
    ("constant Ct (thesis check)", None, "hamrock_dowson", set()),
    ("FASTSIM, Hertz pressure (thesis)", "fastsim_hertz", "hamrock_dowson", set()),
    ("FASTSIM, Kalker's parabolic pressure", "fastsim", "hamrock_dowson", set()),
    ("EHL Eyring isothermal, Hertz pressure", "ehl_traction", "hamrock_dowson", set()),
    ("EHL Eyring thermal, Hertz pressure", "ehl_traction", "hamrock_dowson", {"thermal"}),
    ("EHL Eyring + asperities (mixed), Hertz pressure", "ehl_traction", "hamrock_dowson", {"mixed"}),
    ("EHL Eyring thermal + asperities (mixed), Hertz", "ehl_traction", "hamrock_dowson", {"thermal", "mixed"}),
    ("EHL Eyring isothermal, numerical pressure", "ehl_traction", "multigrid", set()),
    ("EHL Eyring thermal, numerical pressure", "ehl_traction", "multigrid", {"thermal"}),
)
TRACTION_OUTPUTS = ("normal_force", "traction_needed_in", "traction_needed_out", "creepage_in", "creepage_out",
                    "traction_capacity_in", "traction_margin_in", "traction_margin_out", "spin_loss_in",
                    "creep_loss_in", "power_loss", "efficiency")


def traction_rows(level: int, repeats: int) -> pd.DataFrame:
    """The traction ladder of the ball-cone CVT at one operating point — Forti's geometry (tests' traction fluid,
    30/5.5 cSt, alpha 25 1/GPa, Ct 0.1; steel with thermal data; the fluid with k = 0.11
    W/(m K)) at 3000 rpm, 150 W, ratio 1.5, axial-balance clamping (p_h 1.9 GPa; Moes M ~ 300, where the
    numerical film converges): the input contact's creepage, capacity and margin, the spin loss, the drive's
    efficiency and the cost per operating point of each rung (the whole scene run, median of ``repeats`` after
    an untimed run that compiles the kernels).
    The constant-Ct rung is the thesis's check: capacity Ct N, margin 1 - (F_t/F_n)/Ct, no creep or losses."""
    import camcontact as cc
    from camcontact.models.film_multigrid_point import MultigridPoint
    from camcontact.models.traction import Fastsim

    steel = cc.Material(E="207 GPa", nu=0.3, density="7850 kg/m^3", specific_heat="460 J/kg/K",
                        thermal_conductivity="47 W/m/K")
    fluid = cc.Lubricant(name="traction fluid", nu40="30 cSt", nu100="5.5 cSt", density="0.90 g/cm^3",
                         alpha="2.5e-8 1/Pa", thermal_conductivity="0.11 W/m/K",
                         limiting_shear_slope=0.088)  # a traction fluid's Lambda_L (5P4E, Bair & Winer 1979)
    cvt = cc.BallConeCVT(cone_angle="30 deg", cone_contact_radius="24 mm", ball_diameter="14 mm", ball_count=9,
                         tilt_max="30 deg", cam_ramp_angle="10 deg", cam_radius="6 mm", cam_ball_count=5,
                         material=steel, traction_coefficient=0.1, lubricant=fluid, roughness="0.1 um")
    scene = cc.LoadedBallConeCVT(cvt=cvt, power="150 W", input_speed="3000 rpm", ratio=1.5, temperature="60 degC")
    base = {"elasticity", "piezoviscosity", "spin"}
    rows = []
    for label, traction, film, effects in TRACTION_LADDER:
        models = {"film": MultigridPoint(levels=level) if film == "multigrid" else film}
        outputs = list(TRACTION_OUTPUTS[:3])
        if traction is not None:
            models["traction"] = Fastsim(pressure="hertz") if traction == "fastsim_hertz" else traction
            outputs = list(TRACTION_OUTPUTS) + (["asperity_load_fraction_in"] if "mixed" in effects else [])
        times, result = [], None
        for k in range(repeats + 1):  # the first run compiles the kernels it meets: not timed
            start = time.perf_counter()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                result = cc.Analysis(scene, outputs=outputs, models=models, effects=base | effects).run()
            if k:
                times.append(time.perf_counter() - start)
        value = {name: result[name] for name in outputs}
        needed = max(value["traction_needed_in"], value["traction_needed_out"])
        margin = (min(value["traction_margin_in"], value["traction_margin_out"]) if traction is not None
                  else 1.0 - needed / cvt.traction_coefficient)
        rows.append({"rung": label, "creepage in [%]": 100.0 * abs(value.get("creepage_in", math.nan)),
                     "capacity in [N]": value.get("traction_capacity_in",
                                                  cvt.traction_coefficient * value["normal_force"]),
                     "traction margin [%]": 100.0 * margin, "spin loss in [W]": value.get("spin_loss_in", math.nan),
                     "creep loss in [W]": value.get("creep_loss_in", math.nan),
                     "efficiency [%]": 100.0 * value.get("efficiency", math.nan),
                     "asperity share in [%]": 100.0 * value.get("asperity_load_fraction_in", math.nan),
                     "median time [ms]": 1e3 * statistics.median(times)})
    frame = pd.DataFrame(rows)
    frame["efficiency vs last rung [pp]"] = frame["efficiency [%]"] - frame["efficiency [%]"].iloc[-1]
    return frame


def main(argv: list[str] | None = None) -> pd.DataFrame:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="2 x 2 points, levels 4..7, one run each")
    parser.add_argument("--viscosity", default="roelands", choices=("roelands", "barus"))
    parser.add_argument("--density", default="dowson_higginson", choices=("dowson_higginson", "incompressible"))
    parser.add_argument("--repeats", type=int, default=None, help="runs per level (median); default 3, quick 1")
    parser.add_argument("--out", default=str(Path(__file__).parent / "results"), help="output folder")
    parser.add_argument("--cam", action="store_true", help="the cam cycle: quasi-steady versus transient films")
    parser.add_argument("--point", action="store_true", help="circular point contacts: formulas versus grid levels")
    parser.add_argument("--friction", action="store_true", help="the friction ladder over the flat-follower turn")
    parser.add_argument("--traction", action="store_true", help="the traction ladder of the ball-cone CVT")
    args = parser.parse_args(argv)
    if args.traction:
        frame = traction_rows(3 if args.quick else 5, args.repeats or (1 if args.quick else 3))
        return write_results(frame, args.out, "accuracy_vs_time_traction", lambda f, p: None,
                             lambda f: f.set_index("rung"))
    if args.friction:
        step, level = (4.0, 5) if args.quick else (1.0, 7)
        frame = friction_rows(step, level, args.repeats or (1 if args.quick else 3))
        return write_results(frame, args.out, "accuracy_vs_time_friction", lambda f, p: None,
                             lambda f: f.set_index("rung"))
    if args.point:
        Ms, Ls, levels = ((20,), (10,), (3, 4)) if args.quick else ((10, 20, 50, 100), (5, 10), (3, 4, 5, 6))
        frame = point_rows(Ms, Ls, levels, args.repeats or (1 if args.quick else 3))
        return write_results(frame, args.out, "accuracy_vs_time_point", lambda f, p: None,
                             lambda f: f.groupby("method")[["error H_c [%]", "error H_min [%]", "median time [s]"]]
                             .agg(lambda v: v.abs().median()))
    if args.cam:
        step, levels = (4.0, (5,)) if args.quick else (0.5, (6, 7, 8))
        frame = cam_cycle_rows(step, levels, args.repeats or (1 if args.quick else 3))
        return write_results(frame, args.out, "accuracy_vs_time_cam", lambda f, p: None,
                             lambda f: f.set_index("method"))
    if args.quick:
        Ms, Ls, levels, repeats = (20, 100), (5, 10), range(4, 8), args.repeats or 1
    else:
        Ms, Ls, levels, repeats = (5, 10, 20, 50, 100, 200, 500, 1000), (2, 5, 10, 15, 20), range(4, 13), args.repeats or 3
    frame = run(Ms, Ls, list(levels), repeats, args.viscosity, args.density)
    return write_results(frame, args.out, "accuracy_vs_time", plot, summary)


if __name__ == "__main__":
    main()
