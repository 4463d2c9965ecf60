"""Built-in models, one module per topic; they register in :mod:`camcontact.registry`.

The registry imports these modules on first lookup of their family, so importing
:mod:`camcontact` does not load them all.
"""
