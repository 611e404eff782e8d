"""``ballrace validate --cases`` given more than once runs the files of every glob, each
file once (a repeated option used to keep only the last)."""
from typer.testing import CliRunner

from ballrace.cli import app
from ballrace.validation.schema import load_case_file, default_case_dir, load_cases


def _ids(path):
    return {c.id for c in load_case_file(default_case_dir() / path)}


def test_load_cases_takes_several_globs_and_counts_each_file_once():
    both = {c.id for c in load_cases(["roller.toml", "roller_pub*", "roller"])}
    assert both == _ids("roller.toml") | _ids("roller_published.toml")
    assert {c.id for c in load_cases("roller.toml")} == _ids("roller.toml")


def test_validate_runs_every_cases_option():
    res = CliRunner().invoke(app, ["validate", "--fem", "none", "--cases", "roller.toml",
                                   "--cases", "roller_published.toml"])
    assert res.exit_code == 0, res.output
    n = len(_ids("roller.toml") | _ids("roller_published.toml"))
    total = [ln for ln in res.output.splitlines() if "total" in ln][0]
    assert f"│ {n:>4} │" in total or f" {n} " in total


def test_a_glob_matching_nothing_is_named():
    res = CliRunner().invoke(app, ["validate", "--fem", "none", "--cases", "roller.toml",
                                   "--cases", "nothing_here"])
    assert res.exit_code == 2
    assert "nothing_here" in res.output
