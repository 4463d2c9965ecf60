"""ISO 281:2007, ISO 76:2006 and ISO/TS 16281:2008 for radial ball bearings: C_r from the geometry, the
equivalent loads, the reference rating life from the ball loads.

* Basic dynamic load rating (ISO 281 §6.1.1, Eqs. 1-2) of a radial ball bearing with Z balls of
  diameter D_w [mm] in one row (i = 1), nominal contact angle alpha:
  C_r = b_m f_c (cos alpha)^0.7 Z^(2/3) D_w^1.8 [N] for D_w <= 25.4 mm and
  C_r = 3.647 b_m f_c (cos alpha)^0.7 Z^(2/3) D_w^1.4 above, with b_m = 1.3 (Table 1, radial ball
  bearings except filling-slot and insert bearings) and f_c of Table 2 against D_w cos(alpha)/D_pw
  (:data:`FC_TABLE`, single-row radial-contact and angular-contact groove ball bearings; linear
  interpolation between its rows, as the standard allows).
* Dynamic equivalent load P = X F_r + Y F_a (§6.2, Table 3): X = 1, Y = 0 for F_a/F_r <= e. Deep
  groove (and angular contact at 5°): X = 0.56 and e, Y interpolated in f_0 F_a / C_0r
  (:data:`DEEP_GROOVE_XY` on :data:`AXIAL_LOAD_GRID`, held at the grid's ends); angular contact at 10° and
  15° likewise (:data:`ANGULAR_LOAD_DEPENDENT`), from 20° to 45° e, X, Y of the contact angle only
  (:data:`ANGULAR_CONTACT_XY`); contact angles between the rows interpolated linearly.
* f_0 from the static rating of ISO 76:2006 §6.1.1, C_0r = f_0 i Z D_w^2 cos(alpha), so
  f_0 F_a / C_0r = F_a / (i Z D_w^2 cos alpha) [N, mm] when the catalogue gives no f_0.
* Static equivalent load (ISO 76 §6.2.1): P_0 = X_0 F_r + Y_0 F_a, at least F_r; deep groove
  X_0 = 0.6, Y_0 = 0.5; single-row angular contact X_0 = 0.5 with Y_0 of the contact angle
  (:data:`STATIC_Y0`, 5°..45°, held at its ends).
* L10 = (C/P)^3 10^6 revolutions (§7.1) and a_ISO of radial ball bearings (§9.3.3, Eqs. 31-33) are
  :class:`camcontact.models.life_iso281.ISO281`'s with ``rolling_element="ball"``
  (:func:`camcontact.models.life_iso281.a_iso_ball`).
* Pairs of identical single-row angular contact ball bearings (:func:`pair_equivalent_load`,
  :func:`pair_static_equivalent_load`, :func:`pair_load_ratings`): mounted back to back or face to face they are
  rated as one double-row bearing, i = 2 in Eq. 1, C = 2^0.7 C of one bearing, and C_0 = 2 C_0 (ISO 76's
  C_0r = f_0 i Z D_w^2 cos(alpha), i = 2); in tandem as bearings sharing one load, n^0.7 C with n = 2 bearings
  (ISO 281's rule for bearing combinations; the same 2^0.7). P of a DB/DF pair with Table 3's double-row
  columns (:data:`PAIR_XY`): X = 1, Y = Y_1 for F_a/F_r <= e (e of the single row), X_2, Y_2 above; P_0 with
  X_0 = 1 and Y_0 twice the single row's (ISO 76 Table 3's double-row column). A tandem pair takes the single-row
  factors with the pair's F_r, F_a (below 20° the relative axial load of each bearing, f_0 (F_a/2) / C_0r) and the
  single-row X_0 = 0.5, Y_0 with C_0 = 2 C_0. The fatigue load limit of a pair is 2 P_u (ISO 281 Annex B: P_u of a
  ball bearing is proportional to C_0 at a given pitch diameter).
* ISO/TS 16281:2008 basic reference rating life from the ball loads Q_j of the load distribution
  (:func:`reference_rating_life`): the ball loads the rings could carry for 10^6 revolutions,
  Q_ci = C / (0.407 Z (i cos alpha)^0.7) [1 + (1.044 r)^(10/3)]^0.3 and
  Q_ce = C / (0.389 Z (i cos alpha)^0.7) [1 + (1.044 r)^(-10/3)]^0.3 with
  r = ((1 - gamma)/(1 + gamma))^1.72 (f_i (2 f_e - 1) / (f_e (2 f_i - 1)))^0.41, the equivalent ball loads
  of the ring that turns against the load (Q_e = (sum Q_j^3 / Z)^(1/3)) and of the one that does not
  ((sum Q_j^(10/3) / Z)^(3/10)), and L_10r = [(Q_ci/Q_ei)^(-10/3) + (Q_ce/Q_ee)^(-10/3)]^(-9/10) [10^6 rev];
  gamma and alpha nominal.

The double-row factors of a DB/DF pair were checked against published tables (the ISO text itself was not at
hand): 30° and 40° (e 0.80 / 1.14; Y_1 0.78 / 0.55; X_2 0.63 / 0.57; Y_2 1.24 / 0.93) and the static Y_0 of a pair,
twice the single row's (0.92 at 15°, 0.66 at 30°, 0.52 at 40°), in Koyo's catalogue, "Calculation of equivalent
radial / axial load" (koyousa.com/koyocatalog/technical/03/3_1_32.htm); 25° (e 0.68, Y_1 0.92, X_2 0.67, Y_2 1.41),
40° again, and 35° (e 0.95, Y_1 0.66, X_2 0.60, Y_2 1.07, the row the same table gives four-point contact ball
bearings) and Y_0 0.76 at 25° in LYC's "Equivalent dynamic / static load - angular contact ball bearings"
(lycbearing.com). The double-row rows at 20° and 45° and the load-dependent ones below 20° were not found in a
source that could be checked, so they are left out: a DB/DF pair below 25° or above 40° is refused (InputError).

Sources: ISO 281:2007 (Tables 1-3, Eqs. 1-2, 28-29, 31-33), ISO 76:2006 (C_0r, X_0, Y_0), ISO/TS 16281:2008
(Eqs. 19-29 for ball bearings), as transcribed
in independent public implementations (the standard's text was not at hand; its tables' values agree
between them, and a_ISO's exponent 0.19087 is the one continuous at kappa = 0.4); ISO/TR 1281-1 for the
closed form behind Table 3 (tested against it). Tested against the catalogue examples of SKF (Rolling
bearings, "Calculation examples", Example 1, a 6309 deep-groove ball bearing; the SKF Bearing Calculator's
report of a 6309 under combined load) and of FAG (a 6208) in ``tests/literature/test_iso281_ball.py``; the
reference rating life against published reference values of a 7-ball bearing in the same file.
"""

