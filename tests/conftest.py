"""Test-session settings.

Hypothesis profiles: ``ci`` (selected by ``.ci/run`` through ``HYPOTHESIS_PROFILE=ci``)
derandomizes the examples, so a CI run is reproducible and cannot fail on a new random
draw; the default profile explores new examples on every run (and keeps failures in
``.hypothesis/``), which is how the light-thrust high-speed failure was found.
"""
import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "default"))
