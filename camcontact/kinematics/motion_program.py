"""Motion programs: the follower lift f(θ) over a full cam turn, composed of motion-law segments.

A :class:`Segment` maps a normalised motion law (family ``motion_laws``, x in [0, 1]) onto the
cam angles [start, end] and the lifts [lift_start, lift_end]; a dwell has no law. A
:class:`MotionProgram` is an ordered tuple of segments that covers [0, 2π) exactly with a
continuous lift, and gives f [m], f' [m/rad], f'' [m/rad²] and f''' [m/rad³] at any cam
angle, plus a continuity report of its joints (C0/C1/C2, jerk finite/continuous).

Segments hold SI floats (rad, m). The constructors :meth:`MotionProgram.from_segments`,
:meth:`MotionProgram.rise_return_dwell` and :meth:`MotionProgram.thesis_ls1` take
Quantities or strings (``"90 deg"``, ``"20 mm"``) and convert them at the door.

Examples
--------
>>> from camcontact.kinematics.motion_program import MotionProgram
>>> program = MotionProgram.rise_return_dwell("20 mm", "90 deg", "90 deg")
>>> f, f1, f2, f3 = program.evaluate([0.5, 1.0])
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterable, Mapping
from typing import Any

import attrs
import numpy as np
import pint

from .. import registry
from ..errors import CamcontactWarning, InputError
from ..models.base import MotionLaw
from ..units import si_value, to_quantity

__all__ = ["MotionContinuityWarning", "MotionProgram", "Segment", "peak_coefficients"]

TWO_PI = 2.0 * math.pi
#: the law name that means a dwell (scene files cannot write None)
DWELL = "dwell"
#: joints closer than this [rad] count as contiguous (degree strings round to ~1e-16 rad)
ANGLE_TOLERANCE = 1e-9
#: relative tolerance of lift mismatches at joints and of the continuity flags
RELATIVE_TOLERANCE = 1e-9
DERIVATIVE_LABELS = ("f [m]", "f' [m/rad]", "f'' [m/rad^2]", "f''' [m/rad^3]")


class MotionContinuityWarning(CamcontactWarning):
    """A motion program has a velocity or acceleration jump (infinite acceleration or jerk)."""


def resolve_law(law: Any) -> MotionLaw:
    """A :class:`MotionLaw` instance from a registered name, a MotionLaw class or an instance."""
    model = registry.get("motion_laws", law)
    if not isinstance(model, MotionLaw):
        raise InputError(f"motion law {law!r} is not a MotionLaw (a name, MotionLaw subclass or instance)")
    direction = getattr(model, "direction", "rise")
    if direction not in ("rise", "return"):
        raise InputError(f"motion law {model.name!r}: direction = {direction!r}; expected 'rise' or 'return'")
    return model


def _si(value: Any, dimension: str, where: str, *, float_unit: str | None = None) -> float:
    """SI float of a Quantity/string; a bare number is taken in ``float_unit`` if given, else refused."""
    if float_unit is not None and not isinstance(value, (str, pint.Quantity, tuple)):
        try:
            value = float(value)
        except (TypeError, ValueError):
            raise InputError(f"{where} = {value!r}: expected a number [{float_unit}], a Quantity or a string") from None
        if not math.isfinite(value):
            raise InputError(f"{where} = {value!r}: must be finite")
        return value
    return float(si_value(to_quantity(value, dimension, where=where)))


def _angle_field():
    def convert(value, field):
        return _si(value, "[angle]", f"Segment.{field.name}", float_unit="rad")

    return attrs.field(converter=attrs.Converter(convert, takes_field=True))


def _lift_field(**options):
    def convert(value, field):
        if value is None:
            return None
        return _si(value, "[length]", f"Segment.{field.name}", float_unit="m")

    return attrs.field(converter=attrs.Converter(convert, takes_field=True), **options)


@attrs.frozen
class Segment:
    """One segment of a motion program: a motion law (or a dwell) over cam angles [start, end].

    Parameters
    ----------
    law : str, MotionLaw subclass or instance, or None
        Registered name (``"P-1"``, ``"cycloidal"``), a model, or None (or ``"dwell"``) for a dwell.
    start, end : float
        Cam angles [rad] (Quantities and strings such as ``"90 deg"`` are converted); end > start.
    lift_start : float
        Lift at ``start`` [m].
    lift_end : float, optional
        Lift at ``end`` [m]; defaults to ``lift_start`` (required equal for a dwell).

    Notes
    -----
    With x = (θ − start)/β, β = end − start, and the law's y(x), the progress is g = y for a
    rise law and g = 1 − y for a return law, and

    .. math::
        f = f_s + (f_e - f_s)\\,g(x), \\quad f' = (f_e - f_s)\\,g'(x)/\\beta, \\quad
        f'' = (f_e - f_s)\\,g''(x)/\\beta^2, \\quad f''' = (f_e - f_s)\\,g'''(x)/\\beta^3

    so partial lifts are allowed, and a return law on a decreasing lift is the usual return.
    A rise law on a segment whose lift decreases (or a return law on an increasing one) is
    allowed too: it gives the law's shape mirrored, f = f_s − |f_e − f_s| y.
    """

    law: Any = attrs.field(converter=lambda law: None if isinstance(law, str) and law == DWELL else law)
    start: float = _angle_field()
    end: float = _angle_field()
    lift_start: float = _lift_field()
    lift_end: float | None = _lift_field(default=None)
    _model: MotionLaw | None = attrs.field(init=False, default=None, eq=False, repr=False)

    def __attrs_post_init__(self) -> None:
        if self.lift_end is None:
            object.__setattr__(self, "lift_end", self.lift_start)
        if not self.end > self.start:
            raise InputError(
                f"Segment {self.name!r}: end = {math.degrees(self.end):.6g}° must be after "
                f"start = {math.degrees(self.start):.6g}°"
            )
        if self.law is None:
            if self.lift_end != self.lift_start:
                raise InputError(
                    f"dwell segment [{math.degrees(self.start):.6g}°, {math.degrees(self.end):.6g}°]: "
                    f"lift_start = {self.lift_start * 1e3:.6g} mm and lift_end = {self.lift_end * 1e3:.6g} mm "
                    "must be equal (give a motion law to move)"
                )
        else:
            object.__setattr__(self, "_model", resolve_law(self.law))

    @property
    def model(self) -> MotionLaw | None:
        """The resolved motion law instance (None for a dwell)."""
        return self._model

    @property
    def name(self) -> str:
        """The law's name, or ``"dwell"``."""
        if self.law is None:
            return "dwell"
        return self._model.name if self._model is not None else str(self.law)

    @property
    def span(self) -> float:
        """β = end − start [rad]."""
        return self.end - self.start

    def at_normalised(self, x) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(f [m], f' [m/rad], f'' [m/rad²], f''' [m/rad³]) at normalised angles x in [0, 1]."""
        x = np.asarray(x, dtype=float)
        if self._model is None:
            zeros = np.zeros_like(x)
            return zeros + self.lift_start, zeros, zeros.copy(), zeros.copy()
        y, d1, d2, d3 = (np.asarray(v, dtype=float) for v in self._model.derivatives(x))
        if getattr(self._model, "direction", "rise") == "return":
            y, d1, d2, d3 = 1.0 - y, -d1, -d2, -d3
        rise, beta = self.lift_end - self.lift_start, self.span
        return self.lift_start + rise * y, rise * d1 / beta, rise * d2 / beta**2, rise * d3 / beta**3

    def evaluate(self, theta) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(f, f', f'', f''') at cam angles θ [rad] in [start, end] (clipped to the segment)."""
        x = np.clip((np.asarray(theta, dtype=float) - self.start) / self.span, 0.0, 1.0)
        return self.at_normalised(x)


