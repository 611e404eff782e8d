"""The speed-of-the-core table (``core_table.py``): every row with its floor or peer,
measured in this run; printed at the end of ``make bench``."""
import core_table
from conftest import CORE_TABLE


def test_core_table(benchmark):
    res = benchmark.pedantic(core_table.measure, rounds=1, iterations=1)
    CORE_TABLE.append((core_table.machine(), core_table.table(res)))
    for name, r in res:
        if r is not None:
            benchmark.extra_info[name] = {"now": r.now, "floor": r.floor, "ratio": r.ratio}
    assert all(r is None or r.now == r.now for _, r in res)       # every row measured
