"""Analysis: compose components and models, run only what the scene asks for.

A *scene* is a component (e.g. :class:`~camcontact.components.LineContact`) plus what the
user asks of it: the ``outputs`` wanted, the ``models`` chosen per slot (by name, class,
instance or function) and the physical ``effects`` switched on. The scene's builder (see
:mod:`camcontact.scenes`) turns it into a graph of :class:`Step` objects that declare
what they ``require`` and ``provide``. :class:`Analysis` then

1. checks the graph *before running anything*: every requested output must be reachable
   from the scene's inputs; a missing input is an :class:`~camcontact.errors.InputError`
   that says which output needs it and how to give it;
2. runs only the steps needed for the requested outputs, in dependency order;
3. records, per step, the model name and version used and the wall time, so every report
   shows what its accuracy cost.

A model slot given as a list (``models={"film": ["grubin", "moes"]}``) makes one *variant*
per entry; steps that do not depend on the slot run once and are shared.

Examples
--------
>>> from camcontact import Analysis, Body, LineContact, Material
>>> steel = Material(E="210 GPa", nu=0.3)
>>> contact = LineContact(body1=Body(material=steel, radius="20 mm"),
...                       body2=Body(material=steel, radius="10 mm"),
...                       load="1 kN", length="10 mm")
>>> result = Analysis(contact, outputs=["b", "p_h"]).run()
>>> [record.step for record in result.records]
['geometry', 'hertz']
"""

from __future__ import annotations

import functools
import itertools
import logging
import time
import warnings
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

import attrs
import numpy as np

from . import registry
from .errors import CaseTimeout, InputError, PluginError, StepFailureWarning
from .models.base import Model, is_builtin
from .quantities import QUANTITIES
from .step_graph import EFFECTS, SceneGraph, Step, StepFailure, StepRecord, builder_for

__all__ = ["Analysis", "Result"]

#: the package's logger: every step that runs at INFO (``camcontact run -v``), with its model and time
LOGGER = logging.getLogger("camcontact")


def _context(model: str, variant: str) -> str:
    """`` (model, variant v)`` for a log line; empty parts left out."""
    parts = [part for part in (model, f"variant {variant}" if variant else "") if part]
    return f" ({', '.join(parts)})" if parts else ""


def _model_label(model: Any) -> str:
    if isinstance(model, str):
        return model
    return getattr(model, "name", None) or getattr(model, "__name__", None) or type(model).__name__


def input_token(value: Any) -> Any:
    """A hashable stand-in for a graph input that is equal for equal inputs: variants share a step
    whose inputs and upstream steps agree. Numbers, text, arrays, Quantities, attrs instances
    (components, model objects) and other models (by type and attributes) compare by value; any other
    object by identity."""
    if value is None or isinstance(value, (bool, int, float, complex, str, bytes)):
        return (type(value).__name__, value)
    if isinstance(value, np.ndarray):
        if value.dtype == object:
            return ("objects", value.shape, tuple(input_token(v) for v in value.flat))
        return ("ndarray", value.shape, value.dtype.str, value.tobytes())
    if isinstance(value, np.generic):
        return (type(value).__name__, value.item())
    if isinstance(value, (tuple, list, frozenset, set)):
        items = [input_token(v) for v in value]
        return (type(value).__name__, tuple(sorted(items, key=repr) if isinstance(value, (set, frozenset)) else items))
    if isinstance(value, Mapping):
        return ("mapping", tuple(sorted(((repr(k), input_token(v)) for k, v in value.items()), key=repr)))
    if hasattr(value, "magnitude") and hasattr(value, "units"):  # a pint Quantity
        return ("quantity", str(value.units), input_token(np.asarray(value.magnitude)))
    if attrs.has(type(value)):
        return (type(value), tuple(input_token(getattr(value, field.name)) for field in attrs.fields(type(value))))
    if isinstance(value, Model) and hasattr(value, "__dict__"):  # a model not made with attrs: type and attributes
        return (type(value), input_token(vars(value)))
    return ("id", id(value))


def foreign_models(step: Step, inputs: Mapping[str, Any]) -> list[Model]:
    """The models a step reads from the graph inputs that are not built in (plugins, the user's own
    classes and functions): those named when the step fails."""
    return [value for name in step.requires if isinstance(value := inputs.get(name), Model)
            and not is_builtin(type(value))]