from __future__ import annotations

import math

import numpy as np

from ..contact.ball_load_distribution import PAIR_ARRANGEMENTS
from ..errors import InputError

__all__ = ["ANGULAR_CONTACT_XY", "ANGULAR_LOAD_DEPENDENT", "AXIAL_LOAD_GRID", "DEEP_GROOVE_XY", "FC_TABLE", "PAIR_XY",
           "STATIC_Y0", "ball_equivalent_load", "dynamic_load_rating", "pair_equivalent_load", "pair_load_ratings",
           "pair_reference_rating_life", "pair_static_equivalent_load", "reference_rating_life",
           "static_equivalent_load"]

#: ISO 281:2007 Table 1: b_m of radial ball bearings (except filling-slot, insert and self-aligning ones)
B_M = 1.3
#: ISO 281:2007 Table 2, single-row radial-contact and angular-contact groove ball bearings:
#: (D_w cos(alpha) / D_pw, f_c) in steps of 0.01
FC_TABLE = (
    tuple(round(0.01 * k, 2) for k in range(1, 41)),
    (29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5, 56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9,
     60.0, 59.9, 59.8, 59.6, 59.3, 59.0, 58.6, 58.2, 57.7, 57.1, 56.6, 56.0, 55.3, 54.6, 53.9, 53.2, 52.4, 51.7,
     50.9, 50.0, 49.2, 48.4),
)
#: ISO 281:2007 Table 3: the relative axial load f_0 F_a / C_0r (= F_a / (Z D_w^2 cos alpha) [N/mm^2] with
#: ISO 76's C_0r) at which e and Y of the load-dependent rows are given
AXIAL_LOAD_GRID = (0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89)
#: single-row radial-contact (deep groove) ball bearings, and angular contact at 5°: (e, Y) on the grid, X = 0.56
DEEP_GROOVE_XY = (
    (0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44),
    (2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00),
)
#: single-row angular contact ball bearings below 20°: contact angle [deg] -> (e and Y on the grid, X)
ANGULAR_LOAD_DEPENDENT = {
    5.0: (*DEEP_GROOVE_XY, 0.56),
    10.0: ((0.29, 0.32, 0.36, 0.38, 0.40, 0.44, 0.49, 0.54, 0.54),
           (1.88, 1.71, 1.52, 1.41, 1.34, 1.23, 1.10, 1.01, 1.00), 0.46),
    15.0: ((0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56),
           (1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00), 0.44),
}
#: single-row angular contact ball bearings from 20°: contact angle [deg] -> (e, X, Y)
ANGULAR_CONTACT_XY = {20.0: (0.57, 0.43, 1.00), 25.0: (0.68, 0.41, 0.87), 30.0: (0.80, 0.39, 0.76),
                      35.0: (0.95, 0.37, 0.66), 40.0: (1.14, 0.35, 0.57), 45.0: (1.34, 0.33, 0.50)}
