"""Step functions shared by the scenes, grouped by topic.

Every step is a top-level function on SI floats/arrays and scene constants (model objects,
conventions, effect switches), declared with :func:`camcontact.step_graph.step`: its parameters
are what it requires, the decorator says what it provides. Each can be called alone::

    >>> from camcontact.steps.contact import line_hertz
    >>> round(line_hertz(w=1e5, R=0.01, E_reduced=2.3e11)["p_h"] / 1e6, 1)
    605.0

Modules:

:mod:`~camcontact.steps.kinematics`
    surface and entrainment speeds: two bodies, the cam follower, the bearing, the ball-cone CVT;
:mod:`~camcontact.steps.forces`
    forces and dynamics: the valve train (1-DOF prescribed motion, lumped ODE, jump, k_min), the
    bearing's load distribution, the CVT's loads;
:mod:`~camcontact.steps.contact`
    reduced modulus and radius, Hertz (line per contact, per cam angle, per roller; elliptical), approach;
:mod:`~camcontact.steps.stress`
    stresses below the surface, the roughness stress and the yield and fatigue checks;
:mod:`~camcontact.steps.lubricant`
    the lubricant's state at the scene temperature;
:mod:`~camcontact.steps.film`
    film-model resolution, EHL groups, film thickness of one contact, per roller or per CVT side,
    the inlet thermal correction, roughness and Lambda;
:mod:`~camcontact.steps.film_cycle`
    the film over a cam cycle (quasi-steady, warm-started numerical chains, or transient with squeeze);
:mod:`~camcontact.steps.raceway_film`
    Delabenetta's lubricant-and-film chain of a raceway contact, with the thesis's temperature loop;
:mod:`~camcontact.steps.friction`
    friction and wear (cam follower models, Kelley for raceways and bearings);
:mod:`~camcontact.steps.temperature`
    flash and film temperatures of a raceway contact;
:mod:`~camcontact.steps.traction`
    FASTSIM traction with spin of the CVT contacts;
:mod:`~camcontact.steps.life`
    rating lives (ISO 281, Lundberg–Palmgren);
:mod:`~camcontact.steps.summaries`
    cycle summaries (peaks, minima, means over a turn).
"""
