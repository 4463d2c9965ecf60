"""The plugin registry: model families, built-ins and entry-point discovery.

* Families are listed in :data:`camcontact.models.base.FAMILIES`; the entry-point group of
  family ``f`` is ``"camcontact." + f`` (e.g. ``camcontact.film_models``).
* Built-in models are marked in code with the :func:`camcontact.models.base.builtin`
  decorator; the registry imports the modules that hold a family's built-ins
  (:data:`BUILTIN_MODULES`) only when that family is first looked up and registers the
  marked classes they define, so ``import camcontact`` loads no model and compiles nothing
  (and the models do not import the registry).
* Third-party plugins are discovered lazily, per family, on first lookup, through
  :func:`importlib.metadata.entry_points`, and reached by their *entry-point name* (the
  model's own ``name`` labels its results). A plugin that fails to import — whatever it
  raises, ``SystemExit`` and ``KeyboardInterrupt`` included (the user's own Ctrl-C while it
  loads is re-raised) — or does not fit its family gives a
  :class:`~camcontact.errors.PluginLoadWarning` and is listed as failed; the others are
  unaffected. A plugin whose name clashes with a built-in gives a
  :class:`~camcontact.errors.PluginNameClashWarning` and the built-in wins.
* :func:`origin` says where a model object comes from (a plugin's distribution), so that an
  analysis names the plugin and its distribution when it fails.
* ``CAMCONTACT_DISABLE_PLUGIN_AUTOLOAD=1`` switches entry-point discovery off.
* Unknown names raise :class:`~camcontact.errors.UnknownModelError` listing what is available.
"""

from __future__ import annotations

import importlib
import importlib.metadata as metadata
import os
import signal
import threading
import warnings
from collections.abc import Callable, Iterable
from typing import Any

import attrs

from .errors import (
    PluginLoadError,
    PluginLoadWarning,
    PluginNameClashWarning,
    UnknownModelError,
)
from .models.base import FAMILIES, CallableModel, Model, builtin_classes, check_family

__all__ = [
    "PluginInfo",
    "available",
    "entries",
    "families",
    "get",
    "get_class",
    "origin",
    "reset",
]

ENTRY_POINT_PREFIX = "camcontact."
DISABLE_ENV = "CAMCONTACT_DISABLE_PLUGIN_AUTOLOAD"

#: Modules holding the built-in models of each family (imported on first lookup).
BUILTIN_MODULES: dict[str, tuple[str, ...]] = {
    "motion_laws": ("camcontact.models.motion_laws",),
    "viscosity_laws": (
        "camcontact.models.viscosity_pressure",
        "camcontact.models.viscosity_temperature",
    ),
    "density_laws": ("camcontact.models.density",),
    "film_models": ("camcontact.models.film_line", "camcontact.models.film_point", "camcontact.models.film_multigrid",
                    "camcontact.models.film_multigrid_point"),
    "friction_models": ("camcontact.models.friction",),
    "wear_models": ("camcontact.models.wear",),
    "life_models": ("camcontact.models.life_iso281", "camcontact.models.life_lundberg_palmgren"),
    "traction_models": ("camcontact.models.traction", "camcontact.models.traction_fluid",
                        "camcontact.models.traction_spin"),
    "bearing_friction_models": ("camcontact.models.bearing_friction",),
}


@attrs.frozen
class PluginInfo:
    """One row of the registry listing (``camcontact plugins``)."""

    name: str
    family: str
    source: str  #: distribution name and version, or "camcontact (built-in)"
    reference: str
    status: str  #: "ok", "failed: ...", or "shadowed by ..."
    target: str = ""  #: the object path ("module:attr")


_lock = threading.RLock()
_builtins: dict[str, dict[str, type[Model]]] = {family: {} for family in FAMILIES}
_plugins: dict[str, dict[str, type[Model] | Model]] = {}
_infos: dict[str, list[PluginInfo]] = {}
_builtins_imported: set[str] = set()


def families() -> tuple[str, ...]:
    """Names of the plugin families."""
    return tuple(FAMILIES)


def _register_builtin(cls: type[Model]) -> None:
    """Register a built-in model under ``cls.name`` in ``cls.family``; TypeError for two of one name."""
    existing = _builtins[cls.family].get(cls.name)
    if existing is not None and existing is not cls:
        raise TypeError(f"two built-in {cls.family} models are named {cls.name!r}")
    _builtins[cls.family][cls.name] = cls


