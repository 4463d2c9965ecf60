"""The README's marked examples (``<!-- example: NAME -->`` before a python block) run as written."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[2] / "README.md"
EXAMPLES = dict(re.findall(r"<!-- example: (\S+) -->\n```python\n(.*?)\n```", README.read_text(encoding="utf-8"),
                           flags=re.S))


def test_every_python_block_of_the_readme_is_a_marked_example():
    """Every python block runs in the tests: each is marked (an unmarked fragment would go untested)."""
    text = README.read_text(encoding="utf-8")
    assert text.count("```python\n") == len(EXAMPLES) and "add-a-step" in EXAMPLES


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_readme_example_runs(name, tmp_path):
    (tmp_path / "tutorials").symlink_to(README.parent / "tutorials")  # the scene files the README reads
    completed = subprocess.run([sys.executable, "-c", EXAMPLES[name]], capture_output=True, text=True, cwd=tmp_path,
                               timeout=300)
    assert completed.returncode == 0, completed.stderr
    if name == "add-a-step":
        assert "['geometry', 'hertz', 'contact_area']" in completed.stdout
        assert "3.98623" in completed.stdout  # 2 b l with b = 132.874 um (Hertz), l = 15 mm
    # what the comments of the examples say they print
    expected = {"use-from-python": ["megapascal", "available"], "failure-isolation": ["ConvergenceError"],
                "raceway-conventions": ["5.181", "1.98"], "sweep-executor": ["True"], "starved": ["-1.12", " 0.49"],
                "starved-cam": ["276.807", "158.223"],
                "thermal": ["0.943 0.0333 65"]}
    for text in expected.get(name, []):
        assert text in completed.stdout, (name, text, completed.stdout[-2000:])
