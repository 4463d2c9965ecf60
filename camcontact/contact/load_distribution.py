"""Internal load distribution of a rolling bearing with line contacts (numerical, ISO/TS 16281 style).

The inner ring of a bearing with ``rows`` rows of ``Z`` rollers, contact angle ±alpha, is displaced
by (delta_r, delta_a) relative to the outer ring (a self-aligning bearing carries no moment). The
elastic approach along the contact normal of roller j (azimuth psi_j, measured from the direction
of the radial load) in row k (s_k = +1 / -1 for the rows with +alpha / -alpha) is

    delta_jk = delta_r cos(psi_j) cos(alpha) + s_k delta_a sin(alpha) - (c_r / 2) cos(alpha)

with c_r the radial internal clearance (diametral play; zero or negative = preload), and the
roller load Q_jk = K_n max(delta_jk, 0)^(10/9) (line contact; K_n combines the inner and outer
contact in series). The displacements follow from the force balance

    F_r = sum_jk Q_jk cos(alpha) cos(psi_j),      F_a = sum_jk s_k Q_jk sin(alpha),

found as the minimum of the convex potential energy
Pi = sum_jk K_n max(delta_jk, 0)^(19/9) / (19/9) - F_r delta_r - F_a delta_a by Newton's method with
backtracking, so the solution is unique and reached from any start; the record gives the force
residual per iteration.

Load zone. Harris & Kotzalas (Vol. 1, ch. 7, radially loaded bearings with clearance) write the
approach of a roller as delta_psi = delta_r cos(psi) - P_d / 2 with the diametral clearance P_d, so
the loaded arc ends where it vanishes, at the load-zone half-angle

    psi_l = arccos(P_d / (2 delta_r)).

c_r here is that P_d (ISO's radial internal clearance is the total radial play of one ring against
the other). With the contact angle alpha both the ring displacement and the clearance project onto
the contact normal with cos(alpha), which cancels; an axial displacement adds s_k delta_a sin(alpha)
per row (Harris & Kotzalas ch. 7, combined radial and axial load), so per row k

    cos(psi_l,k) = (c_r / 2 - s_k delta_a tan(alpha)) / delta_r,

clipped to [-1, 1] (psi_l = pi: the whole row loaded; 0: the row unloaded; with delta_r = 0 a row is
either wholly loaded or not). For a pure radial load (delta_a = 0) this is Harris's psi_l. It is the
continuous boundary of the loaded arc: the last loaded roller sits at or inside it
(:attr:`LoadDistribution.last_loaded_azimuth`), the next roller outside.

References: Harris & Kotzalas (2007) Rolling Bearing Analysis, ch. 7 (load distribution, the
load-deflection law Q = K delta^(10/9) for line contact); Stribeck's Q_max = 4.08 F_r/(Z cos alpha)
for line contact and zero clearance (NSK catalogue E728 §5.1; tested against the exact discrete
value); Palmgren (1959) Ball and Roller Bearing Engineering for the steel line-contact deflection
delta = 3.84e-5 Q^0.9 / l^0.8 [mm, N, mm] behind :func:`line_contact_stiffness`; ISO/TS 16281:2008
for the numerical approach.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import ConvergenceError, InputError

__all__ = ["LoadDistribution", "line_contact_stiffness", "solve_load_distribution"]

EXPONENT = 10.0 / 9.0  #: Q = K delta^(10/9), line contact
PALMGREN = 3.84e-5  #: delta [mm] = 3.84e-5 Q^0.9 [N] / l^0.8 [mm] per line contact (Palmgren)


def line_contact_stiffness(length: float) -> float:
    """K_n [N/m^(10/9)] of a roller between two raceways (two line contacts in series, effective
    length ``length`` [m]) from Palmgren's deflection delta = 3.84e-5 Q^0.9 / l^0.8 [mm, N, mm]."""
    if not (length > 0.0 and math.isfinite(length)):
        raise InputError(f"line_contact_stiffness: length = {length!r} m; allowed: > 0")
    l_mm = 1e3 * length
    # total approach (both contacts) delta = 2 * 3.84e-5 Q^0.9 / l^0.8 [mm] -> Q = K delta^(10/9)
    K_mm = (l_mm**0.8 / (2.0 * PALMGREN)) ** EXPONENT  # N / mm^(10/9)
    return K_mm * 1e3**EXPONENT