def _import_builtins(family: str) -> None:
    """Import the built-in modules of ``family`` and register the classes they mark (once)."""
    if family in _builtins_imported:
        return
    for name in BUILTIN_MODULES.get(family, ()):
        for cls in builtin_classes(importlib.import_module(name)):
            _register_builtin(cls)
    _builtins_imported.add(family)


def _autoload_disabled() -> bool:
    return os.environ.get(DISABLE_ENV, "").strip().lower() not in ("", "0", "false", "no")


def _entry_points(group: str) -> Iterable[metadata.EntryPoint]:
    return metadata.entry_points(group=group)


def _fits_family(obj: Any, family: str) -> str:
    """Empty string if ``obj`` is a usable model of ``family``, else the reason."""
    base = FAMILIES[family]
    if isinstance(obj, type):
        if not issubclass(obj, base):
            return f"{obj.__module__}.{obj.__qualname__} is not a subclass of {base.__qualname__}"
        if getattr(obj, "__abstractmethods__", None):
            return f"{obj.__qualname__} leaves abstract methods {sorted(obj.__abstractmethods__)}"
    elif not isinstance(obj, base):
        return f"{obj!r} is neither a {base.__qualname__} subclass nor an instance of one"
    if not getattr(obj, "name", ""):
        return "the model has no 'name'"
    return ""


def _load(ep: metadata.EntryPoint) -> Any:
    """``ep.load()``; a KeyboardInterrupt it raises is re-raised only when the user pressed Ctrl-C
    (a SIGINT arrived while it loaded), else it is the plugin's own and fails the plugin like any
    other exception (the SIGINT watch needs the main thread; elsewhere every KeyboardInterrupt is
    re-raised)."""
    interrupted: list[bool] = []
    watching = threading.current_thread() is threading.main_thread()
    previous = signal.getsignal(signal.SIGINT) if watching else None
    if watching:

        def watch(signum, frame):
            interrupted.append(True)
            if callable(previous):
                previous(signum, frame)
            elif previous != signal.SIG_IGN:
                raise KeyboardInterrupt

        signal.signal(signal.SIGINT, watch)
    try:
        return ep.load()
    except KeyboardInterrupt:
        if not watching or interrupted:
            raise
        raise PluginLoadError(f"entry point {ep.value} raised KeyboardInterrupt on import (no Ctrl-C was "
                              "pressed)") from None
    finally:
        if watching:
            signal.signal(signal.SIGINT, signal.SIG_DFL if previous is None else previous)


def _discover(family: str) -> None:
    """Load the entry points of ``family`` once (thread-safe)."""
    if family in _plugins:
        return
    _import_builtins(family)
    loaded: dict[str, type[Model] | Model] = {}
    infos = [
        PluginInfo(name, family, "camcontact (built-in)", cls.reference, "ok",
                   f"{cls.__module__}:{cls.__qualname__}")
        for name, cls in sorted(_builtins[family].items())
    ]
    if not _autoload_disabled():
        for ep in _entry_points(ENTRY_POINT_PREFIX + family):
            dist = getattr(ep, "dist", None)
            source = f"{dist.name} {dist.version}" if dist is not None else "unknown distribution"
            try:
                obj = _load(ep)
                reason = _fits_family(obj, family)
            except KeyboardInterrupt:  # the user's Ctrl-C (_load turns a plugin's own into PluginLoadError)
                raise
            except BaseException as exc:
                warnings.warn(
                    f"camcontact plugin {ep.name!r} ({ep.value}) of family {family} from {source} "
                    f"could not be loaded and is skipped: {type(exc).__name__}: {exc}",
                    PluginLoadWarning,
                    stacklevel=3,
                )
                infos.append(PluginInfo(ep.name, family, source, "", f"failed: {type(exc).__name__}: {exc}", ep.value))
                continue
            if reason:
                warnings.warn(
                    f"camcontact plugin {ep.name!r} ({ep.value}) from {source} does not fit family "
                    f"{family} and is skipped: {reason}",
                    PluginLoadWarning,
                    stacklevel=3,
                )
                infos.append(PluginInfo(ep.name, family, source, "", f"failed: {reason}", ep.value))
                continue
            name = ep.name
            reference = str(getattr(obj, "reference", ""))
            if name in _builtins[family] or name in loaded:
                winner = "the built-in" if name in _builtins[family] else "an earlier plugin"
                warnings.warn(
                    f"camcontact plugin {name!r} ({ep.value}) from {source} clashes with {winner} "
                    f"{family} model of the same name; {winner} is used",
                    PluginNameClashWarning,
                    stacklevel=3,
                )
                infos.append(PluginInfo(name, family, source, reference,
                                        f"shadowed by {winner}", ep.value))
                continue
            loaded[name] = obj
            infos.append(PluginInfo(name, family, source, reference, "ok", ep.value))
    _plugins[family] = loaded
    _infos[family] = infos


