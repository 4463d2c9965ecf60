"""The step graph: the computations of a scene, what each requires and what it provides.

This module sits below both :mod:`camcontact.analysis` (which plans and runs a graph) and
:mod:`camcontact.scenes` (which build one); it imports neither.

A **step function** is a plain top-level function on SI floats/arrays and scene constants (model
objects, conventions, effect switches): its *parameters are what it requires*, the :func:`step`
decorator names the step and declares what it *provides*; it returns a mapping with every provided
name. It stays an ordinary function, so it can be called and tested alone::

    @step("geometry", provides=("E_reduced", "R"))
    def line_geometry(E1, nu1, E2, nu2, R1, R2):
        return {"E_reduced": reduced_modulus(E1, nu1, E2, nu2), "R": reduced_radius(R1, R2)}

    line_geometry(210e9, 0.3, 210e9, 0.3, 0.02, 0.01)   # {'E_reduced': 2.3e11, 'R': 0.00667}

:meth:`Step.of` makes a graph node of it; ``rename=`` binds the same function under other names
(``Step.of(film_parameter, rename={"h": "h_min_in", "Lambda": "Lambda_in"})``). A step whose model
reads further state names (a friction model's ``requires``) takes them through a ``**inputs``
parameter and gets them declared when it is bound (``Step.of(cam_friction, extra=model.requires)``).

A scene builder (registered with :func:`scene_builder` for its component type) returns a
:class:`SceneGraph`: the scene's inputs (SI values, and the chosen model objects and switches under
names of their own), its steps, default outputs, hints for missing inputs and its plot.
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable, Iterable, Mapping
from typing import Any

import attrs

from .errors import InputError

__all__ = ["EFFECTS", "SceneGraph", "Step", "StepFailure", "StepRecord", "add_scene_loader", "builder_for", "checked_request", "given",
           "scene_builder", "scene_builders", "step"]

#: Physical effects a scene may switch on (each scene supports a subset).
EFFECTS = ("elasticity", "piezoviscosity", "compressibility", "thermal", "dynamics", "squeeze", "spin", "mixed",
           "non_newtonian")


@attrs.frozen
class StepSpec:
    """What :func:`step` declares about a step function."""

    name: str
    provides: tuple[str, ...]
    model: str | Callable[..., str] = ""  #: label of the model used, or a function of graph inputs giving it
    version: str | Callable[..., str] = ""
    check: Callable[..., None] | None = None  #: called with graph inputs before anything runs


def step(name: str, provides: Iterable[str], *, model: str | Callable[..., str] = "",
         version: str | Callable[..., str] = "", check: Callable[..., None] | None = None):
    """Declare a function a step named ``name`` that provides ``provides``.

    ``model`` / ``version`` label the step record: a string, or a function whose parameters name
    graph inputs (e.g. ``lambda film_model: film_model.name``). ``check`` is a function of graph
    inputs called when the step is planned, before anything runs (raise InputError to refuse).
    The function is returned unchanged, with the declaration in its ``step`` attribute.
    """
    spec = StepSpec(name, tuple(provides), model, version, check)

    def declare(function):
        function.step = spec
        return function

    return declare


@functools.lru_cache(maxsize=None)
def _parameters(function: Callable) -> tuple[tuple[str, ...], bool]:
    """(names of the named parameters, whether it takes ``**inputs``)."""
    names, extra = [], False
    for parameter in inspect.signature(function).parameters.values():
        if parameter.kind is inspect.Parameter.VAR_KEYWORD:
            extra = True
        elif parameter.kind in (inspect.Parameter.POSITIONAL_OR_KEYWORD, inspect.Parameter.KEYWORD_ONLY):
            names.append(parameter.name)
        else:
            raise TypeError(f"step function {function.__qualname__}: parameter {parameter.name!r} must be nameable")
    return tuple(names), extra


@attrs.frozen
class _Call:
    """Calls a function with state values picked by name (graph names of its parameters)."""

    function: Callable
    arguments: tuple[tuple[str, str], ...]  #: (parameter, graph name)
    extra: tuple[str, ...] = ()  #: graph names passed through ``**inputs``
    optional: tuple[str, ...] = ()  #: graph names passed through ``**inputs`` when the state has them

    def __call__(self, state: Mapping[str, Any]) -> Any:
        kwargs = {parameter: state[name] for parameter, name in self.arguments}
        kwargs.update((name, state[name]) for name in self.extra)
        kwargs.update((name, state[name]) for name in self.optional if name in state)
        return self.function(**kwargs)

    def with_available(self, inputs: Mapping[str, Any]) -> Any:
        """Call with the graph inputs it names (None for those the scene does not give)."""
        return self.function(**{parameter: inputs.get(name) for parameter, name in self.arguments})


def _bind(function: Callable, rename: Mapping[str, str]) -> _Call:
    names, _ = _parameters(function)
    return _Call(function, tuple((name, rename.get(name, name)) for name in names))


@attrs.frozen
class _Outputs:
    """A step function's run: its call, with its outputs renamed to graph names."""

    call: _Call
    rename: tuple[tuple[str, str], ...] = ()

    def __call__(self, state: Mapping[str, Any]) -> Mapping[str, Any]:
        produced = self.call(state)
        if not self.rename:
            return produced
        names = dict(self.rename)
        return {names.get(key, key): value for key, value in produced.items()}