def describe_model(model: Model) -> str:
    """``"plugin 'broken' (film_models) from camcontact-broken 0.1"``, or for a model given in code
    ``"model 'mine' (film_models, my_module.MyFilm)"``."""
    info = registry.origin(model)
    if info is not None:
        return f"plugin {info.name!r} ({info.family}) from {info.source}"
    cls = type(model)
    return f"model {model.name!r} ({model.family}, {cls.__module__}.{cls.__qualname__})"


def graph_resolver(graph: SceneGraph) -> tuple[dict[str, Step], Callable[[str, tuple[str, ...]], list[str]]]:
    """The step providing each output of ``graph`` and ``resolve(key, ())``: the inputs missing on the way to
    ``key`` (an empty list: reachable), each key resolved once; RuntimeError for a graph that provides a name
    twice or has a cycle (a scene builder's bug)."""
    providers: dict[str, Step] = {}
    for step in graph.steps:
        for name in step.provides:
            if name in providers:
                raise RuntimeError(f"scene graph: {name!r} provided by {providers[name].name} and {step.name}")
            providers[name] = step
    resolved: dict[str, list[str]] = {}

    def resolve(key: str, chain: tuple[str, ...]) -> list[str]:
        if key in graph.inputs:
            return []
        if key not in providers:
            return [key]
        if key in resolved:
            return resolved[key]
        if key in chain:
            raise RuntimeError(f"scene graph cycle through {key!r}")
        missing: list[str] = []
        for need in providers[key].requires:
            missing += resolve(need, chain + (key,))
        resolved[key] = missing
        return missing

    return providers, resolve


