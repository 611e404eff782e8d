"""The layering rules, checked on the source (docs: the module docstrings of
ballrace.errors and ballrace.analytic).

* analytic/ never imports fem/, validation/, reports/ or the boundary (the command line,
  commands/, casefiles/, console, units); its only boundary files are the three shims that
  keep the old paths of the moved command and case-file modules importable (``ALIASES``);
* each old path is the moved module itself (the same object), not a copy;
* no import circle among the package's modules at import time;
* no module imports another module's private names (``_name``), except the pairs listed
  in ``KNOWN_PRIVATE`` — a ratchet: the list may only shrink (a new private reach fails).
"""
import ast
from pathlib import Path

import ballrace

ROOT = Path(ballrace.__file__).parent
PACKAGES = ("analytic", "commands", "casefiles", "fem", "meshes", "validation", "reports",
            "teach")

#: (importing file, "module.name") pairs that still reach into another module's privates;
#: each is to be replaced by a public, documented seam.  Do not add to this set.
KNOWN_PRIVATE: set = set()
#: Old module paths kept importable after their modules left analytic/ (and teaching left
#: validation/): each file is a shim that puts the moved module in its place in
#: ``sys.modules`` (so it is the same object).
ALIASES = {"analytic/cli.py": "ballrace.commands.bearing",
           "analytic/shaft_cli.py": "ballrace.commands.shaft",
           "analytic/casefile.py": "ballrace.casefiles.bearing",
           "validation/teach.py": "ballrace.teach.figures"}
#: Names under which a module of the package can be bound in another (``from . import hertz``):
#: every module's own name, found on disk, so a new module is watched from its first commit.
_MODULE_NAMES = {p.stem for p in ROOT.rglob("*.py")
                 if not p.stem.startswith("_") and ".venv" not in p.parts
                 and "tests" not in p.parts} | {"casefile", "teach", "explorer"}


def _sources():
    files = [p for p in ROOT.glob("*.py") if p.name != "setup.py"]
    for pkg in PACKAGES:
        files += sorted((ROOT / pkg).rglob("*.py"))     # sub-packages too (analytic/roller)
    return [(p.relative_to(ROOT).as_posix(), ast.parse(p.read_text(encoding="utf-8")))
            for p in files]


def _module_of(rel: str) -> str:
    parts = rel[:-3].split("/")
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(["ballrace", *parts])


def _absolute(rel: str, node: ast.ImportFrom) -> str:
    if not node.level:
        return node.module or ""
    pkg = _module_of(rel).split(".")
    if not rel.endswith("__init__.py"):
        pkg = pkg[:-1]
    base = pkg[: len(pkg) - node.level + 1]
    return ".".join(base + ([node.module] if node.module else []))


def test_no_module_reaches_into_another_modules_privates_beyond_the_known_ones():
    found = set()
    for rel, tree in _sources():
        for n in ast.walk(tree):
            if isinstance(n, ast.ImportFrom) and n.module:
                if n.module.split(".")[-1].startswith("_"):
                    continue                        # a private helper module of the package
                for a in n.names:
                    if a.name.startswith("_") and not a.name.startswith("__"):
                        found.add((rel, f"{n.module}.{a.name}"))
            elif (isinstance(n, ast.Attribute) and isinstance(n.value, ast.Name)
                  and n.value.id in _MODULE_NAMES and n.attr.startswith("_")
                  and not n.attr.startswith("__")):
                found.add((rel, f"{n.value.id}.{n.attr}"))
    new = found - KNOWN_PRIVATE
    assert not new, f"new reaches into another module's private names: {sorted(new)}"
    gone = KNOWN_PRIVATE - found
    assert not gone, f"remove these from KNOWN_PRIVATE (they are gone): {sorted(gone)}"


def _top_level_imports(rel, tree):
    """Modules of the package imported when ``rel`` is imported (not inside functions)."""
    out = set()
    for n in tree.body:
        nodes = [n]
        if isinstance(n, (ast.If, ast.Try)):
            nodes = list(ast.walk(n))
        for m in nodes:
            if isinstance(m, ast.ImportFrom):
                mod = _absolute(rel, m)
                if mod.startswith("ballrace"):
                    out.add(mod)
                    out.update(f"{mod}.{a.name}" for a in m.names)
            elif isinstance(m, ast.Import):
                out.update(a.name for a in m.names if a.name.startswith("ballrace"))
    return out


