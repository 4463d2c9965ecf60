"""Plane-strain "longitudinal slice" stresses under arbitrary surface pressure and traction.

Saccheto (2008, §3.4, Eqs. 3.48–3.71) computes the subsurface field of the ball-cone contact
slice by slice: the normal pressure p(s) and the tangential (e.g. FASTSIM) traction q(s) along
the rolling direction of one strip of the contact are treated as a 2-D plane-strain load on a
half-space and the Flamant/Boussinesq–Cerruti line-load solutions are superposed. With x along
the surface, z >= 0 into the body, p compressive positive and q acting on the body in +x
(Johnson 1985, Eq. 2.23; stresses compression negative):

.. math::
    \\sigma_x = -\\frac{2z}{\\pi}\\int \\frac{p(s)(x-s)^2\\,ds}{[(x-s)^2+z^2]^2}
               - \\frac{2}{\\pi}\\int \\frac{q(s)(x-s)^3\\,ds}{[(x-s)^2+z^2]^2}

    \\sigma_z = -\\frac{2z^3}{\\pi}\\int \\frac{p(s)\\,ds}{[(x-s)^2+z^2]^2}
               - \\frac{2z^2}{\\pi}\\int \\frac{q(s)(x-s)\\,ds}{[(x-s)^2+z^2]^2}

    \\tau_{xz} = -\\frac{2z^2}{\\pi}\\int \\frac{p(s)(x-s)\\,ds}{[(x-s)^2+z^2]^2}
                - \\frac{2z}{\\pi}\\int \\frac{q(s)(x-s)^2\\,ds}{[(x-s)^2+z^2]^2}

The pressure part is Saccheto's Eqs. 3.63–3.65. His tangential line-load kernels (Eqs.
3.59–3.61) are wrong; the ones above are Johnson's (Eq. 2.21: sigma_x ~ X^3, sigma_z ~ X Z^2,
tau_xz ~ X^2 Z for a tangential line load).

**Integration.** The loads are given at nodes s_0 < ... < s_N and taken linear between them
(zero outside). Each convolution is then integrated *exactly*: two integrations by parts turn
it into a sum over the nodes of the slope jumps times the second antiderivative of the kernel,
plus end terms (see :mod:`camcontact.contact._slice_kernels`). The second antiderivatives are
continuous up to the surface, so there is no near-surface singularity to treat and z = 0 gives
the surface values (sigma_z = -p, tau_xz = -q). The only approximation is the piecewise-linear
representation of the load; for a Hertz (semi-elliptic) profile on cosine-spaced nodes
(:func:`semi_elliptical_load`) the field agrees with McEwen's closed form
(:func:`camcontact.contact.subsurface.line_contact_stresses`) to about 6e-5 p_0 with 201 nodes
and 2e-4 p_0 with 101 nodes at depths z >= 0.1 b (tested). Uniform node spacing resolves the
square-root edges of a Hertz profile less well (about 2e-3 p_0 with 201 nodes, 6e-4 with 401).

**Derived shears.** The Mohr (in-plane principal) maximum shear

.. math::
    \\tau_{max} = \\sqrt{\\left(\\frac{\\sigma_x - \\sigma_z}{2}\\right)^2 + \\tau_{xz}^2}

(Saccheto's Eq. 3.71 prints sigma_x + sigma_z: erratum) and the orthogonal shear tau_xz, whose
range along x at a depth is the alternating shear of Lundberg & Palmgren. Classical line-contact
values (frictionless): tau_max = 0.300 p_0 at z = 0.786 b, x = 0; |tau_xz| = 0.250 p_0 at
z = 0.5 b, x = +-0.866 b (Johnson 1985 §4.2; Saccheto §3.3).

Applied to the central strip of an *elliptical* contact the slice is a plane-strain
approximation: it returns the line-contact ratios for the semi-axis along rolling whatever
the ellipticity (e.g. 0.300 p_0 at 0.786 a for a circle, where the 3-D field has 0.31 p_0 at
about 0.47 a; Saccheto §3.3). This is the thesis's method, reproduced as such.

References
----------
Johnson, K.L. (1985) Contact Mechanics, Cambridge UP, §2.2–2.3 (Eqs. 2.15, 2.21–2.23), §4.2.
McEwen, E. (1949) Stresses in elastic cylinders in contact along a generatrix, Phil. Mag. 40.
Saccheto, T.J.S. (2008) MSc dissertation, FEM/UNICAMP, §3.4, Eqs. 3.48–3.71 (with the errata
of Eqs. 3.51/3.53, 3.59–3.61 and 3.71 corrected as above).
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError
from . import _slice_kernels

__all__ = [
    "MEASURES",
    "SliceExtremum",
    "SliceStress",
    "semi_elliptical_load",
    "slice_extrema",
    "slice_extremum",
    "slice_stresses",
]

#: extremum measures: the Mohr maximum shear and the orthogonal shear |tau_xz|
MEASURES = ("max_shear", "orthogonal")
SPACINGS = ("cosine", "uniform")


# ----------------------------------------------------------------------------- results
@attrs.frozen(eq=False)
class SliceStress:
    """Stresses of a slice at field points (arrays of the broadcast shape of x and z)."""

    x: np.ndarray  #: position along the rolling direction [m]
    z: np.ndarray  #: depth below the surface [m]
    sigma_x: np.ndarray  #: normal stress along x [Pa] (compression negative)
    sigma_z: np.ndarray  #: normal stress along z [Pa]
    tau_xz: np.ndarray  #: shear stress on x and z planes (orthogonal shear) [Pa]

    @property
    def max_shear(self) -> np.ndarray:
        """Mohr maximum (in-plane principal) shear sqrt(((sx - sz)/2)^2 + txz^2) [Pa]."""
        return np.sqrt((0.5 * (self.sigma_x - self.sigma_z)) ** 2 + self.tau_xz**2)

    @property
    def orthogonal_shear(self) -> np.ndarray:
        """Orthogonal shear tau_xz [Pa] (signed)."""
        return self.tau_xz

    def sigma_y(self, nu: float) -> np.ndarray:
        """Out-of-plane stress nu (sigma_x + sigma_z) [Pa] of plane strain for Poisson's ratio nu."""
        return nu * (self.sigma_x + self.sigma_z)

    def as_dict(self) -> dict:
        """The fields as a dict of arrays (``sigma_x``, ``sigma_z``, ``tau_xz``, ``max_shear``)."""
        return {"x": self.x, "z": self.z, "sigma_x": self.sigma_x, "sigma_z": self.sigma_z,
                "tau_xz": self.tau_xz, "max_shear": self.max_shear}


