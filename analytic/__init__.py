"""Analytic rolling-contact and ball-bearing formulas (SI units, numpy-vectorized).

Never imports :mod:`ballrace.fem`: the FE model checks this package, not the reverse.
"""
