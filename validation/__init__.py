"""ballrace.validation — reference cases, the validation runner and its calculations.

* :mod:`~ballrace.validation.schema` — case files (TOML) and their checks;
* :mod:`~ballrace.validation.registry` — named calculations (SI inputs -> SI outputs);
* ``calc_*`` — the calculations of each area (hertz, subsurface, bearing, life, ehl,
  kinematics and highspeed, fem);
* :mod:`~ballrace.validation.runner` — run, compare, statuses (pass/fail/error/missing/skipped);
* :mod:`~ballrace.validation.distributed` — dask plumbing for FE cases and sweeps;
* :mod:`~ballrace.validation.baseline` — regression snapshots (kept apart from the cases);
* :mod:`~ballrace.validation.figures` — data for the report's plots;
* :mod:`~ballrace.validation.derive` — the mpmath derivations quoted by the cases;
* :mod:`~ballrace.validation.cli` — ``ballrace validate`` (``ballrace teach`` is
  :mod:`ballrace.teach`).

See ``docs/validation.md``.
"""
