"""Benchmarks share the tests' slow scalar references (tests/mpref.py).

``bench_core.py`` measures the speed-of-the-core table (``core_table.py``); it is printed
at the end of the session, after pytest-benchmark's own tables.
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

#: filled by bench_core.py: (machine, table text)
CORE_TABLE = []


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    for machine, text in CORE_TABLE:
        terminalreporter.section("speed of the core (benchmarks/core_table.py)")
        terminalreporter.write_line(f"machine: {machine}")
        for line in text.splitlines():
            terminalreporter.write_line(line)
