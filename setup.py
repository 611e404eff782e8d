"""Build hook of the optional compiled kernel; the project is described in pyproject.toml.

``ballrace.analytic._ldkernel`` (analytic/_ldkernel.c, the one-case Newton iteration of the
static load distribution) is built when a C compiler and the Python headers are present.
It is optional: without them the install goes on and loaddist uses its NumPy iteration
(the same answers, some 5 times slower for one load case; docs/performance.md).
"""
from setuptools import Extension, setup

setup(ext_modules=[Extension("ballrace.analytic._ldkernel", ["analytic/_ldkernel.c"],
                             optional=True)])
