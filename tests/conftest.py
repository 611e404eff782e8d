"""Test-session settings.

Hypothesis profiles: ``ci`` (selected by ``.ci/run`` through ``HYPOTHESIS_PROFILE=ci``)
derandomizes the examples, so a CI run is reproducible and cannot fail on a new random
draw; the default profile explores new examples on every run (and keeps failures in
``.hypothesis/``), which is how the light-thrust high-speed failure was found.

Per-test time limit (pytest-timeout, the ``dev`` extra): ``timeout`` in pyproject.toml
(300 s) for every test, so that a solver that stops converging fails its test instead of
holding ``make test`` or CI; the standard-level FE checks (``slow``) get
:data:`SLOW_TIMEOUT` and the long fuzz run (``HYPOTHESIS_PROFILE=fuzz``, ``make fuzz``)
:data:`FUZZ_TIMEOUT` per test.  A test's own ``@pytest.mark.timeout`` wins.
"""
import os

import pytest
from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
# long fuzz run (``make fuzz``, tests/test_fuzz.py): fresh random examples, 10^4 per test
settings.register_profile("fuzz", max_examples=10_000, deadline=None, print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "default"))

#: Time limit of one standard-level FE check (``-m slow``; ``make test-fem`` runs them
#: all in about 20 minutes) [s].
SLOW_TIMEOUT = 1800
#: Time limit of one test of the long fuzz run (10^4 examples) [s].
FUZZ_TIMEOUT = 4 * 3600


def pytest_collection_modifyitems(config, items):
    """Longer time limits for the slow FE checks and the long fuzz run (only when
    pytest-timeout is installed: without it the ``timeout`` marker is unknown)."""
    if not config.pluginmanager.hasplugin("timeout"):
        return
    fuzz = os.environ.get("HYPOTHESIS_PROFILE") == "fuzz"
    for item in items:
        if item.get_closest_marker("timeout") is not None:
            continue
        if fuzz and item.path.name == "test_fuzz.py":
            item.add_marker(pytest.mark.timeout(FUZZ_TIMEOUT))
        elif item.get_closest_marker("slow") is not None:
            item.add_marker(pytest.mark.timeout(SLOW_TIMEOUT))