# ----------------------------------------------------------------------------- analysis
class Analysis:
    """Run a scene: see the module docstring.

    Parameters
    ----------
    scene : component
        A scene component, e.g. :class:`~camcontact.components.LineContact`.
    outputs : sequence of str, optional
        Quantities wanted (names of :mod:`camcontact.quantities`); default: the scene's
        default outputs that its inputs allow.
    models : mapping, optional
        Model per slot (e.g. ``{"film": "moes"}``); a list makes one variant per entry.
    effects : iterable of str, optional
        Physical effects switched on (default: the scene's defaults).
    strict : bool
        False (default): a step that fails leaves NaN in its own outputs with the reason
        (:attr:`Result.failures`, the report's ``failed`` and ``error`` columns) and the others run;
        True: the first failure raises.

    Examples
    --------
    A line contact, two film models side by side; the report in units, one value with its unit, what ran:

    >>> import camcontact as cc
    >>> steel = cc.Material(E="210 GPa", nu=0.3)
    >>> oil = cc.Lubricant(nu40="100 cSt", nu100="11 cSt", density="870 kg/m^3", alpha="22 1/GPa")
    >>> contact = cc.LineContact(body1=cc.Body(material=steel, radius="40 mm", speed="3 m/s", roughness="0.2 um"),
    ...                          body2=cc.Body(material=steel, radius="10 mm", speed="3 m/s", roughness="0.2 um"),
    ...                          load="3 kN", length="15 mm", lubricant=oil, temperature="80 degC")
    >>> analysis = cc.Analysis(contact, outputs=["p_h", "h_min", "Lambda_min"],
    ...                        models={"film": ["pan_hamrock", "dowson_higginson"]})
    >>> analysis.steps()
    ['geometry', 'hertz', 'kinematics', 'lubricant', 'ehl_groups', 'film', 'film_thickness', 'lambda']
    >>> result = analysis.run()
    >>> result.to_frame(units={"h_min": "nm"}).round(1).values.tolist()
    [['pan_hamrock', 958.2, 262.0, 0.9], ['dowson_higginson', 958.2, 280.8, 1.0]]
    >>> print(f"{result.quantity('p_h')[0]:.4g~P}")
    958.2 MPa

    The outputs a scene can give (``camcontact outputs`` for a scene file), and a study over a grid of
    field paths (one row per case; :func:`camcontact.sweep_frame` does the same from a component):

    >>> "Lambda_min" in set(cc.Analysis(contact).available_outputs()["output"])
    True
    >>> table = cc.Analysis(contact, outputs=["p_h"]).sweep({"load": ["1 kN", "3 kN"]}, progress=False)
    >>> table[["load [kN]", "p_h [MPa]"]].round(1).values.tolist()
    [[1.0, 553.2], [3.0, 958.2]]
    """

    def __init__(
        self,
        scene: Any,
        *,
        outputs: Sequence[str] | None = None,
        models: Mapping[str, Any] | None = None,
        effects: Iterable[str] | None = None,
        strict: bool = False,
    ):
        self.scene = scene
        if not isinstance(strict, (bool, np.bool_)):
            raise InputError(f"Analysis.strict = {strict!r}; allowed: True or False")
        self.strict = bool(strict)
        self._builder = builder_for(scene)
        self.models = dict(models or {})
        self.effects = None if effects is None else frozenset(effects)
        if self.effects is not None:
            unknown = sorted(self.effects - set(EFFECTS))
            if unknown:
                raise InputError(f"Analysis: unknown effects {unknown}; known effects: {', '.join(EFFECTS)}")
        if outputs is not None and isinstance(outputs, str):
            outputs = [outputs]
        self.requested = None if outputs is None else tuple(outputs)
        self.variants = self._expand_variants()
        self._signatures: dict[tuple, int] = {}
        self.plans = {label: self._plan(models_) for label, models_ in self.variants}
        if self.requested is not None:
            planned = {name for _, outputs, _ in self.plans.values() for name in outputs}
            for output in self.requested:
                if output not in planned:
                    raise InputError(
                        f"no variant of this analysis can give {output!r} (models: "
                        f"{', '.join(label for label, _ in self.variants)})"
                    )

    # --------------------------------------------------------------- planning
    def _expand_variants(self) -> list[tuple[str, dict[str, Any]]]:
        slots = {k: v for k, v in self.models.items() if isinstance(v, (list, tuple))}
        if not slots:
            return [("", dict(self.models))]
        variants = []
        for combination in itertools.product(*slots.values()):
            chosen = dict(self.models)
            chosen.update(zip(slots, combination))
            label = ", ".join(_model_label(m) for m in combination)
            taken = {existing for existing, _ in variants}
            if label in taken:  # two model objects of one name: number the repeats
                label = next(f"{label} #{n}" for n in itertools.count(2) if f"{label} #{n}" not in taken)
            variants.append((label, chosen))
        return variants

    def _plan(self, models: dict[str, Any]) -> tuple[SceneGraph, tuple[str, ...], list[tuple[Step, int, tuple]]]:
        graph = self._builder(self.scene, models=models, effects=self.effects)
        providers, resolve = graph_resolver(graph)

        if self.requested is None:
            outputs = tuple(o for o in graph.default_outputs if o in providers
                            and (o in graph.effect_outputs or not resolve(o, ())))
            self._check_reachable(graph, [o for o in outputs if o in graph.effect_outputs], resolve)
        else:
            outputs = tuple(o for o in self.requested if o in providers or o in graph.inputs)
            unprovided = [o for o in self.requested if o not in outputs]
            if unprovided and len(self.variants) == 1:
                known = sorted(name for name in providers if name in QUANTITIES)
                raise InputError(
                    f"{graph.kind} scene cannot give {unprovided[0]!r} with these models; it gives: {', '.join(known)}"
                )
            self._check_reachable(graph, outputs, resolve)
        order: list[Step] = []
        seen: set[str] = set()
        visiting: set[str] = set()
        reads: dict[str, tuple[str, ...]] = {}  # per step: its requires and the optional names it gets

        def visit(key: str) -> None:
            if key in graph.inputs or key not in providers:
                return
            step = providers[key]
            if step.name in seen or step.name in visiting:
                return
            visiting.add(step.name)
            for need in step.requires:
                visit(need)
            for name in step.optional:  # read when the graph can give it without a circle through this step
                if name in providers and not resolve(name, ()):
                    visit(name)
            visiting.discard(step.name)
            reads[step.name] = step.requires + tuple(
                name for name in step.optional if name in graph.inputs or (name in providers and providers[name].name in seen))
            seen.add(step.name)
            order.append(step)

        for output in outputs:
            visit(output)
        for step in order:
            if step.check is not None:
                step.check(graph.inputs)
        # a step's key: the number of its signature — its name, model, what it runs (the step function
        # and its binding; a hand-made step's own callable), the values of the graph inputs it reads and
        # the keys of its upstream steps — so that variants share exactly the steps that do not depend
        # on a varied model (numbered in self._signatures, shared by every variant)
        keys: dict[str, int] = {}
        labels: dict[str, tuple[str, str]] = {}
        for step in order:
            labels[step.name] = step.label(graph.inputs)
            upstream = frozenset(keys[providers[k].name] for k in reads[step.name] if k in providers
                                 and k not in graph.inputs)
            read = tuple((k, input_token(graph.inputs[k])) for k in reads[step.name] if k in graph.inputs)
            signature = (step.name, *labels[step.name], step.run, step.provides, read, upstream)
            keys[step.name] = self._signatures.setdefault(signature, len(self._signatures))
        return graph, outputs, [(step, keys[step.name], labels[step.name]) for step in order]

    @staticmethod
    def _check_reachable(graph: SceneGraph, outputs: Iterable[str], resolve: Callable) -> None:
        """InputError naming the missing inputs (with the scene's hints) of the first output that needs one."""
        for output in outputs:
            missing = resolve(output, ())
            if missing:
                hints = "; ".join(f"{m}: {graph.input_hints.get(m, 'not given by the scene')}" for m in dict.fromkeys(missing))
                raise InputError(f"output {output!r} of the {graph.kind} scene needs input the scene does not give ({hints})")

    # --------------------------------------------------------------- running
    def run(self) -> Result:
        """Run the planned steps of every variant and return a :class:`Result`.

        A step that raises (without ``strict``) gives no outputs: they are NaN (None) in the result,
        the steps that need them are skipped, every other step runs, a
        :class:`~camcontact.errors.StepFailureWarning` says so and :attr:`Result.failures` (and the
        report's ``failed``/``error`` columns) say why. With ``strict=True`` the first failure raises;
        a failure inside a model that is not built in is a :class:`~camcontact.errors.PluginError`
        naming the model, its distribution and the step.
        """
        cache: dict[int, tuple[Mapping[str, Any], StepFailure | None]] = {}
        rows: list[dict[str, Any]] = []
        records: list[StepRecord] = []
        failures: list[StepFailure] = []
        outputs_union: list[str] = []
        graph = None
        for label, _ in self.variants:
            graph, outputs, order = self.plans[label]
            state: dict[str, Any] = dict(graph.inputs)
            failed_by: dict[str, str] = {}  # output name -> the step that could not give it
            for step, key, (model, version) in order:
                if key not in cache:
                    cache[key] = self._run_step(step, model, version, label, graph, state, failed_by, records)
                produced, failure = cache[key]
                if failure is not None:
                    failures.append(attrs.evolve(failure, variant=label))
                    failed_by.update((name, step.name) for name in step.provides)
                state.update(produced)
            row = {name: state.get(name) for name in outputs}
            if graph.index is not None:
                row[graph.index] = state[graph.index]
            rows.append(row)
            outputs_union += [o for o in outputs if o not in outputs_union]
        if graph is not None:
            preferred = self.requested if self.requested is not None else graph.default_outputs
            rank = {name: i for i, name in enumerate(preferred)}
            outputs_union.sort(key=lambda name: rank.get(name, len(rank)))
        return Result(
            kind=graph.kind if graph else "",
            outputs=tuple(outputs_union),
            variants=tuple(label for label, _ in self.variants),
            rows=tuple(rows),
            records=tuple(records),
            effects=graph.effects if graph else frozenset(),
            plotter=graph.plotter if graph else None,
            scene=self.scene,
            index=graph.index if graph else None,
            per_index=graph.per_index if graph else frozenset(),
            variant_models=tuple(dict(models) for _, models in self.variants),
            failures=tuple(failures),
        )

    def _run_step(self, step: Step, model: str, version: str, variant: str, graph: SceneGraph,
                  state: Mapping[str, Any], failed_by: Mapping[str, str],
                  records: list[StepRecord]) -> tuple[dict[str, Any], StepFailure | None]:
        """One step: (its outputs, None), or ({}, the failure) when it raised or needs a failed output."""
        needed = [name for name in step.requires if name in failed_by]
        if needed:
            steps = ", ".join(dict.fromkeys(repr(failed_by[name]) for name in needed))
            reason = f"not run: needs {', '.join(needed)}, which step {steps} could not give"
            return {}, StepFailure(step.name, model, variant, step.provides, reason, skipped=True)
        start = time.perf_counter()
        try:
            produced = dict(step.run(state))
            missing = [p for p in step.provides if p not in produced]
            if missing:
                raise RuntimeError(f"step {step.name!r} did not provide {missing}")
        except CaseTimeout:  # a sweep's bound on the whole case, not this step's failure
            raise
        except Exception as exc:
            elapsed = time.perf_counter() - start
            foreign = foreign_models(step, graph.inputs)
            source = "; ".join(describe_model(m) for m in foreign)
            reason = f"{type(exc).__name__}: {exc}"
            if foreign:
                reason = f"{source} failed: {reason}"
            if self.strict:
                if foreign:
                    raise PluginError(f"{reason} (step {step.name!r})", model=model, source=source,
                                      step=step.name) from exc
                raise
            failure = StepFailure(step.name, model, variant, step.provides, reason, source=source)
            records.append(StepRecord(step.name, model, version, variant, elapsed, error=reason))
            LOGGER.info("step %s%s failed after %.1f ms: %s", step.name, _context(model, variant), 1e3 * elapsed, reason)
            outputs = ", ".join(step.provides) if len(step.provides) <= 6 else f"{len(step.provides)} outputs"
            warnings.warn(f"{failure.describe()}; its outputs ({outputs}) are NaN and the other steps ran "
                          "(strict=True raises)", StepFailureWarning, stacklevel=3)
            return {}, failure
        records.append(StepRecord(step.name, model, version, variant, time.perf_counter() - start))
        LOGGER.info("step %s%s ran in %.1f ms", step.name, _context(model, variant), 1e3 * records[-1].wall_time)
        return produced, None

    def sweep(self, grid: Any, *, executor: Any = None, progress: bool | None = None, errors: str = "record",
              table: str = "auto", units: Mapping[str, str] | None = None, chunksize: int | None = None,
              timeout: float | None = None, stream: Any = None, resume: bool = False):
        """This analysis over many cases: one tidy pandas DataFrame (see :mod:`camcontact.sweep_cases`).

        ``grid`` maps field paths of the scene (``"speed"``, ``"cam.base_radius"``) to values (the
        cartesian product is swept) or is a DataFrame of cases; ``executor`` is any
        ``concurrent.futures.Executor`` (None: serial here; a process pool; a Dask client's
        ``get_executor()``); failing cases keep their parameters and the error in the table, a case
        with a failed step its ``failed``/``error`` cells. ``timeout`` [s] bounds each case; ``stream``
        (a .csv path) gets every case as it finishes, and ``resume=True`` runs only the cases not yet
        in it; an interrupted sweep (Ctrl-C, a killed worker) returns the finished cases, with the
        missing ones in ``frame.attrs["missing_cases"]``. ``errors="raise"`` runs the cases strictly
        (the first failing step raises, with its own exception type).

        >>> import camcontact as cc
        >>> steel = cc.Material(E="210 GPa", nu=0.3)
        >>> contact = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm"),
        ...                          body2=cc.Body(material=steel, radius="10 mm"), load="1 kN", length="10 mm")
        >>> frame = cc.Analysis(contact, outputs=["p_h"]).sweep({"load": ["1 kN", "4 kN"]}, progress=False)
        >>> list(frame.columns), round(float(frame["p_h [MPa]"][1] / frame["p_h [MPa]"][0]), 6)
        (['case', 'load [kN]', 'p_h [MPa]', 'error'], 2.0)
        """
        from .sweep_cases import run_sweep

        runner = functools.partial(type(self), strict=True) if self.strict or errors == "raise" else type(self)
        return run_sweep(runner, self.scene, grid, outputs=self.requested, models=self.models, effects=self.effects,
                         executor=executor, progress=progress, errors=errors, table=table, units=units,
                         chunksize=chunksize, timeout=timeout, stream=stream, resume=resume)

    def steps(self, variant: str | None = None) -> list[str]:
        """Names of the steps that :meth:`run` will execute (for the first or a given variant)."""
        label = self.variants[0][0] if variant is None else variant
        return [step.name for step, _, _ in self.plans[label][2]]

    def available_outputs(self, variant: str | None = None):
        """The outputs the scene can give with these models and effects (the first or a given variant), as a
        pandas DataFrame: ``output``, ``unit`` (the report's), ``description``, ``step`` (that computes it),
        ``default`` (in the default report), ``per_index`` (an array over the scene's index, e.g. per cam angle)
        and ``available`` with, where False, the inputs ``missing`` and how to give them. Pass any of them as
        ``outputs=[...]``; ``camcontact outputs`` prints the same for a scene file.

        Examples
        --------
        >>> import camcontact as cc
        >>> steel = cc.Material(E="210 GPa", nu=0.3)
        >>> contact = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm"),
        ...                          body2=cc.Body(material=steel, radius="10 mm"), load="1 kN", length="10 mm")
        >>> table = cc.Analysis(contact).available_outputs()
        >>> row = table.set_index("output").loc["p_h"]
        >>> row["unit"], bool(row["available"]), row["step"]
        ('MPa', True, 'hertz')
        """
        import pandas as pd

        from .report import unit_label

        label = self.variants[0][0] if variant is None else variant
        if label not in self.plans:
            raise InputError(f"Analysis.available_outputs: variant {variant!r}; allowed: "
                             f"{', '.join(repr(v) for v, _ in self.variants)}")
        graph = self.plans[label][0]
        providers, resolve = graph_resolver(graph)
        rows = []
        for name, step in providers.items():
            if name not in QUANTITIES:  # internal values (solutions, tables) are not reported
                continue
            quantity, missing = QUANTITIES[name], list(dict.fromkeys(resolve(name, ())))
            rows.append({"output": name, "unit": "" if quantity.si_unit is None else unit_label(quantity.display_unit),
                         "description": quantity.description, "step": step.name,
                         "default": name in graph.default_outputs, "per_index": name in graph.per_index,
                         "available": not missing,
                         "missing": "; ".join(f"{m}: {graph.input_hints.get(m, 'not given by the scene')}"
                                              for m in missing)})
        return pd.DataFrame(rows, columns=["output", "unit", "description", "step", "default", "per_index",
                                           "available", "missing"])

    def __repr__(self) -> str:
        graph = self.plans[self.variants[0][0]][0]
        variants = f", {len(self.variants)} variants" if len(self.variants) > 1 else ""
        return (f"<Analysis of a {graph.kind} scene{variants}: steps {', '.join(self.steps())}; "
                f"effects {', '.join(sorted(graph.effects)) or 'none'}>")


