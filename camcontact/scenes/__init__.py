"""Scene builders: how each scene component becomes a graph of analysis steps.

A scene module states its inputs (SI values of its component, the chosen models and the effect
switches, under names of their own), its step list, its default outputs and effects, the hints for
missing inputs and its plot; the computations are the step functions of :mod:`camcontact.steps`.
Importing this package registers the built-in scenes with :mod:`camcontact.step_graph`;
``camcontact/__init__.py`` registers that import as a scene loader, so it happens on the first scene
lookup of an Analysis, not when camcontact is imported.

How to add a step or an effect
------------------------------
1. Write the computation as a step function in the topic module of :mod:`camcontact.steps` it belongs
   to (or a new one): a top-level function on SI values whose parameters name what it requires, declared
   with :func:`camcontact.step_graph.step` (its step name, what it provides, a model label)::

       @step("contact_temperature", provides=("flash_temperature",), model="blok")
       def blok_flash(w, E_reduced, R, friction_coefficient, u1, u2, effusivity):
           return {"flash_temperature": flash_temperature(w, E_reduced, R, friction_coefficient, u1, u2,
                                                          effusivity, effusivity)}

   It can now be called and unit-tested alone with floats.
2. Give the scene the inputs it needs that no step provides (``effusivity`` from the material) in the
   scene's inputs function, and append ``Step.of(blok_flash)`` to its step list; use ``rename=`` to bind
   it under the scene's names (``Step.of(film_parameter, rename={"h": "h_min_in", "Lambda":
   "Lambda_in"})``). Add the outputs to :mod:`camcontact.quantities` (unit and meaning) and, if users
   should see them by default, to the scene's ``DEFAULT_OUTPUTS``.
3. An effect is a switch the user asks for by name (``Analysis(effects={...})``): add it to
   :data:`camcontact.step_graph.EFFECTS` and to the scene's ``SUPPORTED_EFFECTS`` (and ``DEFAULT_EFFECTS``
   if it is on by default), then let the builder choose the steps it switches (``Step.of(thermal_films if
   "thermal" in effects else isothermal_films, ...)``) or pass it to a step as an input
   (``"piezoviscosity": "piezoviscosity" in effects``). Only the steps a requested output needs run, so an
   effect costs nothing when nobody asks for what it changes. The outputs an asked-for effect calls for go
   into the graph's ``effect_outputs`` as well as its default outputs: a default report then names an input
   they miss instead of quietly leaving them out (as it does for the scene's other default outputs).

The analysis checks the graph before running (a missing input is an InputError with the scene's hint),
runs only the needed steps and records each step's model and wall time.
"""

from . import (ball_bearing, ball_cone_cvt, bearing, cam_follower, cylindrical_roller_bearing, line_contact,  # noqa: F401
               point_contact, raceway_contact)
