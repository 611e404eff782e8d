"""Teaching's old import paths after it left ``validation/`` for ``teach/``.

``ballrace.validation.teach`` is the moved module itself (``ballrace.teach.figures``, the
same object: a monkeypatch through either path is seen through the other);
``ballrace.validation.explorer``, split in ``compute``, ``page``, ``server`` and
``commands``, re-exports every public name it had (the same objects).  The package's own
code imports only the new paths, and the API pages document each module once.
"""
from __future__ import annotations

import ast
import importlib
import importlib.util
import sys
from pathlib import Path

from typer.testing import CliRunner

import ballrace

ROOT = Path(ballrace.__file__).parent

#: The public names of ``validation/explorer.py`` before the split, and where each lives now.
OLD_EXPLORER = {
    "compute": ("FIELDS", "DEFAULTS", "EXPORT_GRID", "TRACTION_MAX", "InputError", "compute",
                "compute_safe", "case_inputs", "unpack", "export_grid", "export_params"),
    "page": ("page", "export_html"),
    "server": ("MAX_BODY", "MAX_QUERY", "MAX_TEXT", "MAX_CASE_BYTES", "RequestError",
               "check_text", "check_request", "resolve_case", "make_server"),
    "commands": ("register_commands", "SMALL_GRID"),
}


def test_validation_teach_is_the_figures_module():
    import ballrace.validation
    import ballrace.validation.teach
    from ballrace.teach import figures
    from ballrace.validation import teach

    assert teach is figures is sys.modules["ballrace.validation.teach"]
    assert ballrace.validation.teach is figures
    assert figures.__name__ == "ballrace.teach.figures"
    from ballrace.validation.teach import subsurface_figure, title_text, traction_figure

    assert (subsurface_figure, title_text, traction_figure) == (
        figures.subsurface_figure, figures.title_text, figures.traction_figure)


def test_validation_explorer_reexports_every_old_public_name():
    from ballrace.validation import explorer

    for module, names in OLD_EXPLORER.items():
        new = importlib.import_module(f"ballrace.teach.{module}")
        for name in names:
            assert getattr(explorer, name) is getattr(new, name), (module, name)
    assert explorer.__all__ == ["FIELDS", "DEFAULTS", "compute", "case_inputs", "export_html",
                                "export_grid", "make_server", "page", "register_commands",
                                "EXPORT_GRID"]                     # as before the split


def test_the_old_explorer_path_still_computes():
    from ballrace.validation import explorer

    r = explorer.compute(explorer.DEFAULTS)
    # the circle of the defaults: tau_max = 0.31 p0 (Johnson, Contact Mechanics, 1985, §3.4)
    assert abs(r["table"]["tau_max"] / r["table"]["p0"] - 0.31) < 0.005


def test_monkeypatching_the_old_teach_path_is_seen_by_the_command(monkeypatch, tmp_path):
    from ballrace.cli import app

    seen = []

    def fake(*args, **kwargs):
        seen.append(kwargs["path"])
        return {"p_max [Pa]": 1e9}

    monkeypatch.setattr("ballrace.validation.teach.subsurface_figure", fake)
    res = CliRunner().invoke(app, ["teach", "subsurface", "--out", str(tmp_path / "t.png")])
    assert res.exit_code == 0, res.output
    assert seen == [tmp_path / "t.png"]


def _sources():
    files = [p for p in ROOT.glob("*.py") if p.name != "setup.py"]
    for pkg in ("analytic", "commands", "casefiles", "fem", "meshes", "validation", "reports",
                "teach"):
        files += sorted((ROOT / pkg).glob("*.py"))
    return [p.relative_to(ROOT).as_posix() for p in files]


def _imported(rel: str, node) -> set:
    """The modules (and module.name pairs) an import statement of ``rel`` names."""
    if isinstance(node, ast.Import):
        return {a.name for a in node.names}
    pkg = ["ballrace", *rel.split("/")[:-1]]
    base = pkg[: len(pkg) - node.level + 1] if node.level else []
    mod = ".".join(base + ([node.module] if node.module else []))
    return {mod, *(f"{mod}.{a.name}" for a in node.names)}


def test_no_source_imports_the_old_teaching_paths():
    old = {"ballrace.validation.explorer", "ballrace.validation.teach"}
    for rel in _sources():
        if rel in ("validation/explorer.py", "validation/teach.py"):
            continue
        tree = ast.parse((ROOT / rel).read_text(encoding="utf-8"))
        for n in ast.walk(tree):
            if isinstance(n, (ast.Import, ast.ImportFrom)):
                hit = old & _imported(rel, n)
                assert not hit, (rel, sorted(hit))


def test_the_api_pages_leave_out_the_old_paths():
    spec = importlib.util.spec_from_file_location("ballrace_docs_conf_paths",
                                                  ROOT / "docs" / "conf.py")
    conf = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(conf)
    moved = conf.autosummary_context["moved_modules"]
    assert {"ballrace.validation.explorer", "ballrace.validation.teach"} <= set(moved)
    assert not [m for m in moved if m.startswith("ballrace.teach")]