@attrs.frozen
class SliceExtremum:
    """The extremum tau_0 of a shear measure over the search region, and the orthogonal range there."""

    measure: str  #: "max_shear" (Mohr) or "orthogonal" (|tau_xz|)
    tau0: float  #: extreme value of the measure [Pa] (|tau_xz| for "orthogonal")
    x0: float  #: its position along the rolling direction [m]
    z0: float  #: its depth Z_0 [m]
    tau_xz_max: float  #: largest tau_xz along x at depth z0 [Pa]
    x_tau_xz_max: float  #: where it occurs [m]
    tau_xz_min: float  #: smallest (most negative) tau_xz along x at depth z0 [Pa]
    x_tau_xz_min: float  #: where it occurs [m]

    @property
    def orthogonal_range(self) -> float:
        """Range tau_xz,max - tau_xz,min along x at depth z0 [Pa] (2 tau_0 in frictionless rolling)."""
        return self.tau_xz_max - self.tau_xz_min


# ----------------------------------------------------------------------------- validation
def _vector(name: str, value, size: int | None = None) -> np.ndarray:
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"slice stress: {name} = {value!r} is not an array of numbers") from None
    if array.ndim != 1:
        raise InputError(f"slice stress: {name} must be 1-D; got shape {array.shape}")
    if size is not None and array.size != size:
        raise InputError(f"slice stress: {name} has {array.size} values; it needs one per node ({size})")
    bad = ~np.isfinite(array)
    if np.any(bad):
        raise InputError(f"slice stress: {name}[{int(np.argmax(bad))}] = {float(array[bad][0])!r}; allowed: finite values")
    return np.ascontiguousarray(array)


def _load(s, p, q):
    """Validated (s, p, q) as contiguous float64 arrays."""
    s = _vector("nodes s", s)
    if s.size < 2:
        raise InputError(f"slice stress: nodes s has {s.size} value(s); at least 2 nodes are needed")
    steps = np.diff(s)
    if np.any(steps <= 0.0):
        k = int(np.argmax(steps <= 0.0))
        raise InputError(f"slice stress: nodes s must increase strictly; s[{k}] = {float(s[k])!r} m, "
                         f"s[{k + 1}] = {float(s[k + 1])!r} m")
    p = _vector("pressure p", p, s.size)
    if np.any(p < 0.0):
        k = int(np.argmax(p < 0.0))
        raise InputError(f"slice stress: pressure p[{k}] = {float(p[k])!r} Pa; allowed p >= 0 (compression positive)")
    q = np.zeros_like(s) if q is None else _vector("traction q", q, s.size)
    return s, p, q