@attrs.frozen
class Step:
    """One computation of a scene graph (usually made by :meth:`Step.of` from a step function).

    ``run`` receives a mapping holding (at least) ``requires`` and returns a mapping with every
    name in ``provides``. ``model`` and ``version`` label the record of the step (strings, or
    callables of the graph inputs, see :meth:`label`); ``check`` (optional) receives the graph
    inputs and validates up front, before anything runs.
    """

    name: str
    requires: tuple[str, ...]
    provides: tuple[str, ...]
    run: Callable[[Mapping[str, Any]], Mapping[str, Any]] = attrs.field(repr=False)
    model: Any = ""
    version: Any = ""
    check: Callable[[Mapping[str, Any]], None] | None = attrs.field(default=None, repr=False)
    #: names the step reads when the graph can give them (a model's ``optional_requires``), else not
    optional: tuple[str, ...] = ()

    @classmethod
    def of(cls, function: Callable, *, name: str | None = None, rename: Mapping[str, str] | None = None,
           extra: Iterable[str] = (), optional: Iterable[str] = (), provides: Iterable[str] | None = None,
           model: Any = None) -> Step:
        """The graph node of a :func:`step` function.

        ``rename`` maps the function's parameter and output names to graph names; ``extra`` names the
        state values passed through its ``**inputs`` parameter (those it names as parameters anyway are
        dropped) and ``optional`` those passed there only when the graph can give them; ``provides``
        narrows the declared outputs to those this binding gives (a film model without h_min);
        ``name`` and ``model`` override the declared step name and model label. Bindings are cached:
        the same arguments give the same node.
        """
        key = (cls, function, name, tuple(sorted((rename or {}).items())), tuple(extra), tuple(optional),
               None if provides is None else tuple(provides), model)
        try:
            hash(key)
        except TypeError:  # an unhashable model label: bound, not cached
            return _node.__wrapped__(*key)
        return _node(*key)

    def label(self, inputs: Mapping[str, Any]) -> tuple[str, str]:
        """(model, version) of the step record, evaluated with the graph ``inputs``."""
        def text(value):
            if isinstance(value, _Call):
                value = value.with_available(inputs)
            return "" if value is None else str(value)

        return text(self.model), text(self.version)


@functools.lru_cache(maxsize=1024)
def _node(cls: type[Step], function: Callable, name: str | None, rename_items: tuple, extra: tuple, optional: tuple,
          provides: tuple | None, model: Any) -> Step:
    """:meth:`Step.of` (cached by its arguments)."""
    spec = getattr(function, "step", None)
    if not isinstance(spec, StepSpec):
        raise TypeError(f"{getattr(function, '__qualname__', function)!r} is not a step function (use @step)")
    rename = dict(rename_items)
    _, takes_extra = _parameters(function)
    call = _bind(function, rename)
    named = {graph for _, graph in call.arguments}
    extra = tuple(name for name in dict.fromkeys(extra) if name not in named)
    optional = tuple(name for name in dict.fromkeys(optional) if name not in named and name not in extra)
    if (extra or optional) and not takes_extra:
        raise TypeError(f"step function {function.__qualname__} takes no **inputs for {list(extra + optional)}")
    call = attrs.evolve(call, extra=extra, optional=optional)
    requires = tuple(dict.fromkeys((*(graph for _, graph in call.arguments), *extra)))
    declared = spec.provides if provides is None else provides
    undeclared = sorted(set(declared) - set(spec.provides))
    if undeclared:
        raise TypeError(f"step function {function.__qualname__} does not provide {undeclared}")
    renamed = tuple((output, rename[output]) for output in spec.provides if output in rename)
    label = spec.model if model is None else model
    return cls(
        name=name or spec.name, requires=requires, provides=tuple(rename.get(output, output) for output in declared),
        run=_Outputs(call, renamed), model=_bind(label, rename) if callable(label) else label,
        version=_bind(spec.version, rename) if callable(spec.version) else spec.version,
        check=None if spec.check is None else _bind(spec.check, rename).with_available, optional=optional,
    )