#: ISO 76:2006 Table 3, single-row angular contact ball bearings: contact angle [deg] -> Y_0 (X_0 = 0.5)
STATIC_Y0 = {5.0: 0.52, 10.0: 0.50, 15.0: 0.46, 20.0: 0.42, 25.0: 0.38, 30.0: 0.33, 35.0: 0.29, 40.0: 0.26, 45.0: 0.22}
LIFE_EXPONENT_BALL = 3.0
#: ISO 281:2007 Table 3, double-row angular contact ball bearings (a pair back to back or face to face): contact angle
#: [deg] -> (e, Y_1 for F_a/F_r <= e with X = 1, X_2 and Y_2 for F_a/F_r > e); only the rows confirmed from published
#: tables (module docstring)
PAIR_XY = {25.0: (0.68, 0.92, 0.67, 1.41), 30.0: (0.80, 0.78, 0.63, 1.24), 35.0: (0.95, 0.66, 0.60, 1.07),
           40.0: (1.14, 0.55, 0.57, 0.93)}
#: how a pair's C and C_0 grow over one bearing's: i^0.7 (i = 2 rows, or n = 2 bearings in tandem) and i
PAIR_RATING_FACTORS = (2.0**0.7, 2.0)


#: the groove osculations Table 2's f_c holds for (ISO 281 §6.1.1: r_i <= 0.52 D_w, r_e <= 0.53 D_w)
FC_OSCULATIONS = (0.52, 0.53)


def dynamic_load_rating(ball_diameter: float, pitch_diameter: float, ball_count: int, contact_angle: float,
                        rows: int = 1, inner_osculation: float | None = None,
                        outer_osculation: float | None = None) -> float:
    """ISO 281:2007 C_r [N] of a radial ball bearing from D_w, D_pw [m], Z, alpha [rad] and the rows i
    (module docstring). InputError outside Table 2's 0.01 <= D_w cos(alpha)/D_pw <= 0.40 or for grooves more
    open than Table 2 assumes (f_i > 0.52, f_o > 0.53: the catalogue's C is needed then)."""
    ratio = ball_diameter * math.cos(contact_angle) / pitch_diameter
    if not FC_TABLE[0][0] <= ratio <= FC_TABLE[0][-1]:
        raise InputError(f"ISO 281 C_r: D_w cos(alpha)/D_pw = {ratio:.4g} (from BallBearing.ball_diameter and "
                         "pitch_diameter) is outside Table 2 (0.01..0.40); give BallBearing.C from the catalogue")
    for name, value, limit in (("inner_osculation", inner_osculation, FC_OSCULATIONS[0]),
                               ("outer_osculation", outer_osculation, FC_OSCULATIONS[1])):
        if value is not None and value > limit + 1e-12:
            raise InputError(f"ISO 281 C_r: BallBearing.{name} = {value:g} is more open than the {limit} Table 2's f_c "
                             "assumes (ISO 281 then gives a lower rating); give BallBearing.C from the catalogue")
    f_c = float(np.interp(ratio, *FC_TABLE))
    D_w = 1e3 * ball_diameter
    factor = B_M * f_c * (rows * math.cos(contact_angle)) ** 0.7 * ball_count ** (2.0 / 3.0)
    return factor * D_w**1.8 if D_w <= 25.4 else 3.647 * factor * D_w**1.4


