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


def test_the_readme_has_marked_examples():
    assert "add-a-step" in EXAMPLES


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_readme_example_runs(name, tmp_path):
    completed = subprocess.run([sys.executable, "-c", EXAMPLES[name]], capture_output=True, text=True, cwd=tmp_path,
                               timeout=300)
    assert completed.returncode == 0, completed.stderr
    if name == "add-a-step":
        assert "['geometry', 'hertz', 'contact_area']" in completed.stdout
        assert "3.98623" in completed.stdout  # 2 b l with b = 132.874 um (Hertz), l = 15 mm
