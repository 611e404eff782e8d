"""Benchmarks share the tests' slow scalar references (tests/mpref.py)."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests"))