def _as_segment(item: Any, index: int) -> Segment:
    if isinstance(item, Segment):
        return item
    if not isinstance(item, Mapping):
        raise InputError(f"segment {index}: expected a Segment or a dict with law/start/end/lift_start/lift_end, "
                         f"got {item!r}")
    allowed = {"law", "start", "end", "lift_start", "lift_end"}
    unknown = set(item) - allowed
    if unknown:
        raise InputError(f"segment {index}: unknown keys {sorted(unknown)}; allowed: {sorted(allowed)}")
    missing = {"start", "end", "lift_start"} - set(item)
    if missing:
        raise InputError(f"segment {index}: missing {sorted(missing)}")
    where = f"segment {index} ({item.get('law') or 'dwell'})"
    values = {
        key: _si(item[key], dimension, f"{where}: {key}")
        for key, dimension in (("start", "[angle]"), ("end", "[angle]"), ("lift_start", "[length]"),
                               ("lift_end", "[length]"))
        if key != "lift_end" or item.get(key) is not None
    }
    return Segment(law=item.get("law"), **values)


def _degrees(angle: float) -> str:
    return f"{math.degrees(angle):.6g}°"


@attrs.frozen
class MotionProgram:
    """The lift f(θ) over one cam turn: segments covering [0, 2π) with a continuous lift.

    Parameters
    ----------
    segments : sequence of Segment
        In order; the first starts at 0, each starts where the previous ends (within
        1e-9 rad), the last ends at 2π, and the lift is continuous at every joint,
        2π → 0 included. Otherwise :class:`InputError` naming the segment.
    """

    segments: tuple[Segment, ...] = attrs.field(converter=tuple)

    def __attrs_post_init__(self) -> None:
        segments = self.segments
        if not segments:
            raise InputError("MotionProgram needs at least one segment")
        for i, segment in enumerate(segments):
            if not isinstance(segment, Segment):
                raise InputError(f"MotionProgram segment {i}: expected a Segment, got {segment!r} "
                                 "(use MotionProgram.from_segments for dicts)")
        if abs(segments[0].start) > ANGLE_TOLERANCE:
            raise InputError(f"MotionProgram segment 0 ({segments[0].name}) starts at {_degrees(segments[0].start)}; "
                             "the first segment must start at 0°")
        for i in range(1, len(segments)):
            previous, segment = segments[i - 1], segments[i]
            gap = segment.start - previous.end
            if abs(gap) > ANGLE_TOLERANCE:
                kind = "gap" if gap > 0 else "overlap"
                raise InputError(
                    f"MotionProgram segment {i} ({segment.name}, {_degrees(segment.start)}–{_degrees(segment.end)}) "
                    f"starts at {_degrees(segment.start)} but segment {i - 1} ({previous.name}) ends at "
                    f"{_degrees(previous.end)}: {kind} of {abs(math.degrees(gap)):.6g}°"
                )
        last = segments[-1]
        if abs(last.end - TWO_PI) > ANGLE_TOLERANCE:
            raise InputError(f"MotionProgram segment {len(segments) - 1} ({last.name}) ends at {_degrees(last.end)}; "
                             "the last segment must end at 360°")
        scale = max(max(abs(s.lift_start), abs(s.lift_end)) for s in segments)
        for i, segment in enumerate(segments):
            previous = segments[i - 1]  # segment -1 = the last: the joint 360° -> 0°
            mismatch = segment.lift_start - previous.lift_end
            if abs(mismatch) > RELATIVE_TOLERANCE * scale:
                raise InputError(
                    f"MotionProgram segment {i} ({segment.name}, {_degrees(segment.start)}–{_degrees(segment.end)}) "
                    f"starts at lift {segment.lift_start * 1e3:.6g} mm but segment {(i - 1) % len(segments)} "
                    f"({previous.name}) ends at {previous.lift_end * 1e3:.6g} mm: lift mismatch of "
                    f"{mismatch * 1e3:.6g} mm at {_degrees(segment.start)}"
                )

    # ------------------------------------------------------------- evaluation
    @property
    def joints(self) -> np.ndarray:
        """Cam angles of the joints [rad]: the start of every segment (0 is the 360° → 0° joint)."""
        return np.array([segment.start for segment in self.segments])

    def evaluate(self, theta) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(f [m], f' [m/rad], f'' [m/rad²], f''' [m/rad³]) at cam angles ``theta`` [rad].

        Angles are wrapped modulo 2π; at a joint the segment that starts there is used.
        The arrays have the shape of ``theta``.
        """
        theta = np.asarray(theta, dtype=float)
        wrapped = np.mod(theta, TWO_PI).ravel()
        index = np.clip(np.searchsorted(self.joints, wrapped, side="right") - 1, 0, len(self.segments) - 1)
        out = [np.empty_like(wrapped) for _ in range(4)]
        for k in np.unique(index):
            mask = index == k
            for array, values in zip(out, self.segments[k].evaluate(wrapped[mask])):
                array[mask] = values
        return tuple(array.reshape(theta.shape) for array in out)

    def _samples(self, points_per_segment: int = 1025) -> list[np.ndarray]:
        x = np.linspace(0.0, 1.0, points_per_segment)
        values = [segment.at_normalised(x) for segment in self.segments]
        return [np.concatenate([v[k] for v in values]) for k in range(4)]

    @property
    def lift(self) -> float:
        """Largest lift max f [m] (dense sampling of every segment, ends included)."""
        return float(np.max(self._samples()[0]))

    # ------------------------------------------------------------- continuity
    def continuity(self, rtol: float = RELATIVE_TOLERANCE):
        """One row per joint: jumps of f, f', f'', f''' and the smoothness flags.

        Parameters
        ----------
        rtol : float
            A jump of derivative k counts as zero when it is at most ``rtol`` times the largest
            |f^(k)| of the program (dense sampling).

        Returns
        -------
        pandas.DataFrame
            Columns ``"angle [deg]"`` (rounded to 1e-9°), ``"left"``, ``"right"`` (segment names), ``"jump f [m]"``,
            ``"jump f' [m/rad]"``, ``"jump f'' [m/rad^2]"``, ``"jump f''' [m/rad^3]"`` (right minus
            left), and the bools ``C0``, ``C1`` (C0 and velocity continuous), ``C2`` (C1 and
            acceleration continuous), ``jerk_finite`` (= C2) and ``jerk_continuous`` (C2 and the
            jerk continuous).
        """
        import pandas as pd

        scales = [float(np.max(np.abs(values))) for values in self._samples()]
        rows = []
        for i, segment in enumerate(self.segments):
            previous = self.segments[i - 1]
            left = [float(v) for v in previous.at_normalised(1.0)]
            right = [float(v) for v in segment.at_normalised(0.0)]
            jumps = [r - l for r, l in zip(right, left)]
            smooth = [abs(jump) <= rtol * scale for jump, scale in zip(jumps, scales)]
            c0 = smooth[0]
            c1 = c0 and smooth[1]
            c2 = c1 and smooth[2]
            row = {"angle [deg]": round(math.degrees(segment.start), 9), "left": previous.name, "right": segment.name}
            row.update({f"jump {label}": jump for label, jump in zip(DERIVATIVE_LABELS, jumps)})
            row.update({"C0": c0, "C1": c1, "C2": c2, "jerk_finite": c2, "jerk_continuous": c2 and smooth[3]})
            rows.append(row)
        return pd.DataFrame(rows)

    def diagnostics(self, rtol: float = RELATIVE_TOLERANCE) -> list[str]:
        """Messages for joints with a velocity jump (infinite acceleration) or an acceleration jump
        (infinite jerk); empty when the program is C2 everywhere."""
        messages = []
        for row in self.continuity(rtol).itertuples(index=False):
            angle, left, right = row[0], row[1], row[2]
            where = f"joint at {angle:.6g}° ({left} → {right})"
            if not row.C0:
                messages.append(f"{where}: the lift jumps by {row[3] * 1e3:.6g} mm")
            elif not row.C1:
                messages.append(f"{where}: the velocity f' jumps by {row[4]:.6g} m/rad, so the acceleration "
                                "is infinite there")
            elif not row.C2:
                messages.append(f"{where}: the acceleration f'' jumps by {row[5]:.6g} m/rad^2, so the jerk "
                                "is infinite there")
        return messages

    def check(self, strict: bool = False, rtol: float = RELATIVE_TOLERANCE):
        """Warn (:class:`MotionContinuityWarning`) about every joint that is not C2.

        With ``strict=True`` a joint that is not C1 (velocity jump) raises :class:`InputError`
        instead; acceleration jumps still only warn. Returns :meth:`continuity`.
        """
        table = self.continuity(rtol)
        messages = self.diagnostics(rtol)
        if strict and not bool(table["C1"].all()):
            broken = [m for m in messages if "velocity" in m or "lift jumps" in m]
            raise InputError("motion program is not C1: " + "; ".join(broken))
        for message in messages:
            warnings.warn(message, MotionContinuityWarning, stacklevel=2)
        return table

    # ------------------------------------------------------------- constructors
    @classmethod
    def from_segments(cls, segments: Iterable[Segment | Mapping[str, Any]]) -> MotionProgram:
        """A program from Segments and/or dicts.

        Each dict has ``law`` (name, model, or ``"dwell"``/None/absent for a dwell), ``start``, ``end``
        (angles, e.g. ``"90 deg"``), ``lift_start`` and optionally ``lift_end`` (lengths,
        e.g. ``"20 mm"``). Dimensional values must be Quantities or strings: a bare number
        raises :class:`InputError` naming the segment and the field.
        """
        return cls(tuple(_as_segment(item, i) for i, item in enumerate(segments)))

    @classmethod
    def rise_return_dwell(cls, lift, rise, ret, rise_law: Any = "P-1", return_law: Any = "P-2") -> MotionProgram:
        """Rise over [0, rise], return over [rise, rise + ret], dwell at zero lift to 360°.

        Parameters
        ----------
        lift : Quantity or str
            Total lift L [length] (> 0).
        rise, ret : Quantity, str or float
            Angle spans of rise and return (floats are radians); rise + ret <= 360°.
        rise_law, return_law : str or MotionLaw
            Default: the Tsuha (2015) pair P-1 / P-2.
        """
        where = "MotionProgram.rise_return_dwell"
        height = _si(lift, "[length]", f"{where} lift")
        if not height > 0.0:
            raise InputError(f"{where}: lift = {lift!r} must be > 0")
        beta_rise = _si(rise, "[angle]", f"{where} rise", float_unit="rad")
        beta_return = _si(ret, "[angle]", f"{where} ret", float_unit="rad")
        total = beta_rise + beta_return
        if not (beta_rise > 0.0 and beta_return > 0.0) or total > TWO_PI + ANGLE_TOLERANCE:
            raise InputError(f"{where}: rise = {_degrees(beta_rise)} and ret = {_degrees(beta_return)} must be > 0 "
                             f"with rise + ret <= 360° (got {_degrees(total)})")
        segments = [Segment(rise_law, 0.0, beta_rise, 0.0, height)]
        if total >= TWO_PI - ANGLE_TOLERANCE:
            segments.append(Segment(return_law, beta_rise, TWO_PI, height, 0.0))
        else:
            segments.append(Segment(return_law, beta_rise, total, height, 0.0))
            segments.append(Segment(None, total, TWO_PI, 0.0, 0.0))
        return cls(tuple(segments))

    @classmethod
    def thesis_ls1(cls) -> MotionProgram:
        """The Tsuha (2015) LS-1 program: lift 20 mm, P-1 rise 0–90°, P-2 return 90–180°, dwell 180–360°.

        Reference §0 item 1 (established by exact reproduction of Tables 6.3–6.11).
        """
        return cls.rise_return_dwell("20 mm", "90 deg", "90 deg", rise_law="P-1", return_law="P-2")


def peak_coefficients(law: Any, samples: int = 20001) -> tuple[float, float, float]:
    """Peak coefficients max|y'|, max|y''|, max|y'''| [-] of a motion law over x in [0, 1].

    Dense sampling, then a bounded scalar maximisation (scipy) around the best sample.
    """
    from scipy.optimize import minimize_scalar

    model = resolve_law(law)
    x = np.linspace(0.0, 1.0, samples)
    peaks = []
    for order in (1, 2, 3):
        values = np.abs(model.derivatives(x)[order])
        i = int(np.argmax(values))
        low, high = x[max(i - 1, 0)], x[min(i + 1, samples - 1)]
        result = minimize_scalar(lambda t: -abs(float(model.derivatives(t)[order])), bounds=(low, high),
                                 method="bounded", options={"xatol": 1e-12})
        peaks.append(max(float(values[i]), -float(result.fun)))
    return tuple(peaks)
