"""Valve-train dynamics: what the cam must push against, and when the follower leaves it.

Two levels of model:

* :mod:`camcontact.dynamics.prescribed_motion` — the 1-DOF equivalent valve train with the
  follower kept on the cam (Tsuha 2015): contact force from the prescribed motion, jump test,
  minimum spring stiffness.
* :mod:`camcontact.dynamics.valve_train_ode` — lumped 2-DOF and 5-DOF valve trains of
  Ferrarese & Uehara with unilateral cam and seat contacts, integrated in time
  (:func:`simulate`), so jump and seat bounce happen rather than being flagged.

Everything here works on SI floats and arrays (kg, N/m, N s/m, N, rad, rad/s, m, s).
"""

from .valve_train_ode import LumpedValveTrain, SolverRecord, StaticEquilibrium, ValveTrainResponse, simulate

__all__ = ["LumpedValveTrain", "SolverRecord", "StaticEquilibrium", "ValveTrainResponse", "simulate"]