def _points(x, z):
    """Broadcast, validated field points: (x flat, z flat, shape)."""
    try:
        x, z = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(z, dtype=float))
    except ValueError:
        raise InputError(f"slice stress: x (shape {np.shape(x)}) and z (shape {np.shape(z)}) "
                         "do not broadcast together") from None
    for name, array in (("x", x), ("z", z)):
        bad = ~np.isfinite(array)
        if np.any(bad):
            raise InputError(f"slice stress: field point {name} = {float(array[bad].flat[0])!r} m; allowed: finite")
    if np.any(z < 0.0):
        raise InputError(f"slice stress: depth z = {float(z.min())!r} m; allowed z >= 0 (measured into the body)")
    shape = x.shape
    return np.ascontiguousarray(x.ravel()), np.ascontiguousarray(z.ravel()), shape


def _kernel(compiled: bool):
    return _slice_kernels.compiled("slice_field") if compiled else _slice_kernels.slice_field


def _evaluate(s, p, q, x_flat, z_flat, compiled):
    sigma_x = np.empty(x_flat.size)
    sigma_z = np.empty(x_flat.size)
    tau_xz = np.empty(x_flat.size)
    _kernel(compiled)(s, p, q, x_flat, z_flat, sigma_x, sigma_z, tau_xz)
    return sigma_x, sigma_z, tau_xz


# ----------------------------------------------------------------------------- public API
def semi_elliptical_load(half_width: float, peak_pressure: float, *, traction_coefficient: float = 0.0,
                         nodes: int = 201, centre: float = 0.0, spacing: str = "cosine"):
    """Nodes and loads of a Hertz (semi-elliptic) strip with traction q = mu p.

    .. math::
        p(s) = p_0 \\sqrt{1 - (s - s_c)^2 / b^2}, \\qquad q(s) = \\mu\\, p(s)

    (Saccheto 2008 Eqs. 3.66–3.67; for an elliptical contact, b is the semi-axis along rolling of
    the strip and p_0 its centre-line pressure.)

    Parameters
    ----------
    half_width : float
        b [m], > 0.
    peak_pressure : float
        p_0 [Pa], >= 0.
    traction_coefficient : float
        mu [-]: traction q = mu p on the body in +x (negative: in -x).
    nodes : int
        Number of nodes (>= 3).
    centre : float
        s_c [m].
    spacing : str
        ``"cosine"`` (s = s_c - b cos(theta), theta uniform: resolves the square-root edges; the
        piecewise-linear interpolation error falls as 1/nodes^2) or ``"uniform"``.

    Returns
    -------
    s, p, q : ndarray
        Nodes [m], pressure [Pa], traction [Pa].
    """
    for label, value, ok in (("half_width", half_width, half_width > 0), ("peak_pressure", peak_pressure,
                                                                         peak_pressure >= 0)):
        if not (ok and math.isfinite(value)):
            raise InputError(f"semi_elliptical_load: {label} = {value!r}; allowed: finite, "
                             f"{'> 0 m' if label == 'half_width' else '>= 0 Pa'}")
    if not math.isfinite(traction_coefficient):
        raise InputError(f"semi_elliptical_load: traction_coefficient = {traction_coefficient!r}; allowed: finite")
    if int(nodes) != nodes or nodes < 3:
        raise InputError(f"semi_elliptical_load: nodes = {nodes!r}; allowed: an integer >= 3")
    if spacing not in SPACINGS:
        raise InputError(f"semi_elliptical_load: spacing = {spacing!r}; allowed {SPACINGS}")
    if spacing == "cosine":
        theta = np.linspace(0.0, math.pi, int(nodes))
        unit = -np.cos(theta)
        unit[0], unit[-1] = -1.0, 1.0
        shape = np.sin(theta)
        shape[0] = shape[-1] = 0.0
    else:
        unit = np.linspace(-1.0, 1.0, int(nodes))
        shape = np.sqrt(np.clip(1.0 - unit * unit, 0.0, None))
    s = centre + half_width * unit
    p = peak_pressure * shape
    return s, p, traction_coefficient * p