def _table(family: str) -> dict[str, type[Model] | Model]:
    with _lock:
        check_family(family)
        _discover(family)
        return {**_plugins[family], **_builtins[family]}


def available(family: str) -> tuple[str, ...]:
    """Names of the usable models of ``family`` (built-ins and loaded plugins), sorted."""
    return tuple(sorted(_table(family)))


def get_class(family: str, name: str) -> type[Model] | Model:
    """The registered class (or plugin instance) of ``name`` in ``family``."""
    table = _table(family)
    try:
        return table[name]
    except KeyError:
        failed = [i.name for i in _infos.get(family, []) if i.status.startswith("failed")]
        hint = f"; plugins that failed to load: {', '.join(failed)}" if failed else ""
        raise UnknownModelError(
            f"no {family} model named {name!r}; available: {', '.join(sorted(table)) or '(none)'}{hint}"
        ) from None


def get(
    family: str,
    model: str | Model | type[Model] | Callable[..., Any],
    *,
    requires: tuple[str, ...] = (),
    provides: tuple[str, ...] = (),
    **parameters: Any,
) -> Model:
    """A model instance of ``family`` from a name, a class, an instance or a function.

    Parameters
    ----------
    family : str
        One of :func:`families`.
    model : str, Model subclass, Model instance or callable
        A registered name; a model class (instantiated with ``parameters``); a model
        instance (returned as is); or a plain function, wrapped so that it is called
        with ``requires`` as keywords and returns ``provides``.
    **parameters
        Keyword parameters of the model class (e.g. ``p0`` of ``roelands``).
    """
    check_family(family)
    if isinstance(model, str):
        model = get_class(family, model)
    if isinstance(model, type):
        reason = _fits_family(model, family)
        if reason:
            raise UnknownModelError(f"cannot use {model!r} as a {family} model: {reason}")
        return model(**parameters)
    if isinstance(model, Model):
        reason = _fits_family(model, family)
        if reason:
            raise UnknownModelError(f"cannot use {model!r} as a {family} model: {reason}")
        if parameters:
            return attrs.evolve(model, **parameters) if attrs.has(type(model)) else model
        return model
    if callable(model):
        return CallableModel(model, family, requires=requires, provides=provides)
    raise UnknownModelError(
        f"a {family} model must be a name, a model class or instance, or a function; got {model!r}"
    )


def origin(model: Any) -> PluginInfo | None:
    """The registry row of the plugin that ``model`` (a model object or class) comes from, or None for
    a built-in model and for a model given in code (not through an entry point)."""
    cls = model if isinstance(model, type) else type(model)
    with _lock:
        for family, loaded in _plugins.items():
            for name, obj in loaded.items():
                if obj is model or obj is cls:
                    return next(info for info in _infos[family] if info.name == name and info.status == "ok")
    return None


def entries(family: str | None = None) -> list[PluginInfo]:
    """All registry rows (built-in, loaded, failed, shadowed) of one or every family."""
    selected = [family] if family is not None else list(FAMILIES)
    rows: list[PluginInfo] = []
    for fam in selected:
        _table(fam)
        rows.extend(_infos[fam])
    return rows


def discovered_families() -> tuple[str, ...]:
    """Families whose plugins have been looked up so far (for tests and diagnostics)."""
    return tuple(_plugins)


def reset() -> None:
    """Forget discovered plugins (they are looked up again on next use). For tests."""
    with _lock:
        _plugins.clear()
        _infos.clear()
