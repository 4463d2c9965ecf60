"""Components: attrs classes with pint-typed fields, validated at construction."""

from .line_contact import Body, LineContact
from .lubricant import Lubricant, LubricantState
from .material import Material

__all__ = ["Body", "LineContact", "Lubricant", "LubricantState", "Material"]
