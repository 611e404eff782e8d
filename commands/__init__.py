"""The command-line commands of the formula layer (boundary code).

``ballrace bearing`` (:mod:`ballrace.commands.bearing`) and ``ballrace shaft``
(:mod:`ballrace.commands.shaft`): each module reads its case file, calls the formulas of
:mod:`ballrace.analytic` with SI floats, and renders the result as tables in engineering
units or, with ``--json``, as SI numbers.  Registered on the main app by :mod:`ballrace.cli`.
"""