def test_no_import_circle_at_import_time():
    srcs = _sources()
    modules = {_module_of(rel) for rel, _ in srcs}
    graph = {_module_of(rel): {m for m in _top_level_imports(rel, tree) if m in modules}
             - {_module_of(rel)} for rel, tree in srcs}
    for mod in list(graph):                  # a package's __init__ is not an edge back
        graph[mod] = {m for m in graph[mod] if not mod.startswith(m + ".")}
    state, stack = {}, []

    def visit(m):
        state[m] = 1
        stack.append(m)
        for d in sorted(graph.get(m, ())):
            if state.get(d) == 1:
                raise AssertionError("import circle: " + " -> ".join(stack[stack.index(d):] + [d]))
            if d not in state:
                visit(d)
        stack.pop()
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            visit(m)


def test_analytic_imports_no_boundary_package():
    boundary = ("ballrace.fem", "ballrace.validation", "ballrace.reports", "ballrace.cli",
                "ballrace.commands", "ballrace.casefiles", "ballrace.console", "ballrace.units",
                "ballrace.teach")
    for rel, tree in _sources():
        if not rel.startswith("analytic/") or rel in ALIASES:
            continue                              # the shims are checked below
        for n in ast.walk(tree):
            mods = ([_absolute(rel, n)] if isinstance(n, ast.ImportFrom)
                    else [a.name for a in n.names] if isinstance(n, ast.Import) else [])
            for mod in mods:
                if rel == "analytic/_checks.py" and mod == "ballrace.units":
                    continue                      # the "6.35 mm" hint (docs/architecture.md)
                assert not mod.startswith(boundary), (rel, mod)


def test_the_alias_files_are_shims_that_import_only_their_module():
    for rel, target in ALIASES.items():
        tree = ast.parse((ROOT / rel).read_text(encoding="utf-8"))
        pkg, name = target.rsplit(".", 1)
        imports = [(n.module, [a.name for a in n.names]) if isinstance(n, ast.ImportFrom)
                   else (None, [a.name for a in n.names])
                   for n in tree.body if isinstance(n, (ast.Import, ast.ImportFrom))]
        assert imports == [(None, ["sys"]), (pkg, [name])], (rel, imports)
        assert len(tree.body) == 4, rel          # docstring, two imports, the sys.modules line


def test_old_module_paths_are_the_moved_modules():
    import importlib
    import sys

    import ballrace.analytic
    import ballrace.analytic.casefile
    import ballrace.analytic.cli
    import ballrace.analytic.shaft_cli
    from ballrace.analytic import casefile, cli, shaft_cli

    for rel, target in ALIASES.items():
        new = importlib.import_module(target)
        old = _module_of(rel)
        assert importlib.import_module(old) is new, old
        assert sys.modules[old] is new, old
        parent, name = old.rsplit(".", 1)
        assert getattr(importlib.import_module(parent), name) is new, old
        assert new.__name__ == target               # one module, named by its new path
    assert casefile is ballrace.analytic.casefile is sys.modules["ballrace.casefiles.bearing"]
    assert cli is ballrace.analytic.cli is sys.modules["ballrace.commands.bearing"]
    assert shaft_cli is ballrace.analytic.shaft_cli is sys.modules["ballrace.commands.shaft"]


def test_monkeypatching_an_old_path_is_seen_through_the_new_one(monkeypatch):
    from ballrace.casefiles import bearing as casefiles_bearing
    from ballrace.commands import bearing as commands_bearing
    from ballrace.commands import shaft as commands_shaft

    def sentinel(*args, **kwargs):
        return "patched"

    monkeypatch.setattr("ballrace.analytic.casefile.load_case", sentinel)
    monkeypatch.setattr("ballrace.analytic.cli.analyze", sentinel)
    monkeypatch.setattr("ballrace.analytic.shaft_cli.analyze", sentinel)
    assert casefiles_bearing.load_case("any.toml") == "patched"
    assert commands_bearing.analyze(None) == "patched"
    assert commands_shaft.analyze(None) == "patched"


def test_no_source_imports_an_old_path():
    old = {_module_of(rel) for rel in ALIASES}
    for rel, tree in _sources():
        if rel in ALIASES:
            continue
        for n in ast.walk(tree):
            if isinstance(n, ast.ImportFrom):
                mod = _absolute(rel, n)
                mods = [mod, *(f"{mod}.{a.name}" for a in n.names)]
            elif isinstance(n, ast.Import):
                mods = [a.name for a in n.names]
            else:
                continue
            assert not old.intersection(mods), (rel, sorted(old.intersection(mods)))