def _factors(contact_angle_deg: float, axial_ratio: float) -> tuple[float, float, float]:
    """(e, X, Y) of a single-row ball bearing at the nominal contact angle [deg] (0: radial contact; up to 45)
    and the relative axial load f_0 F_a / C_0r: the rows of Table 3 at this load (held at the grid's ends),
    linear between the tabulated angles (as ISO 281 allows for intermediate angles)."""
    rows = {angle: (float(np.interp(axial_ratio, AXIAL_LOAD_GRID, e)), X, float(np.interp(axial_ratio, AXIAL_LOAD_GRID, Y)))
            for angle, (e, Y, X) in ANGULAR_LOAD_DEPENDENT.items()} | ANGULAR_CONTACT_XY
    angles = sorted(rows)
    if contact_angle_deg <= angles[0]:
        return rows[angles[0]]
    return tuple(float(np.interp(contact_angle_deg, angles, [rows[a][k] for a in angles])) for k in range(3))


def ball_equivalent_load(radial_load: float, axial_load: float, *, kind: str, contact_angle: float, C0: float,
                         f0: float | None, ball_count: int, ball_diameter: float) -> dict[str, float]:
    """P [N] and e, X, Y of a single-row radial ball bearing (ISO 281:2007 §6.2, Table 3) for F_r, F_a [N];
    ``kind`` "deep_groove" (the radial-contact row) or "angular_contact" (nominal ``contact_angle`` [rad], up
    to 45°), the static rating C0 [N] and f_0 (None: f_0 F_a / C_0r = F_a / (Z D_w^2 cos alpha) [N/mm^2] from
    ISO 76's C_0r = f_0 Z D_w^2 cos(alpha), D_w [m])."""
    Fr, Fa = float(radial_load), abs(float(axial_load))
    if Fr < 0.0 or not (math.isfinite(Fr) and math.isfinite(Fa)):
        raise InputError(f"ISO 281 P: radial_load = {radial_load!r} N, axial_load = {axial_load!r} N; allowed: finite, "
                         "radial >= 0")
    _check_kind(kind, axial_load)
    degrees = 0.0 if kind == "deep_groove" else math.degrees(contact_angle)
    if not 0.0 <= degrees <= 45.0 + 1e-9:
        raise InputError(f"ISO 281 P: contact angle {degrees:.4g} deg is outside Table 3's radial ball bearings (0..45 deg)")
    area = ball_count * (1e3 * ball_diameter) ** 2 * math.cos(math.radians(degrees))  # mm^2: C_0r / f_0
    ratio = Fa / area if f0 is None else f0 * Fa / C0
    e, X, Y = _factors(degrees, ratio)
    if Fr > 0.0 and Fa / Fr <= e:
        return {"P": Fr, "e": e, "X": 1.0, "Y": 0.0}
    return {"P": X * Fr + Y * Fa, "e": e, "X": X, "Y": Y}


def _check_kind(kind: str, axial_load: float) -> None:
    if kind not in ("deep_groove", "angular_contact"):
        raise InputError(f"ISO 281: kind = {kind!r}; allowed: 'deep_groove', 'angular_contact'")
    if kind == "angular_contact" and axial_load < 0.0:
        raise InputError(f"ISO 281: axial_load = {axial_load:g} N on a single-row angular contact bearing points away from "
                         "its contact angle (allowed >= 0; the other direction is carried by its counterpart)")


def static_equivalent_load(radial_load: float, axial_load: float, *, kind: str, contact_angle: float) -> float:
    """P_0 [N] of a single-row radial ball bearing (ISO 76:2006 §6.2.1): max(X_0 F_r + Y_0 F_a, F_r), with F_r, F_a
    [N], ``kind`` and the nominal ``contact_angle`` [rad] as :func:`ball_equivalent_load`."""
    Fr, Fa = float(radial_load), abs(float(axial_load))
    _check_kind(kind, axial_load)
    if kind == "deep_groove":
        X0, Y0 = 0.6, 0.5
    else:
        X0 = 0.5
        Y0 = float(np.interp(math.degrees(contact_angle), list(STATIC_Y0), list(STATIC_Y0.values())))
    return max(X0 * Fr + Y0 * Fa, Fr)


