"""What a new user meets first: the package namespace, the command line's promises."""
from __future__ import annotations

import ballrace

SUBPACKAGES = {"analytic", "fem", "meshes", "validation", "reports", "cli", "console", "units"}


def test_public_namespace_is_the_documented_one():
    """dir(ballrace) shows the API (``__all__``) and sub-packages, not helper imports
    such as ``logging`` or ``annotations``."""
    public = {n for n in dir(ballrace) if not n.startswith("_")}
    assert public - SUBPACKAGES == set(ballrace.__all__) - {"__version__"}
