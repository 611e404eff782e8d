"""Every docstring example in the installed ``ballrace`` package runs as a doctest.

Modules are imported by their package names (not file paths) so the doctests see the
same objects users do; modules whose optional dependencies are missing are skipped.
"""
import doctest
import importlib
import pkgutil

import numpy as np
import pytest

import ballrace

MODULES = sorted(
    m.name for m in pkgutil.walk_packages(ballrace.__path__, "ballrace.")
    if ".tests" not in m.name and not m.name.startswith("ballrace.benchmarks")
    and m.name != "ballrace.setup"          # the build script, in a checkout only
)


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    try:
        mod = importlib.import_module(name)
    except ImportError as exc:  # optional extra not installed
        pytest.skip(f"{name}: {exc}")
    res = doctest.testmod(mod, extraglobs={"np": np}, optionflags=doctest.ELLIPSIS
                          | doctest.NORMALIZE_WHITESPACE, verbose=False)
    assert res.failed == 0, f"{res.failed} of {res.attempted} doctests failed in {name}"