def reference_rating_life(Q, *, C: float, ball_diameter: float, pitch_diameter: float, contact_angle: float,
                          inner_osculation: float, outer_osculation: float, inner_rotates: bool = True,
                          rows: int = 1) -> dict[str, float]:
    """ISO/TS 16281:2008 basic reference rating life L_10r [10^6 revolutions] of a ball bearing from its ball loads
    ``Q`` [N] (all Z balls of a row, unloaded ones 0), C [N], D_w, D_pw [m], the nominal contact angle [rad] and
    the osculations (module docstring); ``inner_rotates``: the inner ring turns against the load (else the
    outer). Returns L10r with Q_ci, Q_ce, Q_ei, Q_ee [N]; L10r infinite without load."""
    Q = np.asarray(Q, dtype=float)
    if Q.ndim != 1 or Q.size < 3 or np.any(~np.isfinite(Q)) or np.any(Q < 0.0):
        raise InputError(f"ISO/TS 16281 L_10r: the ball loads must be finite and >= 0, one per ball (got {Q!r})")
    Z = Q.size
    gamma = ball_diameter * math.cos(contact_angle) / pitch_diameter
    fi, fe = inner_osculation, outer_osculation
    ratio = ((1.0 - gamma) / (1.0 + gamma)) ** 1.72 * (fi * (2.0 * fe - 1.0) / (fe * (2.0 * fi - 1.0))) ** 0.41
    scale = C / (Z * (rows * math.cos(contact_angle)) ** 0.7)
    Q_ci = scale / 0.407 * (1.0 + (1.044 * ratio) ** (10.0 / 3.0)) ** 0.3
    Q_ce = scale / 0.389 * (1.0 + (1.044 * ratio) ** (-10.0 / 3.0)) ** 0.3
    turning = float(np.mean(Q**3)) ** (1.0 / 3.0)
    standing = float(np.mean(Q ** (10.0 / 3.0))) ** 0.3
    Q_ei, Q_ee = (turning, standing) if inner_rotates else (standing, turning)
    if Q_ei == 0.0 and Q_ee == 0.0:
        return {"L10r": math.inf, "Q_ci": Q_ci, "Q_ce": Q_ce, "Q_ei": 0.0, "Q_ee": 0.0}
    L10r = ((Q_ci / Q_ei) ** (-10.0 / 3.0) + (Q_ce / Q_ee) ** (-10.0 / 3.0)) ** -0.9
    return {"L10r": L10r, "Q_ci": Q_ci, "Q_ce": Q_ce, "Q_ei": Q_ei, "Q_ee": Q_ee}


def pair_load_ratings(C: float, C0: float, fatigue_load_limit: float | None = None) -> dict[str, float | None]:
    """C, C_0 and P_u [N] of a pair of identical bearings from one bearing's (module docstring): 2^0.7 C, 2 C_0 and
    2 P_u (None stays None), for back to back, face to face and tandem alike."""
    dynamic, static = PAIR_RATING_FACTORS
    return {"C": dynamic * C, "C0": static * C0,
            "fatigue_load_limit": None if fatigue_load_limit is None else static * fatigue_load_limit}


def _check_arrangement(arrangement: str, axial_load: float, what: str) -> None:
    if arrangement not in PAIR_ARRANGEMENTS:
        raise InputError(f"{what}: arrangement = {arrangement!r}; allowed: 'back_to_back', 'face_to_face', 'tandem'")
    if arrangement == "tandem" and axial_load < 0.0:
        raise InputError(f"{what}: axial_load = {axial_load:g} N on a tandem pair points away from its contact angle "
                         "(allowed >= 0; both bearings face the same way)")