def slice_stresses(s, p, q, x, z, *, compiled: bool = True) -> SliceStress:
    """Plane-strain stresses at points (x, z) under piecewise-linear surface loads p(s), q(s).

    Parameters
    ----------
    s : array_like
        Load nodes along the rolling direction [m], strictly increasing, at least 2.
    p : array_like
        Normal pressure at the nodes [Pa], >= 0 (compression positive).
    q : array_like or None
        Tangential traction at the nodes [Pa], acting on the body in +x (None: frictionless).
        Both loads are linear between the nodes and zero outside [s_0, s_N]; a load that is not
        zero at an end node is a step there (its sigma_x is logarithmically infinite at that
        surface point).
    x, z : array_like
        Field points [m], broadcast together (e.g. ``x[None, :]``, ``z[:, None]``); z >= 0 is
        the depth into the body, z = 0 gives the surface values.
    compiled : bool
        Use the numba kernel (True) or its plain-Python twin.

    Returns
    -------
    SliceStress
        sigma_x, sigma_z, tau_xz [Pa] (Johnson 1985 Eq. 2.23 signs) on the broadcast shape,
        with ``max_shear`` (Mohr, Saccheto Eq. 3.71 corrected) and ``orthogonal_shear``.
    """
    s, p, q = _load(s, p, q)
    x_flat, z_flat, shape = _points(x, z)
    sigma_x, sigma_z, tau_xz = _evaluate(s, p, q, x_flat, z_flat, compiled)
    return SliceStress(x=x_flat.reshape(shape), z=z_flat.reshape(shape), sigma_x=sigma_x.reshape(shape),
                       sigma_z=sigma_z.reshape(shape), tau_xz=tau_xz.reshape(shape))


def _search_axes(s, x, z):
    span = s[-1] - s[0]
    if x is None:
        x = np.linspace(s[0] - 0.25 * span, s[-1] + 0.25 * span, 161)
    if z is None:
        z = np.linspace(0.0, 0.75 * span, 97)
    x = _vector("search grid x", x)
    z = _vector("search grid z", z)
    for name, axis in (("x", x), ("z", z)):
        if axis.size < 3 or np.any(np.diff(axis) <= 0.0):
            raise InputError(f"slice extremum: search grid {name} needs >= 3 strictly increasing values; "
                             f"got {axis.size}")
    if z[0] < 0.0:
        raise InputError(f"slice extremum: search grid z starts at {float(z[0])!r} m; allowed z >= 0")
    return x, z


def _measure_values(measure, sigma_x, sigma_z, tau_xz):
    if measure == "max_shear":
        return np.sqrt((0.5 * (sigma_x - sigma_z)) ** 2 + tau_xz**2)
    return np.abs(tau_xz)


def _refine_2d(field, cx, cz, half_x, half_z, bounds, rounds=8, points=11, shrink=4.0):
    """Zoom a points x points grid around (cx, cz) ``rounds`` times; returns (value, x, z)."""
    (x_low, x_high), (z_low, z_high) = bounds
    best = None
    for _ in range(rounds):
        gx = np.clip(np.linspace(cx - half_x, cx + half_x, points), x_low, x_high)
        gz = np.clip(np.linspace(cz - half_z, cz + half_z, points), z_low, z_high)
        X, Z = np.meshgrid(gx, gz)
        values = field(X.ravel(), Z.ravel())
        k = int(np.argmax(values))
        cx, cz = float(X.flat[k]), float(Z.flat[k])
        best = (float(values[k]), cx, cz)
        half_x /= shrink
        half_z /= shrink
    return best


def _refine_1d(line, centre, half, bounds, rounds=8, points=21, shrink=8.0):
    low, high = bounds
    best = None
    for _ in range(rounds):
        grid = np.clip(np.linspace(centre - half, centre + half, points), low, high)
        values = line(grid)
        k = int(np.argmax(values))
        centre = float(grid[k])
        best = (float(values[k]), centre)
        half /= shrink
    return best


