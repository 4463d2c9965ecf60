"""A plugin that calls sys.exit when it is imported."""

import sys

sys.exit("camcontact_broken.exits: leaving on import")