def pair_equivalent_load(radial_load: float, axial_load: float, *, arrangement: str, contact_angle: float, C0: float,
                         f0: float | None, ball_count: int, ball_diameter: float) -> dict[str, float]:
    """P [N] and e, X, Y of a pair of identical single-row angular contact ball bearings under the pair's F_r, F_a [N]
    (module docstring): back to back or face to face (F_a of either sign) with the double-row factors of
    :data:`PAIR_XY`, linear between its rows (25..40°; InputError outside, naming the angle); in tandem with
    :func:`ball_equivalent_load`'s single-row factors, each bearing's relative axial load f_0 (F_a/2) / C_0r
    (``C0`` [N] and ``ball_count`` Z of one bearing)."""
    Fr, Fa = float(radial_load), float(axial_load)
    _check_arrangement(arrangement, Fa, "ISO 281 P of a pair")
    if arrangement == "tandem":
        return ball_equivalent_load(Fr, Fa, kind="angular_contact", contact_angle=contact_angle, C0=2.0 * C0, f0=f0,
                                    ball_count=2 * ball_count, ball_diameter=ball_diameter)
    if Fr < 0.0 or not (math.isfinite(Fr) and math.isfinite(Fa)):
        raise InputError(f"ISO 281 P of a pair: radial_load = {radial_load!r} N, axial_load = {axial_load!r} N; "
                         "allowed: finite, radial >= 0")
    degrees = math.degrees(contact_angle)
    angles = sorted(PAIR_XY)
    if not angles[0] - 1e-9 <= degrees <= angles[-1] + 1e-9:
        raise InputError(f"ISO 281 P of a {arrangement} pair: contact angle {degrees:.4g} deg; the double-row factors "
                         f"of Table 3 are implemented from {angles[0]:g} to {angles[-1]:g} deg only (the 20 and 45 deg "
                         "rows and the load-dependent rows below 20 deg could not be confirmed from a source)")
    e, Y1, X2, Y2 = (float(np.interp(degrees, angles, [PAIR_XY[a][k] for a in angles])) for k in range(4))
    Fa = abs(Fa)
    if Fr > 0.0 and Fa / Fr <= e:
        return {"P": Fr + Y1 * Fa, "e": e, "X": 1.0, "Y": Y1}
    return {"P": X2 * Fr + Y2 * Fa, "e": e, "X": X2, "Y": Y2}


def pair_static_equivalent_load(radial_load: float, axial_load: float, *, arrangement: str,
                                contact_angle: float) -> float:
    """P_0 [N] of a pair of identical single-row angular contact ball bearings under the pair's F_r, F_a [N]: back to
    back or face to face F_r + 2 Y_0 |F_a| (X_0 = 1, Y_0 of :data:`STATIC_Y0`); in tandem the single row's
    :func:`static_equivalent_load` (X_0 = 0.5, at least F_r). Its static rating is 2 C_0 (:func:`pair_load_ratings`)."""
    Fr, Fa = float(radial_load), float(axial_load)
    _check_arrangement(arrangement, Fa, "ISO 76 P_0 of a pair")
    if arrangement == "tandem":
        return static_equivalent_load(Fr, Fa, kind="angular_contact", contact_angle=contact_angle)
    Y0 = 2.0 * float(np.interp(math.degrees(contact_angle), list(STATIC_Y0), list(STATIC_Y0.values())))
    return Fr + Y0 * abs(Fa)


def pair_reference_rating_life(Q, row, *, C: float, ball_diameter: float, pitch_diameter: float, contact_angle: float,
                               inner_osculation: float, outer_osculation: float,
                               inner_rotates: bool = True) -> dict[str, float | tuple]:
    """ISO/TS 16281 L_10r [10^6 revolutions] of a pair of identical bearings from the ball loads ``Q`` [N] of both and
    their ``row`` (0 or 1 per ball): each bearing's :func:`reference_rating_life` with its C [N], combined as the two
    rings of a bearing are, L_10r = (sum_k L_k^(-10/9))^(-9/10) (the Weibull slope 10/9 of ball bearings; an unloaded
    bearing's life is infinite and drops out). Returns ``L10r`` and ``L10r_rows`` (per bearing)."""
    Q, row = np.asarray(Q, dtype=float), np.asarray(row)
    if row.shape != Q.shape or not set(np.unique(row).tolist()) <= {0, 1}:
        raise InputError(f"ISO/TS 16281 L_10r of a pair: row must give 0 or 1 for each of the {Q.size} balls "
                         f"(got {row!r})")
    rows = tuple(reference_rating_life(Q[row == k], C=C, ball_diameter=ball_diameter, pitch_diameter=pitch_diameter,
                                       contact_angle=contact_angle, inner_osculation=inner_osculation,
                                       outer_osculation=outer_osculation, inner_rotates=inner_rotates)["L10r"]
                 for k in (0, 1))
    inverse = sum(life ** (-10.0 / 9.0) for life in rows)
    return {"L10r": inverse**-0.9 if inverse > 0.0 else math.inf, "L10r_rows": rows}
