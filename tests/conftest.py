"""Test-session settings.

Hypothesis profiles: ``ci`` (selected by ``.ci/run`` through ``HYPOTHESIS_PROFILE=ci``)
derandomizes the examples, so a CI run is reproducible and cannot fail on a new random
draw; the default profile explores new examples on every run (and keeps failures in
``.hypothesis/``), which is how the light-thrust high-speed failure was found.
"""
import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
# long fuzz run (``make fuzz``, tests/test_fuzz.py): fresh random examples, 10^4 per test
settings.register_profile("fuzz", max_examples=10_000, deadline=None, print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "default"))
