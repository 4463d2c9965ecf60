"""Built-in models, one module per topic, marked with :func:`camcontact.models.base.builtin`;
:mod:`camcontact.registry` registers them (the models do not import the registry).

The registry imports these modules on first lookup of their family, so importing
:mod:`camcontact` does not load them all.
"""
