"""Lumped 2-DOF and 5-DOF valve trains with unilateral cam and seat contact (Ferrarese & Uehara).

An overhead cam drives a bucket tappet (bucket + shim) that pushes the valve open against a
return spring and a "pressure spring" (the gas under the valve head). The valve train is a
chain of point masses; the cam lift y(θ) drives the first one through a unilateral
spring–damper contact, the last one (the valve head) meets the seat through a second
unilateral spring–damper. :func:`simulate` integrates the equations of motion over whole cam
revolutions at constant speed with :func:`scipy.integrate.solve_ivp`, locating every opening
and closing of the two contacts as an event and restarting the integration there, so the
non-smooth switches are resolved accurately (no smoothing of the contact laws).

Topology (documented reading: the figure of the model, Fig. 1 of the paper, is missing)
-----------------------------------------------------------------------------------------
Displacements x_i [m] are positive in the opening direction (away from the cam), measured from
the position where the cam base circle just touches the bucket, the valve head just touches
its seat and every stem element is unstrained (zero lash)::

      cam lift y(θ)
          │  k_c, c_c   (unilateral: pushes only while y − x_1 > 0)
        [m_1]  bucket + shim (+ stem top) ── return spring k_r, preload F_r0 (pushes −x)
          │  k_1, c_s1
        [m_2]  stem segment
          ⋮
          │  k_{n−1}, c_s,n−1
        [m_n]  valve head ── pressure spring k_p while open (x_n > 0), pushes −x
                         ── seat k_v, c_v while seated (x_n < 0), pushes +x only

.. math::
    M \\ddot x + C \\dot x + K x = e_1 (N - F_{r0}) + e_n S, \\\\
    N = \\max(k_c \\delta + c_c \\dot\\delta, 0) \\;\\text{if}\\; \\delta = y - x_1 > 0, \\text{ else } 0, \\\\
    S = \\max(-k_v x_n - c_v \\dot x_n, 0) \\;\\text{if}\\; x_n < 0, \\text{ else } 0,

with K, C the stem chain plus k_r on mass 1 and k_p on mass n while x_n > 0. Gravity is left out.

Readings of the paper (assumptions, since Fig. 1 is missing):

* a chain: cam → m_1 → stem springs → m_n; the 5-DOF stem springs k_1 … k_4 join m_1–m_2, …,
  m_4–m_5 in the printed order;
* masses: m_1 is the tappet (bucket 48.0 g + shim 23.1 g) plus the top stem segment, the middle
  masses are stem segments, m_n the valve head with the lowest stem segment; the 2-DOF m_1 is
  the 5-DOF m_1 … m_4 together (bookkeeping and the 0.9 g shortfall against Table 1 in
  :meth:`LumpedValveTrain.ferrarese_2dof`);
* the return spring acts on m_1 (its retainer sits at the stem top, lumped with the tappet);
  the pressure spring and the seat act on m_n;
* zero valve lash: on the base circle the preload is shared by the cam contact and the seat;
* the 5-DOF model uses the contact and seat elements printed in the 2-DOF column; the 2-DOF
  stem stiffness (not printed) is the series combination of the 5-DOF stem;
* the return-spring preload (not printed) is a field, default 250 N; the stem damping (not
  printed) defaults to 2 % of critical per stem element.

The contact and seat forces follow the Kelvin–Voigt law but never pull: a force element is
*loaded* while both its penetration and its force are positive, i.e. while
h = min(k δ, k δ + c δ̇) > 0. The same continuous h serves as the event function for unloading
(h falls through 0) and loading (h rises through 0); a hysteresis ε = 1e-9 max(F_r0, 1 N) keeps
a restart from re-triggering the event it starts on. A heavily damped element can unload while
its penetration is still positive (the bodies move apart faster than k δ/c): the force is then
zero although there is no gap yet. The reports keep the two apart: ``contact_open`` and
``jumps`` are the geometric separations (gap x_1 − y > 0, located by their own events), the
force is ``contact_force`` (zero whenever unloaded), and ``events`` lists both. The valve's
passing x_n = 0 ("valve open": pressure spring on, valve off its seat) is a third switch, so
every integration segment is a smooth linear ODE with a constant Jacobian.

References
----------
Ferrarese, A., Uehara, S. (n.d.: the copy used prints no year) Modelos de atrito e desgaste no sistema
came–seguidor (friction and wear models in the cam–follower system), Escola Politécnica da USP.
§2 and Fig. 1 (models), Tables 1 and 2 (parameters), Fig. 4 (N at 3000 rpm).
"""

from __future__ import annotations

import math
import time as _time
from collections.abc import Callable

import attrs
import numpy as np
from scipy.integrate import solve_ivp

from ..errors import ConvergenceError, InputError

__all__ = ["LumpedValveTrain", "SolverRecord", "StaticEquilibrium", "ValveTrainResponse", "simulate"]

TWO_PI = 2.0 * math.pi
METHODS = ("auto", "LSODA", "Radau", "BDF")
AUTO_STIFFNESS_LIMIT = 16.0  # ω_max Δt above which "auto" picks Radau over LSODA
SWITCHES = ("contact", "seat", "valve open")
ZENO_RUN = 50  # consecutive switches closer than min_event_interval that count as chattering
TABLE_REFINEMENT = 16  # lift-table nodes per output sample
_trapezoid = getattr(np, "trapezoid", None) or np.trapz  # numpy >= 2.0 / 1.26

# Ferrarese & Uehara Table 1 (global data) [kg, N/m]
TABLE1_MASSES = {"valve": 65.7e-3, "shim": 23.1e-3, "bucket": 48.0e-3}  # [kg]; Table 2 lumps 0.9 g less
_RETURN_SPRING, _PRESSURE_SPRING = 3.34e3, 13.35e3
# Table 2 (printed in kN/m; converted here): k_c = 1.05e3 kN/m, k_v = 1.31e4 kN/m, k1 = 1.25e5 kN/m, k2..k4 = 5.03e5 kN/m
_CONTACT_STIFFNESS, _CONTACT_DAMPING = 1.05e6, 635.0
_SEAT_STIFFNESS, _SEAT_DAMPING = 1.31e7, 963.0
_STEM_5DOF = (1.25e8, 5.03e8, 5.03e8, 5.03e8)
_MASSES_5DOF = (79.7e-3, 8.6e-3, 8.6e-3, 8.6e-3, 30.4e-3)
_MASSES_2DOF = (105.5e-3, 30.4e-3)
DEFAULT_PRELOAD = 250.0  # [N], typical installed load of a passenger-car bucket-tappet valve spring
DEFAULT_STEM_DAMPING_RATIO = 0.02


# ---------------------------------------------------------------------------------------------
# the valve train
# ---------------------------------------------------------------------------------------------

def _to_float_tuple(value, self_, field) -> tuple[float, ...]:
    try:
        items = tuple(float(v) for v in np.atleast_1d(np.asarray(value, dtype=float)).ravel())
    except (TypeError, ValueError):
        raise InputError(f"LumpedValveTrain.{field.name} = {value!r}: expected a sequence of numbers (SI)") from None
    return items


