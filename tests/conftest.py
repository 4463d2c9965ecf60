"""Shared fixtures. Every number in a test names its source or the calculation behind it."""

from __future__ import annotations

import pytest

import camcontact as cc
from camcontact import registry


@pytest.fixture
def steel():
    """Bearing steel, E = 210 GPa, nu = 0.3 (Tsuha 2015 Table 6.2)."""
    return cc.Material(E="210 GPa", nu=0.3, name="steel")


@pytest.fixture
def clean_registry():
    """Forget discovered plugins before and after a test that fakes entry points."""
    registry.reset()
    yield registry
    registry.reset()