@attrs.frozen
class LoadDistribution:
    """Roller loads and ring displacements of a bearing in equilibrium (SI units).

    ``Q`` [N] and ``approach`` [m] have shape (rows, Z); ``azimuth`` [rad] shape (Z,) per row
    (``azimuths`` (rows, Z) with a row offset); ``delta_r``, ``delta_a`` [m] the inner ring's
    displacements; ``residual`` the relative force imbalance; ``iterations`` Newton steps;
    ``clearance`` the radial internal clearance c_r = P_d [m] the loads were solved with.
    """

    Q: np.ndarray = attrs.field(repr=False, eq=False)
    approach: np.ndarray = attrs.field(repr=False, eq=False)
    azimuths: np.ndarray = attrs.field(repr=False, eq=False)
    row_sign: np.ndarray = attrs.field(repr=False, eq=False)
    alpha: float
    delta_r: float
    delta_a: float
    radial_load: float
    axial_load: float
    residual: float
    iterations: int
    residuals: tuple = attrs.field(repr=False, eq=False)
    clearance: float = 0.0

    @property
    def Q_max(self) -> float:
        """Largest roller load [N]."""
        return float(self.Q.max()) if self.Q.size else 0.0

    @property
    def loaded(self) -> np.ndarray:
        """Rollers in contact (Q > 0), shape (rows, Z)."""
        return self.Q > 0.0

    @property
    def load_zone(self) -> np.ndarray:
        """Load-zone half-angle psi_l per row [rad] (Harris & Kotzalas ch. 7; module docstring):
        arccos((c_r / 2 - s_k delta_a tan(alpha)) / delta_r), = arccos(P_d / (2 delta_r)) under a
        radial load; 0: row unloaded, pi: the whole row loaded."""
        out = np.zeros(self.Q.shape[0])
        if not np.any(self.Q > 0.0):
            return out
        for k, sign in enumerate(self.row_sign):
            # approach / cos(alpha) = delta_r cos(psi) + offset: loaded where it is positive
            offset = sign * self.delta_a * math.tan(self.alpha) - 0.5 * self.clearance
            if self.delta_r > 0.0:
                out[k] = math.acos(min(1.0, max(-1.0, -offset / self.delta_r)))
            else:
                out[k] = math.pi if offset > 0.0 else 0.0
        return out

    @property
    def last_loaded_azimuth(self) -> np.ndarray:
        """Angle of the last loaded roller from the load line per row [rad] (0: row unloaded); with
        discrete rollers it lies at or inside :attr:`load_zone`."""
        out = np.zeros(self.Q.shape[0])
        for k in range(self.Q.shape[0]):
            angles = np.abs(np.angle(np.exp(1j * self.azimuths[k][self.Q[k] > 0.0])))
            out[k] = float(angles.max()) if angles.size else 0.0
        return out

    def force_balance(self) -> tuple[float, float]:
        """(sum of radial, sum of axial) roller-load components [N] (equal the applied loads)."""
        c, s = math.cos(self.alpha), math.sin(self.alpha)
        radial = float(np.sum(self.Q * np.cos(self.azimuths)) * c)
        axial = float(np.sum(self.Q * self.row_sign[:, None]) * s)
        return radial, axial

    def to_frame(self):
        """One row per roller: row, index, azimuth [deg], approach [um], Q [N], loaded."""
        import pandas as pd

        rows, Z = self.Q.shape
        return pd.DataFrame({
            "row": np.repeat(np.arange(1, rows + 1), Z),
            "roller": np.tile(np.arange(Z), rows),
            "azimuth [deg]": np.degrees(self.azimuths).ravel(),
            "approach [um]": 1e6 * self.approach.ravel(),
            "Q [N]": self.Q.ravel(),
            "loaded": self.loaded.ravel(),
        })


