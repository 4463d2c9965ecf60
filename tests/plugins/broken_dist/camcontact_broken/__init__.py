"""Broken camcontact plugins, one per way a plugin can fail (the tests of tests/plugins/test_broken_plugins.py)."""
