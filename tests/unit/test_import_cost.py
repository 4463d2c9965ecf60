"""Importing camcontact loads no plugin, compiles no numba kernel, imports no pandas."""

import subprocess
import sys
import textwrap


def test_import_is_light():
    code = textwrap.dedent(
        """
        import importlib.metadata as md
        def refuse(*args, **kwargs):
            raise AssertionError("entry points were looked up at import")
        md.entry_points = refuse
        import sys
        import camcontact
        from camcontact import registry
        assert "numba" not in sys.modules, "numba imported"
        assert "pandas" not in sys.modules, "pandas imported"
        assert "matplotlib" not in sys.modules, "matplotlib imported"
        assert registry.discovered_families() == (), registry.discovered_families()
        assert not [m for m in sys.modules if m.startswith("camcontact.models.film")], "film models imported"
        print("ok")
        """
    )
    completed = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.strip() == "ok"