def solve_load_distribution(
    radial_load: float,
    axial_load: float,
    *,
    rollers_per_row: int,
    contact_angle: float,
    stiffness: float,
    clearance: float = 0.0,
    rows: int = 2,
    row_offset: float = 0.0,
    tolerance: float = 1e-11,
    max_iterations: int = 200,
) -> LoadDistribution:
    """Roller loads of a line-contact bearing under a radial and an axial load (module docstring).

    Parameters
    ----------
    radial_load, axial_load : float
        F_r >= 0 [N] (along azimuth 0) and F_a [N] (positive: carried by the row with +alpha).
    rollers_per_row : int
        Z >= 3.
    contact_angle : float
        alpha [rad], 0 <= alpha < pi/2 (0 only for one row; an axial load then has no support).
    stiffness : float
        K_n [N/m^(10/9)] of one roller (both contacts), e.g. :func:`line_contact_stiffness`.
    clearance : float
        Radial internal clearance c_r [m] (negative: preload).
    rows : int
        1 or 2 (the second row with -alpha).
    row_offset : float
        Azimuth offset of the second row's rollers [rad] (0: rows in line).
    tolerance : float
        On the relative force imbalance |F_applied - F_rollers| / max(|F|, 1 N); where rounding of
        the approaches (a tiny load taking up a large clearance) stops progress, down to its
        square root is accepted.

    Raises
    ------
    InputError
        Bad input (names the argument, the value and what is allowed).
    ConvergenceError
        No equilibrium found (the record is in the message).
    """
    Fr, Fa = float(radial_load), float(axial_load)
    for name, value in (("radial_load", Fr), ("axial_load", Fa), ("clearance", clearance),
                        ("stiffness", stiffness), ("contact_angle", contact_angle)):
        if not math.isfinite(value):
            raise InputError(f"load distribution: {name} = {value!r}; must be finite")
    if Fr < 0.0:
        raise InputError(f"load distribution: radial_load = {Fr:g} N; allowed >= 0 (its direction defines azimuth 0)")
    if not (isinstance(rollers_per_row, (int, np.integer)) and rollers_per_row >= 3):
        raise InputError(f"load distribution: rollers_per_row = {rollers_per_row!r}; allowed: an integer >= 3")
    if rows not in (1, 2):
        raise InputError(f"load distribution: rows = {rows!r}; allowed 1 or 2")
    if not (0.0 <= contact_angle < 0.5 * math.pi):
        raise InputError(f"load distribution: contact_angle = {contact_angle!r} rad; allowed 0 <= alpha < pi/2")
    if not stiffness > 0.0:
        raise InputError(f"load distribution: stiffness = {stiffness!r}; allowed > 0")
    Z = int(rollers_per_row)
    alpha = float(contact_angle)
    c, s = math.cos(alpha), math.sin(alpha)
    if Fa != 0.0 and s == 0.0:
        raise InputError(f"load distribution: axial_load = {Fa:g} N but contact_angle = 0: the rollers cannot carry it")
    psi = 2.0 * math.pi * np.arange(Z) / Z
    azimuths = np.array([psi + (row_offset if k == 1 else 0.0) for k in range(rows)])
    row_sign = np.array([1.0, -1.0][:rows])
    cos_psi = np.cos(azimuths)
    # approach = A @ (delta_r, delta_a) - gap, per roller
    a_r = (cos_psi * c).ravel()
    a_a = (np.repeat(row_sign, Z) * s)
    gap = 0.5 * clearance * c
    A = np.column_stack([a_r, a_a])
    F = np.array([Fr, Fa])
    scale = max(abs(Fr), abs(Fa), 1.0)

    def state(x):
        approach = A @ x - gap
        active = np.maximum(approach, 0.0)
        Q = stiffness * active**EXPONENT
        gradient = A.T @ Q - F
        return approach, Q, gradient

    if Fr == 0.0 and Fa == 0.0:
        x = np.zeros(2)
        approach, Q, _ = state(x)
        return _result(Q * 0.0, approach, azimuths, row_sign, alpha, x, Fr, Fa, 0.0, 0, (), clearance)
    # start: the rigid play taken up plus a Stribeck-sized elastic approach
    per_roller = max(Fr / (0.25 * rows * Z * max(c, 1e-3)), abs(Fa) / (0.5 * Z * max(s, 1e-3)), 1e-9)
    elastic = (per_roller / stiffness) ** (1.0 / EXPONENT)
    x = np.array([(gap + elastic) / max(c, 1e-3) if Fr > 0 else 0.0,
                  math.copysign((gap + elastic) / s, Fa) if (Fa != 0.0 and s > 0) else 0.0])

    def energy(x):
        active = np.maximum(A @ x - gap, 0.0)
        return float(stiffness * np.sum(active ** (EXPONENT + 1.0)) / (EXPONENT + 1.0) - F @ x)

    residuals = []
    approach, Q, g = state(x)
    for iteration in range(1, max_iterations + 1):
        residual = float(np.max(np.abs(g))) / scale
        residuals.append(residual)
        if residual < tolerance:
            return _result(Q, approach, azimuths, row_sign, alpha, x, Fr, Fa, residual, iteration - 1,
                           tuple(residuals), clearance)
        active = approach > 0.0
        weights = stiffness * EXPONENT * np.where(active, np.maximum(approach, 0.0), 0.0) ** (EXPONENT - 1.0)
        H = (A * weights[:, None]).T @ A
        if s == 0.0:
            H[1, 1] = 1.0  # no axial stiffness, no axial load: delta_a stays 0
        # regularise where no roller is in contact yet (flat energy): move to take up the play
        H += np.eye(2) * 1e-12 * max(np.trace(H), stiffness * 1e-9)
        try:
            step = -np.linalg.solve(H, g)
        except np.linalg.LinAlgError:
            step = -g / max(np.trace(H), 1.0)
        if not np.all(np.isfinite(step)):
            raise ConvergenceError(f"load distribution: non-finite Newton step (F_r = {Fr:g} N, F_a = {Fa:g} N)")
        base = energy(x)
        size = float(np.max(np.abs(g)))
        t = 1.0
        while t > 1e-12:
            trial = x + t * step
            # sufficient decrease of the energy, or (near the solution, where energy differences
            # drown in rounding) of the force imbalance
            if (energy(trial) <= base + 1e-4 * t * float(g @ step)
                    or float(np.max(np.abs(state(trial)[2]))) < 0.5 * size):
                break
            t *= 0.5
        if len(residuals) > 5 and min(residuals[-5:]) >= min(residuals[:-5]) and residual < math.sqrt(tolerance):
            # no progress for five steps: the imbalance is at the rounding level of the approaches
            return _result(Q, approach, azimuths, row_sign, alpha, x, Fr, Fa, residual, iteration - 1,
                           tuple(residuals), clearance)
        x = x + t * step
        approach, Q, g = state(x)
    raise ConvergenceError(
        f"load distribution did not converge in {len(residuals)} Newton steps (F_r = {Fr:g} N, F_a = {Fa:g} N, "
        f"residual {residuals[-1]:.3g})"
    )


def _result(Q, approach, azimuths, row_sign, alpha, x, Fr, Fa, residual, iterations, residuals,
            clearance) -> LoadDistribution:
    shape = azimuths.shape
    return LoadDistribution(Q=Q.reshape(shape), approach=approach.reshape(shape), azimuths=azimuths,
                            row_sign=row_sign, alpha=alpha, delta_r=float(x[0]), delta_a=float(x[1]),
                            radial_load=Fr, axial_load=Fa, residual=residual, iterations=iterations,
                            residuals=residuals, clearance=float(clearance))
