"""camcontact-extras: models that camcontact finds through entry points only.

* ``martin`` (film_models) — Martin (1916) rigid-isoviscous line-contact film;
* ``blok`` (film_models) — Blok rigid-piezoviscous line-contact film;
* ``greenwood_tripp`` (friction_models) — Greenwood–Tripp (1970) asperity load share and
  mixed friction coefficient.

Nothing here registers itself on import: ``pyproject.toml`` declares the entry points,
and camcontact's registry loads them on first use of the family.
"""

__version__ = "0.1.0"