def slice_extrema(s, p, q=None, *, measures=MEASURES, x=None, z=None, refine: bool = True,
                  compiled: bool = True) -> dict:
    """Extrema tau_0, their depth Z_0 and position, for several measures (one field evaluation).

    See :func:`slice_extremum` (same arguments); returns ``{measure: SliceExtremum}``.
    """
    measures = (measures,) if isinstance(measures, str) else tuple(measures)
    for measure in measures:
        if measure not in MEASURES:
            raise InputError(f"slice extremum: measure = {measure!r}; allowed {MEASURES}")
    s, p, q = _load(s, p, q)
    xs, zs = _search_axes(s, x, z)
    X, Z = np.meshgrid(xs, zs)
    x_flat, z_flat = np.ascontiguousarray(X.ravel()), np.ascontiguousarray(Z.ravel())
    coarse = _evaluate(s, p, q, x_flat, z_flat, compiled)
    bounds = ((float(xs[0]), float(xs[-1])), (float(zs[0]), float(zs[-1])))
    dx, dz = float(np.max(np.diff(xs))), float(np.max(np.diff(zs)))

    def field(measure):
        def values(xv, zv):
            return _measure_values(measure, *_evaluate(s, p, q, np.ascontiguousarray(xv),
                                                       np.ascontiguousarray(zv), compiled))
        return values

    def tau_xz_line(depth, sign):
        def values(xv):
            xv = np.ascontiguousarray(xv)
            return sign * _evaluate(s, p, q, xv, np.full(xv.size, depth), compiled)[2]
        return values

    results = {}
    for measure in measures:
        values = _measure_values(measure, *coarse)
        best = None
        candidates = np.argsort(values)[::-1][:4] if refine else [int(np.argmax(values))]
        for index in candidates:
            if refine:
                candidate = _refine_2d(field(measure), float(x_flat[index]), float(z_flat[index]), dx, dz, bounds)
            else:
                candidate = (float(values[index]), float(x_flat[index]), float(z_flat[index]))
            if best is None or candidate[0] > best[0]:
                best = candidate
        tau0, x0, z0 = best
        # range of tau_xz along x at the depth z0
        line_x = np.linspace(bounds[0][0], bounds[0][1], 4 * xs.size + 1)
        extremes = []
        for sign in (1.0, -1.0):
            line = tau_xz_line(z0, sign)
            coarse_line = line(line_x)
            k = int(np.argmax(coarse_line))
            if refine:
                value, where = _refine_1d(line, float(line_x[k]), float(line_x[1] - line_x[0]), bounds[0])
            else:
                value, where = float(coarse_line[k]), float(line_x[k])
            extremes.append((sign * value, where))
        results[measure] = SliceExtremum(measure=measure, tau0=tau0, x0=x0, z0=z0,
                                         tau_xz_max=extremes[0][0], x_tau_xz_max=extremes[0][1],
                                         tau_xz_min=extremes[1][0], x_tau_xz_min=extremes[1][1])
    return results


def slice_extremum(s, p, q=None, *, measure: str = "max_shear", x=None, z=None, refine: bool = True,
                   compiled: bool = True) -> SliceExtremum:
    """Extremum tau_0 of a shear measure of the slice field, its depth Z_0 and x position.

    The measure is evaluated on the search grid (x, z), the four best grid points are refined by
    zooming a local grid (8 rounds, each 4 x finer, to ~1e-5 of the grid spacing), and the largest
    is kept. At the depth Z_0 the orthogonal shear tau_xz is then scanned along x (a line 4 x
    finer than the grid, refined the same way) for its largest and smallest values, whose
    difference is the orthogonal shear range.

    Parameters
    ----------
    s, p, q : array_like
        Load nodes [m], pressure [Pa] and traction [Pa] (see :func:`slice_stresses`).
    measure : str
        ``"max_shear"``: the Mohr maximum shear sqrt(((sx - sz)/2)^2 + txz^2) (Saccheto Eq. 3.71
        corrected; what his Ch. 7 simulation uses); ``"orthogonal"``: |tau_xz|, the maximum
        orthogonal shear of Lundberg & Palmgren (Saccheto §5.4; the ball-cone scene's default).
        The thesis is ambiguous about which one fed its life model; both are offered. With
        traction the tau_xz cycle is lopsided: its peak |tau_xz| (``tau0``) then exceeds the
        amplitude, half of ``orthogonal_range`` (see
        :mod:`camcontact.models.life_lundberg_palmgren`).
    x, z : array_like, optional
        1-D search axes [m] (strictly increasing, z >= 0). Default: 161 points over
        [s_0 - L/4, s_N + L/4] and 97 over [0, 3L/4], L = s_N - s_0.
    refine : bool
        Refine below the grid spacing (True) or return the best grid point.
    compiled : bool
        Use the numba kernel (True) or its plain-Python twin.

    Returns
    -------
    SliceExtremum
        ``tau0`` [Pa], ``x0``, ``z0`` [m], ``tau_xz_max``/``tau_xz_min`` at depth z0 [Pa] and
        ``orthogonal_range`` [Pa].
    """
    if measure not in MEASURES:
        raise InputError(f"slice extremum: measure = {measure!r}; allowed {MEASURES}")
    return slice_extrema(s, p, q, measures=(measure,), x=x, z=z, refine=refine, compiled=compiled)[measure]
