"""The fastest round of a finished benchmark, for the ratios in ``extra_info``.

Under ``--benchmark-disable`` (the benchmarks run once as plain tests) pytest-benchmark
keeps no statistics; the ratios are then not recorded instead of failing.
"""


def fastest(benchmark):
    """Minimum round time of ``benchmark`` [s], or None when timing is disabled."""
    stats = getattr(benchmark, "stats", None)
    return None if stats is None else stats.stats.min


def record(benchmark, key, value):
    """``benchmark.extra_info[key] = value(fastest)`` when the benchmark was timed."""
    t = fastest(benchmark)
    if t is not None:
        benchmark.extra_info[key] = value(t)