@attrs.frozen
class SceneGraph:
    """What a scene builder returns for one variant."""

    kind: str
    inputs: Mapping[str, Any]
    steps: tuple[Step, ...]
    default_outputs: tuple[str, ...]
    input_hints: Mapping[str, str] = attrs.field(factory=dict)
    plotter: Callable[..., Any] | None = attrs.field(default=None, repr=False)
    effects: frozenset = frozenset()  #: the effects in force (the scene's defaults if none were asked)
    #: name of the input that indexes array outputs (e.g. ``"cam_angle"``), None for one-row scenes
    index: str | None = None
    #: the outputs that are arrays over ``index`` (the others are scalars: summaries)
    per_index: frozenset = frozenset()
    #: default outputs an asked-for effect calls for: when an input they need is missing the report does not
    #: quietly leave them out (as it does other default outputs) but names the missing input up front
    effect_outputs: frozenset = frozenset()


@attrs.frozen
class StepRecord:
    """What ran: step, model and version, variant, wall time [s], and why it failed ("" when it did not)."""

    step: str
    model: str
    version: str
    variant: str
    wall_time: float
    error: str = ""


@attrs.frozen
class StepFailure:
    """A step of one variant that gave no outputs (``strict=False``): they are NaN in the report.

    ``skipped`` is True for a step that did not run because a step it needs failed; ``reason`` is
    ``"ExceptionType: message"`` (or which failed outputs it needed); ``source`` names the plugin
    model and its distribution when one was involved ("" otherwise).
    """

    step: str
    model: str
    variant: str
    outputs: tuple[str, ...]
    reason: str
    skipped: bool = False
    source: str = ""

    def describe(self) -> str:
        """One line: ``"step 'film' (multigrid): ConvergenceError: ..."``."""
        model = f" ({self.model})" if self.model else ""
        return f"step {self.step!r}{model}: {self.reason}"


def given(**values: Any) -> dict[str, Any]:
    """The scene inputs among ``values`` that are given (not None): an input left out is reported up front,
    with the scene's hint, when a requested output needs it."""
    return {name: value for name, value in values.items() if value is not None}


def checked_request(kind: str, models: Mapping[str, Any], effects: Iterable[str] | None, *, slots: Iterable[str],
                    supported: Iterable[str], default: Iterable[str]) -> frozenset:
    """What a scene builder was asked, checked: the effects in force (``default`` when none were
    asked); an effect the scene does not support or a model slot it does not have is an InputError."""
    supported = frozenset(supported)
    effects = frozenset(default) if effects is None else frozenset(effects)
    unsupported = sorted(effects - supported)
    if unsupported:
        raise InputError(f"effects {unsupported} do not apply to a {kind} scene; it supports {sorted(supported)}")
    slots = tuple(slots)
    unknown = sorted(set(models) - set(slots))
    if unknown:
        raise InputError(f"{kind} scene: unknown model slots {unknown}; slots are {', '.join(map(repr, slots))}")
    return effects


# ----------------------------------------------------------------------------- builders
_BUILDERS: dict[type, Callable[..., SceneGraph]] = {}
_LOADERS: list[Callable[[], None]] = []


def scene_builder(component_type: type):
    """Register the graph builder of a scene component type (used by :mod:`camcontact.scenes`).

    A builder is called as ``builder(component, models=..., effects=...)`` and returns a
    :class:`SceneGraph`.
    """

    def register(function):
        _BUILDERS[component_type] = function
        return function

    return register


def add_scene_loader(loader: Callable[[], None]) -> None:
    """Register ``loader``, a function that registers scene builders, to be called on the first lookup.

    The package registers the import of its built-in scenes this way (``camcontact/__init__.py``), so
    that importing camcontact loads no scene and this module needs to know none.
    """
    _LOADERS.append(loader)


def _load_scenes() -> None:
    for loader in list(_LOADERS):
        loader()
        _LOADERS.remove(loader)


def scene_builders() -> dict[type, Callable[..., SceneGraph]]:
    """The registered scene builders by component type (the built-in scenes included)."""
    _load_scenes()
    return dict(_BUILDERS)


def builder_for(scene: Any) -> Callable[..., SceneGraph]:
    """The registered graph builder of ``scene``'s type (InputError listing the scene types if none)."""
    _load_scenes()
    for cls in type(scene).__mro__:
        if cls in _BUILDERS:
            return _BUILDERS[cls]
    kinds = ", ".join(sorted(c.__name__ for c in _BUILDERS))
    raise InputError(f"Analysis: {type(scene).__name__} is not a scene; scenes are: {kinds}")
