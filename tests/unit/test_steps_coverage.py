"""Every step function has a unit test: a new step without one fails here.

Enumerates the modules of the ``camcontact.steps`` package (pkgutil), takes every function defined there
whose ``step`` attribute is a :class:`camcontact.step_graph.StepSpec`, and asserts that its name occurs in
the source of at least one ``tests/unit/test_steps_*.py`` file (other than this one).
"""

import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import camcontact.steps
from camcontact.step_graph import StepSpec

HERE = Path(__file__).resolve()


def step_functions():
    """{qualified name: function} of the step functions defined in the camcontact.steps modules."""
    found = {}
    for info in pkgutil.iter_modules(camcontact.steps.__path__):
        module = importlib.import_module(f"camcontact.steps.{info.name}")
        for name, obj in vars(module).items():
            if (inspect.isfunction(obj) and obj.__module__ == module.__name__
                    and isinstance(getattr(obj, "step", None), StepSpec)):
                found[f"{module.__name__}.{name}"] = obj
    return found


def test_every_step_function_is_named_in_a_step_unit_test():
    functions = step_functions()
    assert len(functions) >= 60  # 64 when this test was written: the enumeration itself works
    sources = [path.read_text(encoding="utf-8") for path in sorted(HERE.parent.glob("test_steps_*.py"))
               if path.resolve() != HERE]
    assert sources
    missing = sorted(qualified for qualified, function in functions.items()
                     if not any(re.search(rf"\b{re.escape(function.__name__)}\b", text) for text in sources))
    assert not missing, f"step functions without a unit test in tests/unit/test_steps_*.py: {missing}"
