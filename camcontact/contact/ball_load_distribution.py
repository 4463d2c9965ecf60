"""Internal load distribution of a ball bearing, with the contact angle changing under load.

Rigid rings, no speed effects (Harris & Kotzalas 2007, Vol. 1 ch. 7, "ball bearings under combined
radial, thrust and moment load"; Jones 1960). The centres of the inner and outer raceway groove
curvatures are A = (f_i + f_o - 1) D apart in the unloaded, just-touching state (D the ball diameter,
f = r/D the osculations). With the inner ring displaced by (delta_a, delta_r) and tilted by theta
relative to the outer ring, the centres of ball j at azimuth psi_j (from the radial load's direction)
lie

    A_1j = a_0 + delta_a + R_i theta cos(psi_j)        (axially)
    A_2j = r_0 + delta_r cos(psi_j)                    (radially)

apart, so the ball's elastic deformation (both contacts) and its contact angle are

    delta_j = sqrt(A_1j^2 + A_2j^2) - A,   alpha_j = atan2(A_1j, A_2j),

and its load Q_j = K_n(alpha_j) max(delta_j, 0)^(3/2), with K_n the stiffness of the ball's two
Hertz contacts in series at that angle (exact elliptical Hertz, :func:`ball_stiffness`). R_i =
d_m/2 + (f_i - 1/2) D cos(alpha_0) is the radius of the locus of the inner groove's curvature
centres, which a tilt theta of the inner ring about the bearing centre moves axially by R_i theta
(``moment_lever="groove_centres"``, the default); ISO/TS 16281 as commercial codes apply it (and the
reference values tested) takes the pitch radius d_m/2 instead (``moment_lever="pitch"``): the tilt then
differs by the factor R_i/(d_m/2), about 1 %, and a moment's effect by as much. The moment acts in the
plane of the radial load (tilting about the axis normal to it; positive M presses the ball at psi = 0
onto the flank of positive alpha); a moment out of that plane is not modelled. The unloaded offsets are

* deep-groove (radial) bearing with diametral clearance P_d: a_0 = 0, r_0 = A - P_d/2, so the free
  contact angle is alpha_0 = arccos(1 - P_d/(2A)) (Harris & Kotzalas Eq. 2.9) and a ball may touch
  either flank of its grooves (alpha_j of either sign);
* angular-contact bearing with the free contact angle alpha_0: a_0 = A sin(alpha_0),
  r_0 = A cos(alpha_0); a ball touches only the flanks of its contact angle (alpha_j > 0): one whose
  centres move past the groove bottoms (A_1j <= 0) carries no load.

The applied loads balance the balls' reactions

    F_a = sum Q_j sin(alpha_j),  F_r = sum Q_j cos(alpha_j) cos(psi_j),
    M = sum Q_j sin(alpha_j) R_i cos(psi_j),

the gradient of the potential Pi = sum K_n max(delta_j, 0)^(5/2)/(5/2) - F . x (for fixed K_n convex for a
deep-groove bearing, delta_j being the norm of an affine function; for an angular-contact bearing only
while the loaded balls stay on their flanks, A_1j > 0, which holds unless the loads nearly lift them).
Newton's method with backtracking minimises it with each ball's K_n frozen; K_n is then updated at the new contact angles until they settle. Without a given
moment the tilt is held at zero (a bearing on a shaft supported elsewhere, Harris's combined-load
case) and the moment the balls then exert is reported; with one, theta is solved. Two angular-contact bearings
mounted as a pair (back to back, face to face or in tandem, with an axial preload) share one set of ring
displacements about the pair's centre: :func:`solve_ball_pair_load_distribution`.

References: Harris, T.A. & Kotzalas, M.N. (2007) Rolling Bearing Analysis, 5th ed., Vol. 1, ch. 2
(Eqs. 2.1-2.9: osculation, total curvature B, free contact angle), ch. 6 (Hertz contact of a ball
in its grooves) and ch. 7 (load distribution; Stribeck's Q_max = 4.37 F_r/(Z cos alpha) for zero
clearance, about 5 F_r/(Z cos alpha) with a normal clearance); Jones, A.B. (1960) A general theory
for elastically constrained ball and radial roller bearings under arbitrary load and speed
conditions, J. Basic Eng. 82:309-320.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import ConvergenceError, InputError
from .hertz_elliptical import hertz_elliptical

__all__ = ["OPPOSED_ARRANGEMENTS", "PAIR_ARRANGEMENTS", "BallLoadDistribution", "ball_race_radii", "ball_stiffness",
           "solve_ball_load_distribution", "solve_ball_pair_load_distribution"]

EXPONENT = 1.5  #: Q = K delta^(3/2), point contact
RACES = ("inner", "outer")
#: the pairs whose bearings face each other, clamped so that they can be preloaded
OPPOSED_ARRANGEMENTS = ("back_to_back", "face_to_face")
#: how the two bearings of a pair face each other (:func:`solve_ball_pair_load_distribution`)
PAIR_ARRANGEMENTS = (*OPPOSED_ARRANGEMENTS, "tandem")


def ball_race_radii(ball_diameter: float, pitch_diameter: float, osculation: float, contact_angle: float,
                    race: str) -> tuple[float, float]:
    """Reduced radii (R_x along rolling, R_y across) [m] of a ball in the inner or outer raceway groove:
    R_x = (D/2)(1 -/+ gamma), gamma = D cos(alpha)/d_m, and R_y = f D/(2 f - 1) (Harris & Kotzalas ch. 2)."""
    gamma = ball_diameter * math.cos(contact_angle) / pitch_diameter
    sign = -1.0 if race == "inner" else 1.0
    return 0.5 * ball_diameter * (1.0 + sign * gamma), osculation * ball_diameter / (2.0 * osculation - 1.0)


def ball_stiffness(ball_diameter: float, pitch_diameter: float, inner_osculation: float, outer_osculation: float,
                   contact_angle: float, E_reduced: float) -> float:
    """K_n [N/m^(3/2)] of a ball between both raceways at ``contact_angle`` [rad] (E' [Pa]): the exact
    elliptical Hertz approaches delta = c Q^(2/3) of the two contacts in series, K_n = (c_i + c_o)^(-3/2)."""
    compliance = 0.0
    for race, f in zip(RACES, (inner_osculation, outer_osculation)):
        Rx, Ry = ball_race_radii(ball_diameter, pitch_diameter, f, contact_angle, race)
        compliance += hertz_elliptical(1.0, Rx, Ry, E_reduced).approach
    return compliance**-EXPONENT


@attrs.frozen
class BallLoadDistribution:
    """Ball loads, contact angles and ring displacements in equilibrium (SI units).

    ``Q`` [N], ``contact_angle`` [rad], ``approach`` (the deformation delta_j, both contacts) [m] and
    ``stiffness`` K_n [N/m^1.5] per ball; ``azimuth`` [rad]; ``delta_a``, ``delta_r`` [m] and ``tilt``
    [rad] the inner ring's displacements; ``moment`` [N m] the balls' moment about the bearing centre
    (the applied one, or the reaction with the tilt held); ``residual`` the relative force imbalance;
    ``iterations`` Newton steps in all; ``residuals`` per step.
    """

    Q: np.ndarray = attrs.field(repr=False, eq=False)
    contact_angle: np.ndarray = attrs.field(repr=False, eq=False)
    approach: np.ndarray = attrs.field(repr=False, eq=False)
    stiffness: np.ndarray = attrs.field(repr=False, eq=False)
    azimuth: np.ndarray = attrs.field(repr=False, eq=False)
    delta_a: float
    delta_r: float
    tilt: float
    moment: float
    radial_load: float
    axial_load: float
    free_contact_angle: float
    residual: float
    iterations: int
    residuals: tuple = attrs.field(repr=False, eq=False)
    row: np.ndarray | None = attrs.field(default=None, repr=False, eq=False)
    arrangement: str = "single"

    @property
    def row_axial_loads(self) -> np.ndarray:
        """Axial load [N] each row (bearing) carries onto its own flanks, sum Q sin(alpha) (one value for a single
        bearing)."""
        rows = np.zeros(self.Q.size, dtype=int) if self.row is None else self.row
        axial = np.where(self.Q > 0.0, self.Q * np.sin(np.nan_to_num(self.contact_angle)), 0.0)
        return np.bincount(rows, weights=axial)

    @property
    def Q_max(self) -> float:
        """Largest ball load [N]."""
        return float(self.Q.max()) if self.Q.size else 0.0

    @property
    def loaded(self) -> np.ndarray:
        """Balls in contact (Q > 0)."""
        return self.Q > 0.0

    @property
    def load_zone(self) -> float:
        """Angle of the last loaded ball from the load line [rad] (0: none loaded, pi: all)."""
        angles = np.abs(np.angle(np.exp(1j * self.azimuth[self.loaded])))
        return float(angles.max()) if angles.size else 0.0

    def to_frame(self):
        """One row per ball: azimuth [deg], contact angle [deg], approach [um], Q [N], loaded."""
        import pandas as pd

        return pd.DataFrame({"ball": np.arange(self.Q.size), "azimuth [deg]": np.degrees(self.azimuth),
                             "contact angle [deg]": np.degrees(self.contact_angle),
                             "approach [um]": 1e6 * self.approach, "Q [N]": self.Q, "loaded": self.loaded})


@attrs.frozen
class _Geometry:
    """The centre offsets per ball and their derivatives with respect to x = (delta_a, delta_r, theta): per ball the
    flank direction ``sign`` of its bearing (+1, or -1 for the mirrored bearing of a pair), the axial position ``z``
    [m] of its row from the centre of tilt and the axial ``offset`` [m] a preload gives its centres."""

    a0: float
    r0: float
    A: float
    locus: float
    cos_psi: np.ndarray
    one_flank: bool
    sign: np.ndarray | float = 1.0
    z: np.ndarray | float = 0.0
    offset: np.ndarray | float = 0.0

    def centres(self, x):
        return (self.a0 + self.offset + self.sign * (x[0] + self.locus * x[2] * self.cos_psi),
                self.r0 + (x[1] - self.z * x[2]) * self.cos_psi)

    def state(self, x, K):
        """(delta, alpha, Q, s, A1, A2) per ball."""
        A1, A2 = self.centres(x)
        s = np.hypot(A1, A2)
        delta = s - self.A
        touching = delta > 0.0
        if self.one_flank:
            touching &= A1 > 0.0
        Q = np.where(touching, K * np.maximum(delta, 0.0) ** EXPONENT, 0.0)
        return delta, np.arctan2(A1, A2), Q, s, A1, A2

    def jacobian(self):
        """d(A1, A2)/dx per ball: shape (Z, 2, 3)."""
        Z = self.cos_psi.size
        G = np.zeros((Z, 2, 3))
        G[:, 0, 0] = self.sign
        G[:, 0, 2] = self.sign * self.locus * self.cos_psi
        G[:, 1, 1] = self.cos_psi
        G[:, 1, 2] = -self.z * self.cos_psi
        return G


def solve_ball_load_distribution(
    radial_load: float,
    axial_load: float,
    moment: float | None = None,
    *,
    ball_count: int,
    ball_diameter: float,
    pitch_diameter: float,
    inner_osculation: float,
    outer_osculation: float,
    E_reduced: float,
    clearance: float = 0.0,
    free_contact_angle: float | None = None,
    moment_lever: str = "groove_centres",
    tolerance: float = 1e-10,
    max_iterations: int = 200,
) -> BallLoadDistribution:
    """Ball loads and contact angles of a ball bearing under F_r, F_a and a moment (module docstring).

    Parameters
    ----------
    radial_load, axial_load : float
        F_r >= 0 [N] (along azimuth 0) and F_a [N] (positive: towards the flanks of +alpha).
    moment : float, optional
        Tilting moment M [N m] in the plane of the radial load (about the axis normal to it); None holds the tilt
        at zero.
    ball_count, ball_diameter, pitch_diameter : int, float, float
        Z (>= 3), D [m], d_m [m].
    inner_osculation, outer_osculation : float
        f_i, f_o = groove radius / D (> 0.5).
    E_reduced : float
        E' [Pa] of ball and rings.
    clearance : float
        Diametral clearance P_d [m] of a deep-groove bearing (negative: preload); with
        ``free_contact_angle`` it must be 0.
    free_contact_angle : float, optional
        alpha_0 [rad] of an angular-contact bearing (0 < alpha_0 < pi/2): its balls touch one flank
        only. None: a deep-groove bearing, alpha_0 from the clearance.
    moment_lever : str
        "groove_centres" (R_i, default) or "pitch" (d_m/2, ISO/TS 16281 as commercial codes apply it).
    tolerance : float
        On the relative force imbalance |F - sum| / max(|F_r|, |F_a|, |M|/R_i, 1 N).

    Raises
    ------
    InputError
        Bad input (names the argument, the value and what is allowed), or loads the bearing cannot
        carry (an angular-contact bearing under a radial load without the axial load that holds its
        balls on their flanks).
    ConvergenceError
        No equilibrium found (the record is in the message).
    """
    Fr, Fa = float(radial_load), float(axial_load)
    D, d_m = float(ball_diameter), float(pitch_diameter)
    _check_inputs(Fr, Fa, 0.0 if moment is None else moment, clearance, ball_count, D, d_m, E_reduced, moment_lever,
                  tolerance, max_iterations, inner_osculation, outer_osculation)
    A = (inner_osculation + outer_osculation - 1.0) * D
    if free_contact_angle is None:
        if not clearance < 2.0 * A:
            raise InputError(f"ball load distribution: clearance = {clearance * 1e6:.4g} um is not below 2 (f_i + f_o - 1) D "
                             f"= {2e6 * A:.4g} um: the balls would fall out of their grooves")
        a0, r0 = 0.0, A - 0.5 * clearance
        alpha0 = math.acos(min(1.0, r0 / A))
    else:
        alpha0 = float(free_contact_angle)
        if not 0.0 < alpha0 < 0.5 * math.pi:
            raise InputError(f"ball load distribution: free_contact_angle = {math.degrees(alpha0):.4g} deg; allowed "
                             "0 < alpha_0 < 90 deg")
        if clearance != 0.0:
            raise InputError("ball load distribution: an angular-contact bearing takes its free_contact_angle, not a "
                             f"clearance (clearance = {clearance!r} m)")
        a0, r0 = A * math.sin(alpha0), A * math.cos(alpha0)
    Z = int(ball_count)
    psi = 2.0 * math.pi * np.arange(Z) / Z
    locus = 0.5 * d_m + (inner_osculation - 0.5) * D * math.cos(alpha0) if moment_lever == "groove_centres" else 0.5 * d_m
    geometry = _Geometry(a0=a0, r0=r0, A=A, locus=locus, cos_psi=np.cos(psi), one_flank=free_contact_angle is not None)
    free_dofs = [0, 1, 2] if moment is not None else [0, 1]
    F = np.array([Fa, Fr, 0.0 if moment is None else float(moment)])

    stiffness = _stiffness_law(D, d_m, inner_osculation, outer_osculation, E_reduced)
    K0 = float(stiffness([alpha0])[0])
    x = np.zeros(3)
    if not (Fr == 0.0 and Fa == 0.0 and F[2] == 0.0):
        x = _start(geometry, K0, F, Z, alpha0, clearance if free_contact_angle is None else 0.0)
    return _equilibrium(geometry, F, free_dofs, stiffness, K0, alpha0, x, tolerance, max_iterations, psi)


def solve_ball_pair_load_distribution(
    radial_load: float,
    axial_load: float,
    moment: float | None = None,
    *,
    arrangement: str,
    row_spacing: float,
    preload: float = 0.0,
    ball_count: int,
    ball_diameter: float,
    pitch_diameter: float,
    inner_osculation: float,
    outer_osculation: float,
    E_reduced: float,
    free_contact_angle: float,
    moment_lever: str = "groove_centres",
    tolerance: float = 1e-10,
    max_iterations: int = 200,
) -> BallLoadDistribution:
    """Ball loads and contact angles of a pair of identical angular-contact ball bearings on one rigid shaft and in
    one rigid housing, under F_r, F_a and a tilting moment M in the plane of F_r (module docstring for one bearing);
    ``moment`` None holds the tilt at zero (a shaft supported elsewhere too) and reports the balls' moment.

    The rows sit at z = -e/2 and +e/2 about the pair's centre, e = ``row_spacing`` (row 0, which carries a positive
    F_a, at -e/2 back to back or in tandem, at +e/2 face to face); the inner rings
    move together by (delta_a, delta_r) and tilt by theta about that centre, so the ball centres of row k move
    axially by sign_k (delta_a + R_i theta cos(psi)) in their bearing's own frame and radially by
    (delta_r - z_k theta) cos(psi). ``arrangement``:

    * ``"back_to_back"`` (DB, "O"): the contact lines of the two rows meet on the axis outside the pair, which
      spreads the rows' reactions and makes the pair stiff against tilting;
    * ``"face_to_face"`` (DF, "X"): they meet inside it, which makes the pair compliant against tilting;
    * ``"tandem"`` (DT): both rows face the same way and share an axial load of one direction (F_a > 0).

    ``preload`` delta_p [m] (DB / DF only): the axial interference of the clamped pair, which presses each bearing's
    balls onto their flanks by delta_p / 2 (its axial offset) before any load; a preloaded pair keeps both rows
    loaded until the axial load relieves one, at F_a = 2^(3/2) F_0 for a constant contact angle (F_0 the preload
    force; Harris & Kotzalas 2007, ch. 8). Positive F_a presses row 0 onto its flanks. Returns the 2Z balls (row 0
    first) with ``row`` and ``arrangement``; ``moment`` the applied M (the tilt solved) or the balls' reaction.

    Raises InputError for a bad input (naming it) or loads the pair cannot carry (a tandem pair without an axial
    load of its direction), ConvergenceError when no equilibrium is found.
    """
    Fr, Fa, M = float(radial_load), float(axial_load), 0.0 if moment is None else float(moment)
    D, d_m = float(ball_diameter), float(pitch_diameter)
    _check_inputs(Fr, Fa, M, 0.0, ball_count, D, d_m, E_reduced, moment_lever, tolerance, max_iterations,
                  inner_osculation, outer_osculation)
    if arrangement not in PAIR_ARRANGEMENTS:
        raise InputError(f"ball pair load distribution: arrangement = {arrangement!r}; allowed: "
                         f"{', '.join(PAIR_ARRANGEMENTS)}")
    if not (row_spacing > 0.0 and math.isfinite(row_spacing)):
        raise InputError(f"ball pair load distribution: row_spacing = {row_spacing!r} m; allowed: finite and > 0 (the "
                         "axial distance between the rows' ball centres)")
    if not (preload >= 0.0 and math.isfinite(preload)) or (arrangement not in OPPOSED_ARRANGEMENTS and preload != 0.0):
        raise InputError(f"ball pair load distribution: preload = {preload!r} m; allowed: finite and >= 0, and 0 for a "
                         "tandem pair (it is preloaded against a third bearing, which is not modelled)")
    alpha0 = float(free_contact_angle)
    if not 0.0 < alpha0 < 0.5 * math.pi:
        raise InputError(f"ball pair load distribution: free_contact_angle = {math.degrees(alpha0):.4g} deg; allowed "
                         "0 < alpha_0 < 90 deg")
    A = (inner_osculation + outer_osculation - 1.0) * D
    Z = int(ball_count)
    psi = np.tile(2.0 * math.pi * np.arange(Z) / Z, 2)
    row = np.repeat([0, 1], Z)
    # row 0 carries positive F_a (its flank sign +1); its contact lines meet the axis outside the pair (O) when it sits
    # at -e/2, inside (X) at +e/2
    first = 0.5 if arrangement == "face_to_face" else -0.5
    z = np.where(row == 0, first, -first) * row_spacing
    sign = np.ones(2 * Z) if arrangement == "tandem" else np.where(row == 0, 1.0, -1.0)
    locus = 0.5 * d_m + (inner_osculation - 0.5) * D * math.cos(alpha0) if moment_lever == "groove_centres" else 0.5 * d_m
    geometry = _Geometry(a0=A * math.sin(alpha0), r0=A * math.cos(alpha0), A=A, locus=locus, cos_psi=np.cos(psi),
                         one_flank=True, sign=sign, z=z, offset=0.5 * preload)
    F = np.array([Fa, Fr, M])

    stiffness = _stiffness_law(D, d_m, inner_osculation, outer_osculation, E_reduced)
    K0 = float(stiffness([alpha0])[0])
    x = np.zeros(3)
    if preload == 0.0 and (Fa != 0.0 or Fr != 0.0 or M != 0.0):
        # take up the play that the unpreloaded pair has not: a Stribeck-sized elastic deformation of the balls
        per_ball = max(5.0 * Fr / (Z * math.cos(alpha0)), abs(Fa) / (Z * math.sin(alpha0)),
                       4.0 * abs(M) / (row_spacing * Z), 1e-6)
        elastic = (per_ball / K0) ** (1.0 / EXPONENT)
        x[0] = math.copysign(elastic / math.sin(alpha0), Fa) if Fa != 0.0 else 0.0
        x[1] = elastic / math.cos(alpha0) if Fr > 0.0 else 0.0
        if moment is not None and M != 0.0:  # a tilt that presses the balls of one side (either arrangement)
            x[2] = math.copysign(elastic / (locus * math.sin(alpha0) + 0.5 * row_spacing * math.cos(alpha0)), M)
    free_dofs = [0, 1] if moment is None else [0, 1, 2]
    return _equilibrium(geometry, F, free_dofs, stiffness, K0, alpha0, x, tolerance, max_iterations, psi,
                        row=row, arrangement=arrangement)



def _stiffness_law(D: float, d_m: float, inner_osculation: float, outer_osculation: float, E_reduced: float):
    """K_n of each ball at its contact angle [rad]: alpha (array) -> K_n (array) [N/m^1.5]."""
    def stiffness(alpha):
        return np.array([ball_stiffness(D, d_m, inner_osculation, outer_osculation, a, E_reduced) for a in alpha])

    return stiffness

def _check_inputs(Fr, Fa, moment, clearance, ball_count, D, d_m, E_reduced, moment_lever, tolerance, max_iterations,
                  inner_osculation, outer_osculation) -> None:
    """InputError naming the argument, its value and what is allowed, for the inputs both solvers share."""
    for name, value in (("radial_load", Fr), ("axial_load", Fa), ("clearance", clearance), ("moment", moment)):
        if not math.isfinite(value):
            raise InputError(f"ball load distribution: {name} = {value!r}; must be finite")
    if Fr < 0.0:
        raise InputError(f"ball load distribution: radial_load = {Fr:g} N; allowed >= 0 (its direction is azimuth 0)")
    if not (isinstance(ball_count, (int, np.integer)) and ball_count >= 3):
        raise InputError(f"ball load distribution: ball_count = {ball_count!r}; allowed: an integer >= 3")
    for name, value in (("ball_diameter", D), ("pitch_diameter", d_m), ("E_reduced", E_reduced)):
        if not (value > 0.0 and math.isfinite(value)):
            raise InputError(f"ball load distribution: {name} = {value!r}; allowed: finite and > 0")
    if not d_m > D:
        raise InputError(f"ball load distribution: pitch_diameter = {d_m!r} m must exceed ball_diameter = {D!r} m")
    if moment_lever not in ("groove_centres", "pitch"):
        raise InputError(f"ball load distribution: moment_lever = {moment_lever!r}; allowed: 'groove_centres', 'pitch'")
    if not (tolerance > 0.0 and isinstance(max_iterations, int) and max_iterations >= 1):
        raise InputError(f"ball load distribution: tolerance = {tolerance!r}, max_iterations = {max_iterations!r}; "
                         "allowed: tolerance > 0, max_iterations an integer >= 1")
    for name, f in (("inner_osculation", inner_osculation), ("outer_osculation", outer_osculation)):
        if not 0.5 < f < 1.0:
            raise InputError(f"ball load distribution: {name} = {f!r}; allowed 0.5 < f < 1 (groove radius over ball "
                             "diameter: at 0.5 the groove fits the ball and the contact has no Hertz solution)")


def _equilibrium(geometry: _Geometry, F: np.ndarray, free_dofs: list, stiffness, K0: float, alpha0: float,
                 x: np.ndarray, tolerance: float, max_iterations: int, psi: np.ndarray, **extra) -> BallLoadDistribution:
    """Newton on the potential with the balls' K_n frozen, then K_n updated at the new contact angles until they
    settle; the result with its convergence record (ConvergenceError above 100 x the tolerance)."""
    Fa, Fr = float(F[0]), float(F[1])
    scale = max(abs(Fr), abs(Fa), abs(F[2]) / geometry.locus, 1.0)
    K = np.full(psi.size, K0)
    residuals: list[float] = []
    iterations = 0
    previous = None
    for _outer in range(20):
        x, used = _newton(geometry, K, F, x, free_dofs, scale, tolerance, max_iterations, residuals, (Fr, Fa))
        iterations += used
        _, alpha, Q, *_ = geometry.state(x, K)
        new_K = stiffness(np.where(Q > 0.0, alpha, alpha0))
        if previous is not None and np.max(np.abs(alpha - previous)) < 1e-12 or np.allclose(new_K, K, rtol=1e-13):
            break
        previous, K = alpha, new_K
    delta, alpha, Q, _, _, A2 = geometry.state(x, K)
    if np.any((Q > 0.0) & (A2 <= 0.0)):
        raise InputError(f"ball load distribution: under F_r = {Fr:g} N, F_a = {Fa:g} N, M = {F[2]:g} N m loaded balls "
                         "reach contact angles of 90 deg and beyond: the loads drive them over their grooves' shoulders "
                         "(the bearing cannot carry them; the shoulders are not modelled)")
    reaction = float(_gradient(geometry, x, K, np.zeros(3))[2])
    gradient = _gradient(geometry, x, K, F)
    weight = np.array([1.0, 1.0, 1.0 / geometry.locus])
    residual = float(np.max(np.abs(gradient[free_dofs] * weight[free_dofs]))) / scale
    if residual > max(100.0 * tolerance, 1e-8):
        raise ConvergenceError(f"ball load distribution: force imbalance {residual:.3g} after {iterations} Newton steps "
                               f"(F_r = {Fr:g} N, F_a = {Fa:g} N, M = {F[2]:g} N m)")
    return BallLoadDistribution(
        Q=Q, contact_angle=np.where(Q > 0.0, alpha, np.nan), approach=delta, stiffness=K, azimuth=psi,
        delta_a=float(x[0]), delta_r=float(x[1]), tilt=float(x[2]), moment=reaction, radial_load=Fr, axial_load=Fa,
        free_contact_angle=alpha0, residual=residual, iterations=iterations, residuals=tuple(residuals), **extra)


def _start(geometry: _Geometry, K: float, F: np.ndarray, Z: int, alpha0: float, clearance: float) -> np.ndarray:
    """A start with balls touching: the play taken up plus a Stribeck-sized elastic deformation."""
    Fa, Fr, M = F
    per_ball = max(5.0 * Fr / (Z * max(math.cos(alpha0), 0.1)), abs(Fa) / (Z * max(math.sin(alpha0), 0.1)),
                   4.0 * abs(M) / (geometry.locus * Z * max(math.sin(alpha0), 0.1)), 1e-6)
    elastic = (per_ball / K) ** (1.0 / EXPONENT)
    # the axial offset of the centres at which a ball is loaded that much, along the flank of the load's sign
    reach = math.sqrt(max((geometry.A + elastic) ** 2 - geometry.r0**2, 0.0))
    x = np.zeros(3)
    if Fa != 0.0 or (geometry.one_flank and Fr > 0.0):
        x[0] = math.copysign(reach, Fa if Fa != 0.0 else 1.0) - geometry.a0
    if Fr > 0.0:
        x[1] = 0.5 * max(clearance, 0.0) + elastic
    if M != 0.0 and Fa == 0.0 and not geometry.one_flank:
        x[2] = math.copysign(reach, M) / geometry.locus
    return x


def _gradient(geometry: _Geometry, x, K, F):
    """dPi/dx = sum Q_j d(delta_j)/dx - F."""
    _, alpha, Q, *_ = geometry.state(x, K)
    G = geometry.jacobian()
    normal = np.stack([np.sin(alpha), np.cos(alpha)], axis=1)
    return np.einsum("j,jk,jkl->l", Q, normal, G) - F


def _newton(geometry, K, F, x, free, scale, tolerance, max_iterations, residuals, loads):
    """Newton steps with backtracking on the potential (K frozen) from x; returns (x, steps)."""
    G = geometry.jacobian()
    weight = np.array([1.0, 1.0, 1.0 / geometry.locus])

    def energy(x):
        delta, _, Q, *_ = geometry.state(x, K)
        return float(np.sum(Q * np.maximum(delta, 0.0)) / (EXPONENT + 1.0) - F @ x)

    for step_count in range(max_iterations):
        delta, alpha, Q, s, A1, A2 = geometry.state(x, K)
        g = _gradient(geometry, x, K, F)
        residual = float(np.max(np.abs(g[free] * weight[free]))) / scale
        residuals.append(residual)
        if residual < tolerance:
            return x, step_count
        loaded = Q > 0.0
        if not np.any(loaded):
            raise InputError(_no_contact_message(geometry, F))
        n = np.stack([A1, A2], axis=1) / s[:, None]
        stiff = EXPONENT * K * np.maximum(delta, 0.0) ** (EXPONENT - 1.0)
        H = np.zeros((3, 3))
        for j in np.flatnonzero(loaded):
            gradient_j = n[j] @ G[j]
            tangent = (np.eye(2) - np.outer(n[j], n[j])) / s[j]
            H += stiff[j] * np.outer(gradient_j, gradient_j) + Q[j] * G[j].T @ tangent @ G[j]
        sub = H[np.ix_(free, free)]
        sub += np.eye(len(free)) * 1e-14 * max(np.trace(sub), 1.0)
        step = np.zeros(3)
        step[free] = -np.linalg.solve(sub, g[free])
        base = energy(x)
        t = 1.0
        while t > 1e-12:
            trial = x + t * step
            if energy(trial) <= base + 1e-4 * t * float(g @ step) or \
                    float(np.max(np.abs(_gradient(geometry, trial, K, F)[free] * weight[free]))) / scale < 0.5 * residual:
                break
            t *= 0.5
        x = x + t * step
        if np.max(np.abs(x[:2])) > 10.0 * geometry.A:
            raise InputError(_no_contact_message(geometry, F))
    raise ConvergenceError(f"ball load distribution did not converge in {max_iterations} Newton steps "
                           f"(F_r = {loads[0]:g} N, F_a = {loads[1]:g} N, residual {residuals[-1]:.3g})")


def _no_contact_message(geometry: _Geometry, F: np.ndarray) -> str:
    Fa, Fr, M = F
    loads = f"F_r = {Fr:g} N, F_a = {Fa:g} N, M = {M:g} N m"
    if not geometry.one_flank:
        return f"ball load distribution: no ball carries {loads}: the rings move apart without touching the balls"
    if Fa < 0.0:
        why = "F_a < 0 pushes the balls off the flanks of its contact angle (allowed F_a > 0; its counterpart takes the other way)"
    elif Fa == 0.0:
        why = (("a radial load" if Fr > 0.0 else "a moment") + " needs an axial load that holds the balls on their flanks "
               "(F_a > 0, of the order of 1.25 F_r tan(alpha_0) for half the balls under a radial load; or mount it as a pair)")
    else:
        why = "the axial load is too small to hold the balls on their flanks against the radial load and the moment"
    return f"ball load distribution: an angular-contact ball bearing cannot carry {loads}: {why}"