def _to_float(value, self_, field) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        raise InputError(f"LumpedValveTrain.{field.name} = {value!r}: expected a number (SI)") from None


def _to_optional_float_tuple(value, self_, field):
    return None if value is None else _to_float_tuple(value, self_, field)


_tuple = attrs.Converter(_to_float_tuple, takes_self=True, takes_field=True)
_float = attrs.Converter(_to_float, takes_self=True, takes_field=True)
_optional_tuple = attrs.Converter(_to_optional_float_tuple, takes_self=True, takes_field=True)


def _check(name: str, values, unit: str, *, strict: bool) -> None:
    """Every value finite and > 0 (strict) or >= 0; the message names field, value and range."""
    arr = np.atleast_1d(np.asarray(values, dtype=float))
    bad = ~np.isfinite(arr) | ((arr <= 0.0) if strict else (arr < 0.0))
    if np.any(bad):
        index = int(np.flatnonzero(bad)[0])
        what = f"{values!r}" if arr.size == 1 else f"{values!r} (entry {index}: {arr[index]!r})"
        allowed = "> 0" if strict else ">= 0"
        raise InputError(f"LumpedValveTrain.{name} = {what}: must be finite and {allowed} [{unit}]")


@attrs.frozen(kw_only=True)
class LumpedValveTrain:
    """A valve train lumped into a chain of masses, with unilateral cam and seat contacts.

    SI floats throughout. Mass 1 is on the cam side (bucket tappet + shim), the last mass is the
    valve head; see the module docstring for the topology and the sign conventions (x > 0 opens
    the valve).

    Parameters
    ----------
    masses : sequence of float
        m_1 … m_n [kg] (> 0), cam side first.
    stem_stiffness : sequence of float
        k_1 … k_{n−1} [N/m] (> 0): the spring between masses i and i+1 (length n − 1).
    contact_stiffness, contact_damping : float
        k_c [N/m] (> 0), c_c [N s/m] (>= 0) of the cam–tappet contact between the lift y and
        mass 1. Unilateral: N = max(k_c (y − x_1) + c_c (ẏ − ẋ_1), 0) while y − x_1 > 0, else 0.
    seat_stiffness, seat_damping : float
        k_v [N/m] (> 0), c_v [N s/m] (>= 0) of the valve seat acting on the last mass while it
        is seated (x_n < 0); the seat pushes only (towards +x).
    return_spring_stiffness : float
        k_r [N/m] (>= 0) of the valve (return) spring acting on mass 1.
    return_spring_preload : float
        F_r0 [N] (>= 0), the spring force with the valve closed: the spring force on mass 1 is
        −(F_r0 + k_r x_1). Default 250 N (not given by the paper; see :meth:`ferrarese_2dof`).
    pressure_spring_stiffness : float
        k_p [N/m] (>= 0): the paper's "pressure spring" for the gas under the valve head,
        force −k_p x_n on the last mass while the valve is open (x_n > 0).
    stem_damping : sequence of float, optional
        c_s,1 … c_s,n−1 [N s/m] (>= 0) in parallel with the stem springs. Default (None):
        c_s,i = 2 ζ_s sqrt(k_i μ_i), μ_i = m_i m_{i+1}/(m_i + m_{i+1}) the reduced mass of the
        two neighbours, with ζ_s = ``stem_damping_ratio``.
    stem_damping_ratio : float
        ζ_s [-] (0 <= ζ_s <= 1) for the default stem damping; default 0.02 (2 %, the usual order
        of structural damping of steel valve-train members). The paper gives no stem damping;
        without it the stem modes (kHz to tens of kHz) ring undamped for the whole simulation.
    name : str

    Notes
    -----
    Static deflection on the base circle (zero lash, valve seated): mass 1 is held by the
    contact (k_c, to the cam) in parallel with the stem–seat chain
    k_chain = (Σ 1/k_i + 1/k_v)^−1, so the preload divides between them,
    N_0 = F_r0 k_c / (k_c + k_r + k_chain). With the valve open and the follower on the cam,
    quasi-statically N = (F_r0 + k_e y)/(1 + k_e/k_c), k_e = k_r + (1/k_p + Σ 1/k_i)^−1.
    """

    masses: tuple = attrs.field(converter=_tuple)
    stem_stiffness: tuple = attrs.field(default=(), converter=_tuple)
    contact_stiffness: float = attrs.field(converter=_float)
    contact_damping: float = attrs.field(default=0.0, converter=_float)
    seat_stiffness: float = attrs.field(converter=_float)
    seat_damping: float = attrs.field(default=0.0, converter=_float)
    return_spring_stiffness: float = attrs.field(converter=_float)
    return_spring_preload: float = attrs.field(default=DEFAULT_PRELOAD, converter=_float)
    pressure_spring_stiffness: float = attrs.field(default=0.0, converter=_float)
    stem_damping: tuple | None = attrs.field(default=None, converter=_optional_tuple)
    stem_damping_ratio: float = attrs.field(default=DEFAULT_STEM_DAMPING_RATIO, converter=_float)
    name: str = "lumped valve train"

    def __attrs_post_init__(self) -> None:
        if len(self.masses) < 1:
            raise InputError("LumpedValveTrain.masses = (): give at least one mass [kg]")
        _check("masses", self.masses, "kg", strict=True)
        n = len(self.masses)
        if len(self.stem_stiffness) != n - 1:
            raise InputError(
                f"LumpedValveTrain.stem_stiffness = {self.stem_stiffness!r}: {len(self.stem_stiffness)} values for "
                f"{n} masses; expected {n - 1} (one spring between each pair of consecutive masses) [N/m]"
            )
        if n > 1:
            _check("stem_stiffness", self.stem_stiffness, "N/m", strict=True)
        _check("contact_stiffness", self.contact_stiffness, "N/m", strict=True)
        _check("seat_stiffness", self.seat_stiffness, "N/m", strict=True)
        _check("contact_damping", self.contact_damping, "N*s/m", strict=False)
        _check("seat_damping", self.seat_damping, "N*s/m", strict=False)
        _check("return_spring_stiffness", self.return_spring_stiffness, "N/m", strict=False)
        _check("return_spring_preload", self.return_spring_preload, "N", strict=False)
        _check("pressure_spring_stiffness", self.pressure_spring_stiffness, "N/m", strict=False)
        if self.stem_damping is not None:
            if len(self.stem_damping) != n - 1:
                raise InputError(
                    f"LumpedValveTrain.stem_damping = {self.stem_damping!r}: {len(self.stem_damping)} values for "
                    f"{n} masses; expected {n - 1} [N*s/m] (or None for the default)"
                )
            if n > 1:
                _check("stem_damping", self.stem_damping, "N*s/m", strict=False)
        if not (0.0 <= self.stem_damping_ratio <= 1.0):
            raise InputError(
                f"LumpedValveTrain.stem_damping_ratio = {self.stem_damping_ratio!r}: allowed 0 <= ratio <= 1 [-]"
            )

    # -- parameter sets of the paper -------------------------------------------------------------

    @classmethod
    def ferrarese_2dof(cls, return_spring_preload: float = DEFAULT_PRELOAD, **overrides) -> LumpedValveTrain:
        """The 2-DOF model of Ferrarese & Uehara, Table 2 (with Table 1's springs).

        m_1 = 105.5 g (bucket 48.0 + shim 23.1 + four stem segments of 8.6 g), m_2 = 30.4 g
        (valve head with the lowest part of the stem). k_c = 1.05e3 kN/m = 1.05e6 N/m, c_c = 635 N s/m,
        k_v = 1.31e4 kN/m = 1.31e7 N/m, c_v = 963 N s/m (the table prints stiffnesses in kN/m),
        k_r = 3.34e3 N/m, k_p = 13.35e3 N/m (Table 1).

        Parameters
        ----------
        return_spring_preload : float
            F_r0 [N]. The paper gives none; 250 N is a typical installed load of a
            passenger-car bucket-tappet valve spring (range about 200–300 N).
        **overrides
            Any other field (e.g. ``return_spring_stiffness=2e4``).

        Notes
        -----
        *Stem stiffness.* The 2-DOF stem stiffness is not printed. It is taken as the series
        combination of the 5-DOF stem, 1/k = Σ 1/k_i = 1/1.25e8 + 3/5.03e8, k = 7.161e7 N/m, so
        both models have the same static compliance between tappet and valve head (the same
        quasi-static contact force). Another reading — the 2-DOF as the 5-DOF with m_1…m_4 rigidly
        merged — would keep only k_4 = 5.03e8 N/m; that changes only the second natural frequency
        (stem mode, 8.8 kHz vs 23 kHz), far above the cam harmonics.

        *Masses.* Both models lump the same 135.9 g: 2-DOF m_1 = 5-DOF m_1 + m_2 + m_3 + m_4
        (79.7 + 3 × 8.6 = 105.5 g) and m_2 = m_5 = 30.4 g; 5-DOF m_1 = bucket + shim + one stem
        segment = 48.0 + 23.1 + 8.6 = 79.7 g. Table 1's components sum to 136.8 g
        (valve 65.7 + shim 23.1 + bucket 48.0): the lumped valve is 4 × 8.6 + 30.4 = 64.8 g, 0.9 g
        (1.4 % of the valve, 0.7 % of the total) short of 65.7 g — a rounding of the segment
        masses or a misprint in the paper; the printed Table 2 masses are used as they are.

        *Magnitudes.* Natural frequencies (follower on the cam): valve open 446 Hz and 8.77 kHz;
        valve seated 1.55 kHz and 9.25 kHz (:meth:`natural_frequencies`), above the first cam
        harmonics at 3000 rpm (50 Hz) as a valve train should be. Static deflections at
        F_r0 = 250 N: cam contact 0.24 mm, stem 3.5 µm, seat 17 µm. The contact element is
        heavily damped: ζ_c = c_c/(2 sqrt(k_c m_1)) = 0.95 (1.10 on the 5-DOF's 79.7 g), the seat
        ζ_v = 0.76 on m_2. k_c = 1.05e6 N/m is far softer than a steel Hertz line contact
        (~1e8–1e9 N/m) and must lump camshaft, bearing and tappet compliance; k_r = 3.34 N/mm is
        about ten times softer than a production valve spring (F_r0/k_r = 75 mm would be its
        installed compression), which is why the preload is an independent field.
        """
        return cls._ferrarese(_MASSES_2DOF, (1.0 / sum(1.0 / k for k in _STEM_5DOF),), "Ferrarese & Uehara 2-DOF",
                              return_spring_preload, overrides)

    @classmethod
    def ferrarese_5dof(cls, return_spring_preload: float = DEFAULT_PRELOAD, **overrides) -> LumpedValveTrain:
        """The 5-DOF model of Ferrarese & Uehara, Table 2 (with Table 1's springs).

        m = (79.7, 8.6, 8.6, 8.6, 30.4) g; stem k_1 = 1.25e5 kN/m = 1.25e8 N/m between m_1 and
        m_2, k_2 = k_3 = k_4 = 5.03e5 kN/m = 5.03e8 N/m between m_2…m_5. The table prints the
        contact and seat elements (k_c, c_c, k_v, c_v) in the 2-DOF column only; the 5-DOF model
        uses the same elements. Return and pressure springs from Table 1, as
        :meth:`ferrarese_2dof` (see there for the preload default and the mass bookkeeping).

        Notes
        -----
        Stem segment stiffness EA/L = 5.03e8 N/m is a 6 mm steel stem about 12 mm long, and the
        whole stem in series (7.16e7 N/m) about 80 mm long: the kN/m reading of the table gives
        the right magnitudes (the printed numbers in N/m would be a stem a thousand times too
        soft). Natural frequencies (follower on the cam): valve open 446 Hz, 8.23, 25.9, 50.9 and
        70.0 kHz; valve seated 1.57, 8.53, 26.0, 50.9 and 70.0 kHz (:meth:`natural_frequencies`),
        the first as the 2-DOF model's. The stem modes make the ODE stiff (see :func:`simulate`,
        ``method="auto"``).
        """
        return cls._ferrarese(_MASSES_5DOF, _STEM_5DOF, "Ferrarese & Uehara 5-DOF", return_spring_preload, overrides)

    @classmethod
    def _ferrarese(cls, masses, stem_stiffness, name, return_spring_preload, overrides) -> LumpedValveTrain:
        """A model with the paper's contact, seat and spring elements (Tables 1 and 2), then ``overrides``."""
        fields = dict(
            masses=masses, stem_stiffness=stem_stiffness, contact_stiffness=_CONTACT_STIFFNESS,
            contact_damping=_CONTACT_DAMPING, seat_stiffness=_SEAT_STIFFNESS, seat_damping=_SEAT_DAMPING,
            return_spring_stiffness=_RETURN_SPRING, return_spring_preload=return_spring_preload,
            pressure_spring_stiffness=_PRESSURE_SPRING, name=name,
        )
        fields.update(overrides)
        return cls(**fields)

    # -- derived quantities -------------------------------------------------------------------

    @property
    def n_masses(self) -> int:
        """Number of masses (degrees of freedom) n."""
        return len(self.masses)

    @property
    def total_mass(self) -> float:
        """Σ m_i [kg]."""
        return float(sum(self.masses))

    @property
    def stem_damping_coefficients(self) -> np.ndarray:
        """c_s,i [N s/m]: ``stem_damping`` or the default 2 ζ_s sqrt(k_i μ_i)."""
        if self.stem_damping is not None:
            return np.asarray(self.stem_damping, dtype=float)
        m = np.asarray(self.masses)
        k = np.asarray(self.stem_stiffness)
        reduced = m[:-1] * m[1:] / (m[:-1] + m[1:])
        return 2.0 * self.stem_damping_ratio * np.sqrt(k * reduced)

    @property
    def series_stem_stiffness(self) -> float:
        """(Σ 1/k_i)^−1 [N/m], the stem from mass 1 to the head as one spring (inf for n = 1)."""
        if not self.stem_stiffness:
            return math.inf
        return 1.0 / sum(1.0 / k for k in self.stem_stiffness)

    def system_matrices(self, *, contact: bool = True, seated: bool = False,
                        pressure: bool | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Mass, damping and stiffness matrices M [kg], C [N s/m], K [N/m] of one contact state.

        Parameters
        ----------
        contact : bool
            Follower on the cam (adds k_c, c_c to mass 1).
        seated : bool
            Valve on its seat (adds k_v, c_v to the last mass).
        pressure : bool, optional
            Pressure spring active (adds k_p to the last mass); default ``not seated``.
        """
        n = self.n_masses
        pressure = (not seated) if pressure is None else pressure
        M = np.diag(np.asarray(self.masses, dtype=float))
        K = np.zeros((n, n))
        C = np.zeros((n, n))
        cs = self.stem_damping_coefficients
        for i, (k, c) in enumerate(zip(self.stem_stiffness, cs)):
            for mat, value in ((K, k), (C, c)):
                mat[i, i] += value
                mat[i + 1, i + 1] += value
                mat[i, i + 1] -= value
                mat[i + 1, i] -= value
        K[0, 0] += self.return_spring_stiffness
        if contact:
            K[0, 0] += self.contact_stiffness
            C[0, 0] += self.contact_damping
        if seated:
            K[-1, -1] += self.seat_stiffness
            C[-1, -1] += self.seat_damping
        if pressure:
            K[-1, -1] += self.pressure_spring_stiffness
        return M, C, K

    def natural_frequencies(self, *, contact: bool = True, seated: bool = False) -> np.ndarray:
        """Undamped natural frequencies f_j = ω_j/(2π) [Hz] of one contact state, ascending.

        Eigenvalues of M^−1 K with the elements of that state (pressure spring on when not
        seated). With ``contact=False`` and the valve open the chain floats on the soft springs.

        >>> train = LumpedValveTrain.ferrarese_2dof()
        >>> [round(float(f)) for f in train.natural_frequencies()]
        [446, 8771]
        """
        M, _, K = self.system_matrices(contact=contact, seated=seated)
        m_half = 1.0 / np.sqrt(np.diag(M))
        eig = np.linalg.eigvalsh(K * m_half[:, None] * m_half[None, :])
        return np.sqrt(np.clip(eig, 0.0, None)) / TWO_PI

    def static_equilibrium(self, lift: float = 0.0) -> StaticEquilibrium:
        """Static equilibrium with the cam held at lift y [m] (follower on the cam).

        Solves the piecewise-linear statics: valve seated if the seated solution has x_n <= 0,
        else open (pressure spring on). On the base circle (y = 0) the preload passes through
        the chain: N_0 = F_r0 k_c/(k_c + k_r + k_chain) (see the class notes).
        """
        y = float(lift)
        if not math.isfinite(y):
            raise InputError(f"LumpedValveTrain.static_equilibrium: lift = {lift!r} must be finite [m]")
        force = np.zeros(self.n_masses)
        force[0] = self.contact_stiffness * y - self.return_spring_preload
        for seated in (True, False):
            _, _, K = self.system_matrices(contact=True, seated=seated)
            x = np.linalg.solve(K, force)
            if seated and x[-1] <= 0.0:
                break
            if not seated and x[-1] >= 0.0:
                break
        else:  # pragma: no cover - the two states cover every lift for k >= 0, F_r0 >= 0
            raise ConvergenceError(f"{self.name}: no consistent static state at lift {y!r} m")
        penetration = y - x[0]
        if penetration < 0.0:
            raise InputError(
                f"LumpedValveTrain.static_equilibrium: lift = {y!r} m leaves the follower off the cam "
                "(negative lift below the base circle?)"
            )
        contact_force = self.contact_stiffness * penetration
        seat_force = -self.seat_stiffness * x[-1] if seated else 0.0
        return StaticEquilibrium(displacement=x, contact_force=float(contact_force), seat_force=float(seat_force),
                                 seated=seated)


@attrs.frozen(eq=False)
class StaticEquilibrium:
    """Static state: displacements x [m] (per mass), contact force N [N], seat force [N], seated flag."""

    displacement: np.ndarray
    contact_force: float
    seat_force: float
    seated: bool


# ---------------------------------------------------------------------------------------------
# the response
# ---------------------------------------------------------------------------------------------

@attrs.frozen(eq=False)
class SolverRecord:
    """How a :func:`simulate` run went: method, wall time [s], segments, events, RHS calls."""

    method: str
    wall_time: float
    segments: int
    events: int
    rhs_evaluations: int
    rtol: float
    atol: np.ndarray


@attrs.frozen(eq=False)
class ValveTrainResponse:
    """Time response of a :class:`LumpedValveTrain` over whole cam revolutions.

    Arrays are sampled on a uniform cam-angle grid plus the instants of the contact events
    (at an event the arrays hold the values just after the switch). 2-D arrays are
    (time, mass), mass 1 (cam side) first. "Open"/"seated" are geometric, the forces are the
    Kelvin–Voigt forces (which can vanish before a gap opens; see the module notes).

    Attributes
    ----------
    train : LumpedValveTrain
    speed : float
        Cam speed ω [rad/s].
    cycles : int
        Cam revolutions simulated.
    time : ndarray
        t [s], from 0.
    angle : ndarray
        Cam angle θ = θ_0 + ω t [rad], unwrapped.
    lift, lift_velocity, lift_acceleration : ndarray
        y [m], ẏ = ω y' [m/s], ÿ = ω² y'' [m/s²] of the cam.
    displacement, velocity : ndarray
        x [m], ẋ [m/s] per mass, shape (time, n).
    contact_force : ndarray
        N [N] between cam and mass 1 (>= 0).
    seat_force : ndarray
        Seat force on the valve head [N] (>= 0); zero whenever the valve is off its seat.
    contact_open : ndarray of bool
        Follower off the cam: gap x_1 − y >= 0 with the contact unloaded.
    seated : ndarray of bool
        Valve on its seat, x_n <= 0 (to within the switch hysteresis, ~1e-14 m).
    jumps : pandas.DataFrame
        One row per separation of follower and cam (a gap opens): "cycle", "start angle [deg]",
        "end angle [deg]" (unwrapped), "duration [s]", "max gap [m]", "complete" (False when
        the run ended with the gap still open; the end is then the last instant).
    seat_bounces : pandas.DataFrame
        One row per lift-off of the valve from its seat that the cam did not drive (the valve
        leaves the seat while the cam lift is not rising, ẏ <= 0: a rebound at closing or a
        jump-driven opening); columns as ``jumps`` with "max lift [m]".
    events : pandas.DataFrame
        Every switch in time order: "time [s]", "angle [deg]", "switch", "active". Switches:
        "contact" (cam force loaded/unloaded), "gap" (follower separates from / lands on the
        cam), "seat" (seat force loaded/unloaded), "valve open" (x_n > 0 / back on the seat).
    record : SolverRecord
    """

    train: LumpedValveTrain
    speed: float
    cycles: int
    time: np.ndarray
    angle: np.ndarray
    lift: np.ndarray
    lift_velocity: np.ndarray
    lift_acceleration: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    contact_force: np.ndarray
    seat_force: np.ndarray
    contact_open: np.ndarray
    seated: np.ndarray
    jumps: object
    seat_bounces: object
    events: object
    record: SolverRecord

    @property
    def period(self) -> float:
        """Cam period 2π/ω [s]."""
        return TWO_PI / self.speed

    @property
    def jumped(self) -> bool:
        """True if the follower left the cam at least once."""
        return len(self.jumps) > 0

    def to_frame(self):
        """DataFrame with one row per instant, columns ``"name [unit]"`` (SI).

        Columns: "time [s]", "angle [deg]", "lift [m]", "lift velocity [m/s]",
        "lift acceleration [m/s²]", "x1 [m]" … "xn [m]", "v1 [m/s]" … "vn [m/s]", "N [N]",
        "seat force [N]", "contact open [-]", "seated [-]".
        """
        import pandas as pd

        columns = {
            "time [s]": self.time,
            "angle [deg]": np.degrees(self.angle),
            "lift [m]": self.lift,
            "lift velocity [m/s]": self.lift_velocity,
            "lift acceleration [m/s²]": self.lift_acceleration,
        }
        for i in range(self.displacement.shape[1]):
            columns[f"x{i + 1} [m]"] = self.displacement[:, i]
        for i in range(self.velocity.shape[1]):
            columns[f"v{i + 1} [m/s]"] = self.velocity[:, i]
        columns["N [N]"] = self.contact_force
        columns["seat force [N]"] = self.seat_force
        columns["contact open [-]"] = self.contact_open
        columns["seated [-]"] = self.seated
        return pd.DataFrame(columns)

    _ALIASES = {"N": "contact_force", "contact_force": "contact_force", "N [N]": "contact_force",
                "seat_force": "seat_force", "seat force [N]": "seat_force"}

    def cycle_mean(self, quantity, *, skip_cycles: int = 0) -> float:
        """Integral mean over the simulated whole cycles: (1/T) ∫ q dt, trapezoid in time.

        Parameters
        ----------
        quantity : str or array_like
            A name ("N"/"contact_force", "seat_force", or a column of :meth:`to_frame`) or an
            array with one value per instant of ``time`` (e.g. friction power computed from N).
        skip_cycles : int
            Leave out the first cycles (start transient); at least one cycle must remain.

        Returns
        -------
        float
            The mean over [skip_cycles T, cycles T], T the cam period, in the unit of the quantity.
        """
        if isinstance(quantity, str):
            attribute = self._ALIASES.get(quantity)
            if attribute is not None:
                values = getattr(self, attribute)
            else:
                frame = self.to_frame()
                if quantity not in frame.columns:
                    raise InputError(
                        f"ValveTrainResponse.cycle_mean: quantity = {quantity!r} is not one of "
                        f"{sorted(set(self._ALIASES) | set(frame.columns))}"
                    )
                values = frame[quantity].to_numpy(dtype=float)
        else:
            values = np.asarray(quantity, dtype=float)
            if values.shape != self.time.shape:
                raise InputError(
                    f"ValveTrainResponse.cycle_mean: quantity has shape {values.shape}; expected one value per "
                    f"instant, shape {self.time.shape}"
                )
        if not (isinstance(skip_cycles, (int, np.integer)) and 0 <= skip_cycles < self.cycles):
            raise InputError(
                f"ValveTrainResponse.cycle_mean: skip_cycles = {skip_cycles!r}; allowed 0 <= skip_cycles < "
                f"{self.cycles} (an integer)"
            )
        start = skip_cycles * self.period
        keep = self.time >= start - 1e-9 * self.period
        t = self.time[keep]
        q = np.asarray(values, dtype=float)[keep]
        if not np.all(np.isfinite(q)):
            raise InputError("ValveTrainResponse.cycle_mean: the quantity has non-finite values")
        return float(_trapezoid(q, t) / (t[-1] - t[0]))


# ---------------------------------------------------------------------------------------------
# simulation
# ---------------------------------------------------------------------------------------------

def _lift_callable(lift) -> Callable:
    if callable(lift):
        return lift
    evaluate = getattr(lift, "evaluate", None)
    if callable(evaluate):
        return evaluate
    raise InputError(
        f"simulate: lift = {lift!r}: expected a callable θ [rad] -> (y [m], dy/dθ [m/rad], d²y/dθ² [m/rad²], ...)"
    )


def _evaluate_lift(fn, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    try:
        out = fn(theta)
        parts = [np.asarray(out[i], dtype=float) for i in range(3)]
    except InputError:
        raise
    except (TypeError, IndexError, KeyError, ValueError) as exc:
        raise InputError(
            f"simulate: lift({type(theta).__name__}) must return at least 3 arrays (y [m], dy/dθ [m/rad], "
            f"d²y/dθ² [m/rad²]); calling it failed: {exc}"
        ) from exc
    for name, part in zip(("y", "dy/dθ", "d²y/dθ²"), parts):
        if part.shape != theta.shape:
            part = np.broadcast_to(part, theta.shape) if part.size in (1, theta.size) else part
            if part.shape != theta.shape:
                raise InputError(f"simulate: lift returned {name} of shape {part.shape}; expected {theta.shape}")
        if not np.all(np.isfinite(part)):
            raise InputError(f"simulate: lift returned non-finite {name} values")
    return tuple(np.reshape(p, theta.shape).astype(float) for p in parts)


class _HermiteLift:
    """y(t) [m] and ẏ(t) [m/s] of the cam from a quintic Hermite table of one revolution.

    The lift callable is evaluated once, vectorised, at ``points`` angles per revolution
    (phase-locked to the output grid, so output instants are nodes); between nodes the quintic
    Hermite polynomial matches y, y' and y'' at both ends (error O(h⁶ y⁽⁶⁾) on smooth stretches,
    O(h² Δy'') across a jump of y''). This keeps Python calls of the lift out of the ODE's
    right-hand side; the polynomial coefficients live in Python lists for fast scalar lookup.
    """

    def __init__(self, fn, theta0: float, omega: float, points: int):
        self.theta0, self.omega, self.points = theta0, omega, points
        self.h = TWO_PI / points
        phi = np.arange(points + 1) * self.h
        y, d1, d2 = _evaluate_lift(fn, np.mod(theta0 + phi, TWO_PI))
        h = self.h
        p0, p1 = y[:-1], y[1:]
        v0, v1 = h * d1[:-1], h * d1[1:]
        a0, a1 = h * h * d2[:-1], h * h * d2[1:]
        coef = np.column_stack([
            p0, v0, 0.5 * a0,
            -10.0 * p0 - 6.0 * v0 - 1.5 * a0 + 0.5 * a1 - 4.0 * v1 + 10.0 * p1,
            15.0 * p0 + 8.0 * v0 + 1.5 * a0 - a1 + 7.0 * v1 - 15.0 * p1,
            -6.0 * p0 - 3.0 * v0 - 0.5 * a0 + 0.5 * a1 - 3.0 * v1 + 6.0 * p1,
        ])
        self.coef = coef.tolist()
        self.last_t = math.nan
        self.last = (0.0, 0.0)

    def __call__(self, t: float) -> tuple[float, float]:
        """(y [m], ẏ [m/s]) at time t [s]."""
        if t == self.last_t:
            return self.last
        u = (self.omega * t) % TWO_PI / self.h
        i = int(u)
        if i >= self.points:
            i = self.points - 1
        s = u - i
        c0, c1, c2, c3, c4, c5 = self.coef[i]
        y = c0 + s * (c1 + s * (c2 + s * (c3 + s * (c4 + s * c5))))
        dy = (c1 + s * (2.0 * c2 + s * (3.0 * c3 + s * (4.0 * c4 + s * 5.0 * c5)))) * (self.omega / self.h)
        self.last_t, self.last = t, (y, dy)
        return self.last


def _positive_int(value, name: str, minimum: int) -> int:
    if (isinstance(value, bool) or not isinstance(value, (int, np.integer, float)) or not math.isfinite(value)
            or float(value) != int(value)):
        raise InputError(f"simulate: {name} = {value!r}: expected an integer >= {minimum}")
    if int(value) < minimum:
        raise InputError(f"simulate: {name} = {value!r}: allowed {name} >= {minimum}")
    return int(value)


def simulate(
    train: LumpedValveTrain,
    lift,
    speed: float,
    cycles: int = 2,
    points_per_cycle: int = 720,
    method: str = "auto",
    rtol: float = 1e-6,
    atol=None,
    *,
    start_angle: float = 0.0,
    max_events: int | None = None,
    min_event_interval: float = 1e-9,
) -> ValveTrainResponse:
    """Integrate a lumped valve train over whole cam revolutions at constant cam speed.

    Parameters
    ----------
    train : LumpedValveTrain
    lift : callable
        θ [rad] (array) -> (y [m], dy/dθ [m/rad], d²y/dθ² [m/rad²], ...): at least three arrays
        of the shape of θ, e.g. ``MotionProgram.evaluate``; an object with an ``evaluate``
        method is accepted too. Called with θ wrapped to [0, 2π). The lift is measured above the
        base circle (y = 0 on it).
    speed : float
        Cam angular speed ω [rad/s] (> 0), constant.
    cycles : int
        Cam revolutions to integrate (>= 1).
    points_per_cycle : int
        Output samples per revolution (>= 8), uniform in cam angle; event instants are added.
        The solver step is also limited to one sample interval.
    method : {"auto", "LSODA", "Radau", "BDF"}
        Method of :func:`scipy.integrate.solve_ivp`, each given the exact constant Jacobian of
        the current contact state. The stem modes make the system stiff; LSODA (which starts
        non-stiff and switches itself) is fastest while the highest natural frequency is
        moderate, Radau (L-stable) when it is far above the output rate. ``"auto"`` picks LSODA
        if ω_max Δt < 16 (ω_max the highest natural frequency [rad/s], seated or open, Δt the
        output interval), else Radau. Measured with the Ferrarese sets over 2 cycles: 2-DOF
        (ω_max Δt = 1.6 at 3000 rpm, 9.7 at 500 rpm) LSODA 0.3–1.0 s vs Radau 1.1–2.4 s; 5-DOF
        (12 and 73) LSODA 2.3 s and 7.9 s vs Radau 3.5 s and 2.1 s. BDF is slow on the lightly
        damped stem modes (orders > 2 are not A-stable) and only offered for comparison.
    rtol : float
        Relative tolerance (> 0).
    atol : float or array_like, optional
        Absolute tolerance; default 1e-10 m on displacements and 1e-7 m/s on velocities.
        An array has one value per state (n displacements, then n velocities).
    start_angle : float
        θ_0 [rad] at t = 0; it should lie on the base circle (dwell).
    max_events : int, optional
        Most switches (see ``ValveTrainResponse.events``) allowed (default 500 per cycle) before
        :class:`~camcontact.errors.ConvergenceError` (chattering).
    min_event_interval : float
        [s] More than ``ZENO_RUN`` = 50 consecutive switches each closer than this to the previous one are taken
        as Zeno chattering: ConvergenceError.

    Returns
    -------
    ValveTrainResponse

    Raises
    ------
    InputError
        Bad arguments (speed <= 0, cycles < 1, a lift callable of the wrong shape, ...).
    ConvergenceError
        The solver failed, chattered, or produced non-finite values.

    Notes
    -----
    The run starts from the static equilibrium at y(θ_0) (on the base circle: valve seated,
    the preload shared between the cam contact and the stem–seat chain), with every mass moving
    at the cam's velocity ω y'(θ_0) (zero on the base circle). Between events the system is linear,
    ż = A z + b(t), with A constant; events end a segment where a force element loads or unloads
    (h = min(k δ, k δ + c δ̇) crosses ±ε, ε = 1e-9 max(F_r0, 1 N)) or the valve passes x_n = 0,
    and the next segment restarts from the event state with the new A. The opening and closing
    of a geometric gap at the cam are located by non-terminal events (no restart). The lift is
    tabulated once and interpolated by quintic Hermite polynomials inside the right-hand side
    (``TABLE_REFINEMENT`` nodes per output sample); for the cycloidal test cam the interpolated
    y is exact to 1e-16 m and ẏ to 1e-10 m/s.
    """
    if not isinstance(train, LumpedValveTrain):
        raise InputError(f"simulate: train = {train!r}: expected a LumpedValveTrain")
    fn = _lift_callable(lift)
    try:
        omega = float(speed)
    except (TypeError, ValueError):
        raise InputError(f"simulate: speed = {speed!r}: expected a number ω [rad/s]") from None
    if not (math.isfinite(omega) and omega > 0.0):
        raise InputError(f"simulate: speed = {speed!r}: cam speed ω must be finite and > 0 [rad/s]")
    cycles = _positive_int(cycles, "cycles", 1)
    points_per_cycle = _positive_int(points_per_cycle, "points_per_cycle", 8)
    if method not in METHODS:
        raise InputError(f"simulate: method = {method!r}; allowed: {', '.join(METHODS)} (the system is stiff)")
    rtol = float(rtol)
    if not (math.isfinite(rtol) and rtol > 0.0):
        raise InputError(f"simulate: rtol = {rtol!r}: must be > 0")
    n = train.n_masses
    if atol is None:
        atol_arr = np.concatenate([np.full(n, 1e-10), np.full(n, 1e-7)])
    else:
        atol_arr = np.broadcast_to(np.asarray(atol, dtype=float), (2 * n,)).copy() if np.size(atol) in (1, 2 * n) \
            else None
        if atol_arr is None or not np.all(np.isfinite(atol_arr) & (atol_arr > 0.0)):
            raise InputError(f"simulate: atol = {atol!r}: must be > 0, a number or {2 * n} values")
    theta0 = float(start_angle)
    if not math.isfinite(theta0):
        raise InputError(f"simulate: start_angle = {start_angle!r}: must be finite [rad]")
    max_events = 500 * cycles if max_events is None else _positive_int(max_events, "max_events", 0)
    min_event_interval = float(min_event_interval)
    if not (min_event_interval >= 0.0):
        raise InputError(f"simulate: min_event_interval = {min_event_interval!r}: must be >= 0 [s]")

    wall_start = _time.perf_counter()
    period = TWO_PI / omega
    t_end = cycles * period
    n_grid = cycles * points_per_cycle + 1
    t_grid = np.linspace(0.0, t_end, n_grid)
    dt_grid = t_grid[1] - t_grid[0]
    if method == "auto":
        highest = TWO_PI * max(float(train.natural_frequencies(seated=True)[-1]),
                               float(train.natural_frequencies(seated=False)[-1]))
        method = "LSODA" if highest * dt_grid < AUTO_STIFFNESS_LIMIT else "Radau"
    y_grid, dy_grid, ddy_grid = _evaluate_lift(fn, np.mod(theta0 + omega * t_grid, TWO_PI))

    # -- constants of the model ------------------------------------------------------------------
    kc, cc = train.contact_stiffness, train.contact_damping
    kv, cv = train.seat_stiffness, train.seat_damping
    preload = train.return_spring_preload
    eps = 1e-9 * max(preload, 1.0)
    # hysteresis per switch [N]; the valve-open switch's is half the seat's so that "valve reaches
    # x_n = 0" and "seat engages" never fall on the same instant
    hysteresis = (eps, eps, 0.5 * eps)
    use_pressure = train.pressure_spring_stiffness > 0.0
    inv_m = 1.0 / np.asarray(train.masses, dtype=float)
    systems: dict[tuple[bool, bool, bool], np.ndarray] = {}

    def system(modes):
        A = systems.get(modes)
        if A is None:
            M, C, K = train.system_matrices(contact=modes[0], seated=modes[1], pressure=modes[2] and use_pressure)
            A = np.zeros((2 * n, 2 * n))
            A[:n, n:] = np.eye(n)
            A[n:, :n] = -K * inv_m[:, None]
            A[n:, n:] = -C * inv_m[:, None]
            systems[modes] = A
        return A

    lift_at = _HermiteLift(fn, theta0, omega, TABLE_REFINEMENT * points_per_cycle)

    def h_contact(t, z):
        y, dy = lift_at(t)
        d, dd = y - z[0], dy - z[n]
        return min(kc * d, kc * d + cc * dd)

    def h_seat(t, z):
        return min(-kv * z[n - 1], -kv * z[n - 1] - cv * z[2 * n - 1])

    def h_valve_open(t, z):
        return kv * z[n - 1]

    def h_gap(t, z):
        return kc * (lift_at(t)[0] - z[0])

    switch_functions = (h_contact, h_seat, h_valve_open)

    def switch_values(t, z):
        """h of each switch (> 0: active) [N]."""
        return tuple(h(t, z) for h in switch_functions)

    def make_event(h, offset, direction, terminal):
        memo: dict[float, float] = {}

        def event(t, z):
            # solve_ivp first calls an event at each step end with the solver's own state, and later
            # brackets the root with the dense output at the same two instants; the interpolant can
            # differ from the stored state (LSODA), flip the sign near 0 and make brentq fail. The
            # memo returns the value of the first call at an instant, so the bracket is the one detected.
            value = memo.get(t)
            if value is None:
                value = h(t, z) + offset
                if len(memo) > 8:
                    memo.clear()
                memo[t] = value
            return value

        event.terminal = terminal
        event.direction = direction
        return event

    # -- initial state: static equilibrium ----------------------------------------------------
    static = train.static_equilibrium(y_grid[0])
    z = np.concatenate([static.displacement, np.full(n, dy_grid[0] * omega)])
    modes = (True, static.seated, (not static.seated) and static.displacement[-1] > 0.0)
    modes = _consistent_modes(modes, switch_values(0.0, z), hysteresis)

    times = [np.array([0.0])]
    states = [z[:, None]]
    mode_rows = [np.array([modes])]
    event_rows: list[tuple[float, str, bool]] = []
    t = 0.0
    segments = 0
    nfev = 0
    close_run = 0
    tol_t = 1e-9 * dt_grid
    b0 = np.zeros(2 * n)
    b0[n] = -preload * inv_m[0]

    while True:
        A = system(modes)
        contact_on = modes[0]

        def rhs(tt, zz, A=A, contact_on=contact_on):
            out = A @ zz + b0
            if contact_on:
                y, dy = lift_at(tt)
                out[n] += (kc * y + cc * dy) * inv_m[0]
            return out

        events = [make_event(switch_functions[i], hysteresis[i] if modes[i] else -hysteresis[i],
                             -1.0 if modes[i] else 1.0, True) for i in range(3)]
        if not contact_on:  # the geometric gap y − x_1 < 0 opens and closes only while N = 0
            events.append(make_event(h_gap, 0.0, 0.0, False))
        t_eval = t_grid[t_grid > t + tol_t]
        segments += 1
        try:
            sol = solve_ivp(rhs, (t, t_end), z, method=method, t_eval=t_eval, events=events, rtol=rtol,
                            atol=atol_arr, jac=lambda tt, zz, A=A: A, max_step=dt_grid)
        except (ValueError, RuntimeError, ArithmeticError) as exc:
            raise ConvergenceError(f"simulate ({train.name}, ω = {omega:.6g} rad/s): solve_ivp failed at "
                                   f"t = {t:.6g} s: {exc}") from exc
        nfev += int(sol.nfev)
        if sol.status < 0:
            raise ConvergenceError(f"simulate ({train.name}, ω = {omega:.6g} rad/s): solve_ivp failed at "
                                   f"t = {t:.6g} s: {sol.message}")
        seg_t = np.asarray(sol.t, dtype=float)
        if seg_t.size:
            times.append(seg_t)
            states.append(np.asarray(sol.y, dtype=float).reshape(2 * n, seg_t.size))
            mode_rows.append(np.tile(np.array(modes), (seg_t.size, 1)))
        if not contact_on:  # gap openings/closings: recorded as instants, no restart
            for t_gap, z_gap in zip(np.atleast_1d(sol.t_events[3]), np.atleast_1d(sol.y_events[3])):
                z_gap = np.asarray(z_gap, dtype=float)
                opening = lift_at(float(t_gap))[1] - z_gap[n] < 0.0
                event_rows.append((float(t_gap), "gap", bool(opening)))
                if np.min(np.abs(t_grid - t_gap)) > tol_t:
                    times.append(np.array([float(t_gap)]))
                    states.append(z_gap[:, None])
                    mode_rows.append(np.array([modes]))
        if sol.status == 0:
            break

        # a terminal event: find it, switch, restart
        fired = [(te[-1], k) for k, te in enumerate(sol.t_events[:3]) if len(te)]
        t_event, k_first = max(fired)
        z_event = np.asarray(sol.y_events[k_first][-1], dtype=float)
        if not np.all(np.isfinite(z_event)):
            raise ConvergenceError(f"simulate ({train.name}): non-finite state at the event t = {t_event:.6g} s")
        new = list(modes)
        for te, k in fired:
            if abs(te - t_event) <= tol_t:
                new[k] = not new[k]
        new_modes = _consistent_modes(tuple(new), switch_values(t_event, z_event), hysteresis)
        for i in range(3):
            if new_modes[i] != modes[i]:
                event_rows.append((t_event, SWITCHES[i], new_modes[i]))
        close_run = close_run + 1 if t_event - t < min_event_interval else 0
        if close_run > ZENO_RUN:
            raise ConvergenceError(
                f"simulate ({train.name}, ω = {omega:.6g} rad/s): contact chattering (Zeno) near "
                f"θ = {math.degrees(theta0 + omega * t_event):.4f} deg: more than {ZENO_RUN} consecutive "
                f"switches within {min_event_interval:g} s of each other"
            )
        if len(event_rows) > max_events:
            raise ConvergenceError(
                f"simulate ({train.name}, ω = {omega:.6g} rad/s): more than max_events = {max_events} contact "
                f"switches by θ = {math.degrees(theta0 + omega * t_event):.4f} deg (chattering?); raise "
                "max_events if this is physical"
            )
        modes, t, z = new_modes, float(t_event), z_event
        if np.min(np.abs(t_grid - t)) > tol_t:
            times.append(np.array([t]))
            states.append(z[:, None])
            mode_rows.append(np.array([modes]))
        if t_end - t <= tol_t:  # an event on the last instant: close the record at t_end
            if max(float(np.max(a)) for a in times) < t_end:
                times.append(np.array([t_end]))
                states.append(z[:, None])
                mode_rows.append(np.array([modes]))
            break

    time_all = np.concatenate(times)
    z_all = np.concatenate(states, axis=1).T
    mode_all = np.concatenate(mode_rows, axis=0).astype(bool)
    order = np.argsort(time_all, kind="stable")
    time_all, z_all, mode_all = time_all[order], z_all[order], mode_all[order]
    if np.any(np.diff(time_all) <= 0.0):
        keep = np.concatenate([[True], np.diff(time_all) > 0.0])
        time_all, z_all, mode_all = time_all[keep], z_all[keep], mode_all[keep]
    if not np.all(np.isfinite(z_all)):
        raise ConvergenceError(f"simulate ({train.name}, ω = {omega:.6g} rad/s): the solution has non-finite values")
    event_rows.sort(key=lambda row: row[0])

    # -- outputs ----------------------------------------------------------------------------------
    angle = theta0 + omega * time_all
    on_grid = np.isin(time_all, t_grid)
    y = np.empty_like(time_all)
    dyt = np.empty_like(time_all)
    ddyt = np.empty_like(time_all)
    grid_index = np.searchsorted(t_grid, time_all[on_grid])
    y[on_grid], dyt[on_grid], ddyt[on_grid] = y_grid[grid_index], omega * dy_grid[grid_index], \
        omega**2 * ddy_grid[grid_index]
    if np.any(~on_grid):
        ye, dye, ddye = _evaluate_lift(fn, np.mod(angle[~on_grid], TWO_PI))
        y[~on_grid], dyt[~on_grid], ddyt[~on_grid] = ye, omega * dye, omega**2 * ddye
    x = z_all[:, :n]
    v = z_all[:, n:]
    contact_on, seat_on, valve_open = mode_all[:, 0], mode_all[:, 1], mode_all[:, 2]
    N = np.where(contact_on, np.maximum(kc * (y - x[:, 0]) + cc * (dyt - v[:, 0]), 0.0), 0.0)
    S = np.where(seat_on, np.maximum(-kv * x[:, -1] - cv * v[:, -1], 0.0), 0.0)
    for name, arr in (("contact force", N), ("seat force", S), ("lift", y)):
        if not np.all(np.isfinite(arr)):
            raise ConvergenceError(f"simulate ({train.name}): non-finite {name}")
    contact_open = ~contact_on & (y - x[:, 0] <= 0.0)

    import pandas as pd

    gap_transitions = []
    gap_open = False
    for t_row, name, active in event_rows:
        if name == "gap" and active != gap_open:
            gap_transitions.append((t_row, active))
            gap_open = active
        elif name == "contact" and active and gap_open:  # the force closed: the gap has closed
            gap_transitions.append((t_row, False))
            gap_open = False
    valve_transitions = [(t_row, active) for t_row, name, active in event_rows if name == "valve open"]
    jumps = _intervals(gap_transitions, time_all, x[:, 0] - y, t_end, omega, theta0, "max gap [m]",
                       lambda t0: True)

    def not_cam_driven(t0):
        return _evaluate_lift(fn, np.array([math.fmod(theta0 + omega * t0, TWO_PI) % TWO_PI]))[1][0] <= 0.0

    seat_bounces = _intervals(valve_transitions, time_all, x[:, -1], t_end, omega, theta0, "max lift [m]",
                              not_cam_driven)
    events_frame = pd.DataFrame({
        "time [s]": [r[0] for r in event_rows],
        "angle [deg]": [math.degrees(theta0 + omega * r[0]) for r in event_rows],
        "switch": [r[1] for r in event_rows],
        "active": [bool(r[2]) for r in event_rows],
    })
    record = SolverRecord(method=method, wall_time=_time.perf_counter() - wall_start, segments=segments,
                          events=len(event_rows), rhs_evaluations=nfev, rtol=rtol, atol=atol_arr)
    return ValveTrainResponse(
        train=train, speed=omega, cycles=cycles, time=time_all, angle=angle, lift=y, lift_velocity=dyt,
        lift_acceleration=ddyt, displacement=x, velocity=v, contact_force=N, seat_force=S,
        contact_open=contact_open, seated=~valve_open, jumps=jumps, seat_bounces=seat_bounces,
        events=events_frame, record=record,
    )


def _consistent_modes(modes, h, hysteresis):
    """Switch states consistent with the h values (active needs h >= −ε_i, inactive h <= ε_i)."""
    new = list(modes)
    for i in range(3):
        if new[i] and h[i] < -hysteresis[i]:
            new[i] = False
        elif not new[i] and h[i] > hysteresis[i]:
            new[i] = True
    return tuple(bool(m) for m in new)


def _intervals(transitions, time_all, measure, t_end, omega, theta0, measure_name, accept):
    """Intervals between (t, True) and the next (t, False) transition as a DataFrame."""
    import pandas as pd

    rows = []
    start = None
    for t, active in transitions:
        if active and start is None:
            start = t
        elif not active and start is not None:
            rows.append((start, t, True))
            start = None
    if start is not None:
        rows.append((start, t_end, False))
    columns = ["cycle", "start angle [deg]", "end angle [deg]", "duration [s]", measure_name, "complete"]
    records = []
    for t0, t1, complete in rows:
        if not accept(t0):
            continue
        inside = (time_all >= t0) & (time_all <= t1)
        peak = float(np.max(measure[inside])) if np.any(inside) else 0.0
        records.append((
            int(math.floor(omega * t0 / TWO_PI)) + 1,
            math.degrees(theta0 + omega * t0),
            math.degrees(theta0 + omega * t1),
            t1 - t0,
            max(peak, 0.0),
            complete,
        ))
    return pd.DataFrame.from_records(records, columns=columns)
