"""Scene builders: how each scene component becomes a graph of analysis steps.

Importing this package registers the built-in scenes with :mod:`camcontact.analysis`.
"""

from . import ball_cone_cvt, bearing, cam_follower, line_contact, raceway_contact  # noqa: F401