@attrs.frozen
class Result:
    """Outcome of :meth:`Analysis.run`: values in SI, the record of what ran, reports and plots."""

    kind: str
    outputs: tuple[str, ...]
    variants: tuple[str, ...]
    rows: tuple[dict[str, Any], ...] = attrs.field(repr=False)
    records: tuple[StepRecord, ...] = attrs.field(repr=False)
    effects: frozenset  #: effects in force
    plotter: Callable[..., Any] | None = attrs.field(default=None, repr=False, eq=False)
    scene: Any = attrs.field(default=None, repr=False, eq=False)
    index: str | None = None  #: the input indexing array outputs (e.g. "cam_angle"), None for one-row results
    per_index: frozenset = frozenset()  #: outputs that are arrays over ``index``
    #: the models of each variant (slot -> model, as given), for plots that evaluate more of a variant
    variant_models: tuple[Mapping[str, Any], ...] = attrs.field(default=(), repr=False, eq=False)
    #: the steps that gave no outputs (``strict=False``), per variant, with the reason
    failures: tuple[StepFailure, ...] = ()

    def __getitem__(self, name: str) -> Any:
        """SI value of ``name`` (a list with one entry per variant when there are several); :meth:`quantity`
        gives it with its unit."""
        if name not in self.outputs:
            raise KeyError(f"{name!r} is not among the outputs {self.outputs}")
        values = [row.get(name) for row in self.rows]
        return values[0] if len(values) == 1 else values

    def quantity(self, name: str, unit: str | None = None) -> Any:
        """``name`` as a pint Quantity in ``unit`` (default: the report's unit; a list per variant when there
        are several; text and status outputs as they are; an output a variant does not give: None).

        >>> import camcontact as cc
        >>> steel = cc.Material(E="210 GPa", nu=0.3)
        >>> contact = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm"),
        ...                          body2=cc.Body(material=steel, radius="10 mm"), load="1 kN", length="10 mm")
        >>> print(f"{cc.Analysis(contact, outputs=['p_h']).run().quantity('p_h'):.4g~P}")
        742.2 MPa
        """
        from .units import Q_

        if name not in self.outputs:
            raise KeyError(f"{name!r} is not among the outputs {self.outputs}")
        spec = QUANTITIES.get(name)
        values = [row.get(name) for row in self.rows]
        if spec is None or spec.si_unit is None:
            return values[0] if len(values) == 1 else values
        target = unit if unit is not None else spec.display_unit
        try:
            converted = [None if v is None else Q_(np.asarray(v, dtype=float) if np.ndim(v) else float(v),
                                                   spec.si_unit).to(target) for v in values]
        except Exception as exc:  # pint: an unknown unit or the wrong dimension
            raise InputError(f"Result.quantity: {name} [{spec.si_unit or '-'}] in unit = {unit!r}: {exc}") from None
        return converted[0] if len(converted) == 1 else converted

    def __repr__(self) -> str:
        from .report import text_table

        frame = self.summary_frame() if self.index is not None else self.to_frame()
        head = (f"<Result of a {self.kind} scene: {len(self.variants)} variant(s), {len(self.records)} steps in "
                f"{1e3 * self.wall_time:.1f} ms" + (f"; {len(self.failures)} failed" if self.failures else "")
                + (f"; per {self.index}: to_frame()" if self.index is not None else "") + ">")
        lines = text_table(frame).splitlines() if len(frame.columns) else []
        if len(lines) > 25:
            lines = lines[:24] + [f"... {len(lines) - 24} more rows: to_frame()"]
        return "\n".join([head, *lines])

    def _repr_html_(self) -> str:
        """Jupyter: the scene's values (the cycle summary and the first rows per index for an indexed scene),
        the failures and the steps that ran with their times."""
        import html

        frame = self.summary_frame() if self.index is not None else self.to_frame()
        parts = [f"<p><b>{html.escape(self.kind)}</b> result — {len(self.variants)} variant(s), effects: "
                 f"{html.escape(', '.join(sorted(self.effects)) or 'none')}; {len(self.records)} steps in "
                 f"{1e3 * self.wall_time:.1f} ms</p>"]
        if len(frame.columns):
            shown = frame.set_index("variant").T if "variant" in frame else frame.T
            parts.append(shown.to_html(max_rows=60, float_format=lambda v: f"{v:.5g}", header="variant" in frame))
        if self.index is not None:
            rows = self.to_frame()
            parts.append(f"<p>per {html.escape(self.index)} ({len(rows)} rows; all in <code>to_frame()</code>):</p>")
            parts.append(rows.to_html(max_rows=10, max_cols=12, float_format=lambda v: f"{v:.5g}", index=False))
        for failure in self.failures:
            parts.append(f"<p>failed: {html.escape(failure.describe())}</p>")
        parts.append("<details><summary>steps</summary>"
                     + self.steps_frame().to_html(index=False, float_format=lambda v: f"{v:.3f}") + "</details>")
        return "\n".join(parts)

    def to_frame(self, units: Mapping[str, str] | None = None):
        """pandas DataFrame, columns ``"name [unit]"`` (see :mod:`camcontact.report`).

        One row per variant; for a scene with an index (a cam cycle) one row per variant and index
        value (cam angle), holding the per-angle outputs; its scalars are in :meth:`summary_frame`.
        """
        from .report import result_frame

        return result_frame(self, units)

    def summary_frame(self, units: Mapping[str, str] | None = None):
        """pandas DataFrame of the scalar outputs (cycle summaries), one row per variant."""
        from .report import result_frame

        return result_frame(self, units, scalars=True)

    def steps_frame(self):
        """pandas DataFrame of the steps that ran: model, version, variant, wall time [ms]."""
        from .report import steps_frame

        return steps_frame(self)

    @property
    def wall_time(self) -> float:
        """Total wall time of the steps that ran [s]."""
        return sum(record.wall_time for record in self.records)

    def plot(self, **kwargs: Any):
        """Plot the result (needs matplotlib, the ``plot`` extra); returns the Figure."""
        if self.plotter is None:
            raise InputError(f"the {self.kind} scene has no plot")
        return self.plotter(self, **kwargs)
