"""The documentation site: generated validation pages, docstring escaping, internal links.

Fast tests check the pieces (the case-page generator against the TOML files, the
``|x|`` escaping of docstrings, the link checker on a small hand-made site).  The slow
test builds the site with warnings as errors and checks that it has no broken internal
link, that MathJax is served locally, that every public function of the analytic modules
has an API entry and every validation case a page entry.  ``make test-docs`` runs it on
the full build (``BALLRACE_DOCS_HTML=docs/_build/html``, gallery executed); without that
variable the slow test builds into a temporary folder with the gallery not executed.
"""
from __future__ import annotations

import importlib
import os
import re
import shutil
import subprocess
import sys
import tomllib
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
CASES = ROOT / "validation" / "cases"
sys.path.insert(0, str(DOCS / "_ext"))


# --------------------------------------------------------------------------- link checker
class _Links(HTMLParser):
    def __init__(self):
        super().__init__()
        self.links: list[str] = []
        self.ids: set[str] = set()

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for key in ("id", "name"):
            if a.get(key):
                self.ids.add(a[key])
        for key in ("href", "src"):
            if a.get(key) is not None and not (tag == "a" and key == "src"):
                self.links.append(a[key])


def _parse(path: Path) -> _Links:
    p = _Links()
    p.feed(path.read_text(encoding="utf-8", errors="replace"))
    return p


def broken_links(site: Path) -> list[str]:
    """Internal links of a built HTML site that point to a missing file or anchor.

    External links (with a scheme or ``//``), ``mailto:`` and ``data:`` are not followed
    (the site must work offline, which :func:`external_assets` checks separately).
    """
    site = Path(site)
    pages = {p.resolve(): None for p in site.rglob("*.html")}
    bad = []
    for page in list(pages):
        parsed = pages[page] = pages[page] or _parse(page)
        for link in parsed.links:
            u = urlsplit(link)
            if u.scheme or link.startswith("//") or not (u.path or u.fragment):
                continue
            target = (page.parent / unquote(u.path)).resolve() if u.path else page
            if target.is_dir():
                target = target / "index.html"
            if not target.exists():
                bad.append(f"{page.relative_to(site.resolve())}: {link} (no such file)")
                continue
            if u.fragment and target.suffix == ".html":
                if target not in pages:
                    pages[target] = None
                tp = pages[target] or _parse(target)
                pages[target] = tp
                if unquote(u.fragment) not in tp.ids:
                    bad.append(f"{page.relative_to(site.resolve())}: {link} (no such anchor)")
    return bad


def external_assets(site: Path) -> list[str]:
    """Scripts, stylesheets and images that a page would fetch from the network."""
    out = []
    pat = re.compile(r"<(?:script|img|link)\b[^>]*\b(?:src|href)=\"((?:https?:)?//[^\"]+)\"")
    for page in Path(site).rglob("*.html"):
        for m in pat.finditer(page.read_text(encoding="utf-8", errors="replace")):
            tag = page.read_text(encoding="utf-8")[m.start():m.end()]
            if "<link" in tag and "stylesheet" not in tag and "icon" not in tag:
                continue          # rel="canonical" and the like are not fetched
            out.append(f"{page.name}: {m.group(1)}")
    return out


def test_link_checker_finds_missing_files_and_anchors(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "index.html").write_text(
        '<a href="sub/page.html#here">ok</a> <a href="sub/page.html#gone">bad anchor</a>'
        '<a href="missing.html">bad file</a> <a href="https://example.org/x">external</a>'
        '<img src="img.png"> <a href="#top">self</a><span id="top"></span>')
    (tmp_path / "sub" / "page.html").write_text('<h1 id="here">x</h1><a href="../">up</a>')
    bad = broken_links(tmp_path)
    assert sorted(bad) == sorted(["index.html: sub/page.html#gone (no such anchor)",
                                  "index.html: missing.html (no such file)",
                                  "index.html: img.png (no such file)"])


# --------------------------------------------------------------------------- case pages
def _all_cases():
    for path in sorted(CASES.glob("*.toml")):
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        for case in data.get("case", []):
            yield path, case


def test_case_pages_list_every_case_with_its_expectations(tmp_path):
    import casepages

    written = casepages.write_pages(tmp_path)
    assert (tmp_path / "cases" / "index.rst") in written
    n = 0
    for path, case in _all_cases():
        n += 1
        page = (tmp_path / "cases" / f"{path.stem}.rst").read_text(encoding="utf-8")
        assert f".. _case-{case['id']}:" in page
        assert case["calculation"] in page
        for name, spec in case.get("expected", {}).items():
            assert f"``{name}``" in page, (case["id"], name)
            if "value" in spec:
                assert str(spec["value"]).replace("`", "'") in page, (case["id"], name)
            words = str(spec.get("reason", "")).split()
            assert not words or words[0].replace("_", "\\_") in page
        for name in case.get("inputs", {}):
            assert f"``{name}``" in page, (case["id"], name)
    index = (tmp_path / "cases" / "index.rst").read_text(encoding="utf-8")
    assert f"{n} cases in {len(list(CASES.glob('*.toml')))} files" in index


def test_case_pages_merge_defaults():
    import casepages

    merged = casepages.merge_defaults(
        {"source": {"author": "Johnson", "year": 1985}, "inputs": {"E1": "200 GPa"}},
        {"source": {"reference": "§3.4"}, "inputs": {"load": "1 N"}, "id": "x"})
    assert merged["source"] == {"author": "Johnson", "year": 1985, "reference": "§3.4"}
    assert merged["inputs"] == {"E1": "200 GPa", "load": "1 N"}


# --------------------------------------------------------------------------- docstrings
def _conf():
    spec = importlib.util.spec_from_file_location("ballrace_docs_conf", DOCS / "conf.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_absolute_value_bars_are_escaped_only_in_prose():
    pytest.importorskip("sphinx")
    lines = ["error |got - value| <= atol and |x|", "``|x|`` and :math:`|x|` stay",
             ".. math::", "", "   |x|^2", "back", ">>> abs(-1)  # |x|", "1", "",
             "a | b | c"]
    _conf().escape_absolute_values(lines)
    assert lines == ["error \\|got - value\\| <= atol and \\|x\\|",
                     "``|x|`` and :math:`|x|` stay", ".. math::", "", "   |x|^2", "back",
                     ">>> abs(-1)  # |x|", "1", "", "a | b | c"]


# --------------------------------------------------------------------------- built site
@pytest.fixture(scope="module")
def site(tmp_path_factory):
    pytest.importorskip("sphinx")
    pytest.importorskip("sphinx_gallery")
    given = os.environ.get("BALLRACE_DOCS_HTML")
    if given:
        return Path(given)
    out = tmp_path_factory.mktemp("site")
    # build a copy of docs/ (its generated folders left out), so this test never rewrites
    # the pages of a full `make docs` build with the gallery not executed
    src = out / "docs"
    shutil.copytree(DOCS, src, ignore=shutil.ignore_patterns(
        "_build", "auto_gallery", "generated", "cases", "sg_execution_times.rst"))
    cmd = [sys.executable, "-m", "sphinx", "-b", "html", "-W", "--keep-going", "-q",
           "-D", "plot_gallery=0", "-d", str(out / ".doctrees"), str(src), str(out / "html")]
    env = {**os.environ, "MPLBACKEND": "Agg", "BALLRACE_DOCS_ROOT": str(ROOT)}
    res = subprocess.run(cmd, capture_output=True, text=True, env=env)
    assert res.returncode == 0, f"sphinx-build failed or warned:\n{res.stderr[-4000:]}"
    return out / "html"


@pytest.mark.slow
def test_built_site_has_no_broken_internal_links(site):
    bad = broken_links(site)
    assert not bad, "\n".join(bad[:50])


@pytest.mark.slow
def test_built_site_works_offline(site):
    assert (site / "_static" / "mathjax" / "tex-chtml.js").exists()
    assert not external_assets(site), external_assets(site)[:20]


@pytest.mark.slow
def test_built_site_documents_every_public_function_and_case(site):
    import inspect

    api = {p.name: _parse(p).ids for p in (site / "api" / "generated").glob("*.html")}
    import pkgutil

    modules = [f"{pkg}.{m.name}" for pkg in ("ballrace.analytic", "ballrace.commands",
                                             "ballrace.casefiles", "ballrace.teach")
               for m in pkgutil.iter_modules(importlib.import_module(pkg).__path__)
               if not m.name.startswith("_")]
    assert {"ballrace.analytic.hertz", "ballrace.analytic.loaddist",
            "ballrace.commands.bearing", "ballrace.casefiles.bearing",
            "ballrace.teach.compute"} <= set(modules)
    for name in modules:
        mod = importlib.import_module(name)
        if mod.__name__ != name:       # an old path of a moved module: one page, the new path
            assert f"{name}.html" not in api, name
            continue
        public = getattr(mod, "__all__", None) or [
            n for n, o in vars(mod).items() if not n.startswith("_")
            and inspect.isfunction(o) and o.__module__ == name]
        ids = api[f"{name}.html"]
        # names defined here (a re-export such as highspeed.ConvergenceError is documented
        # in the module that defines it)
        missing = [n for n in public if callable(getattr(mod, n))
                   and getattr(getattr(mod, n), "__module__", name) == name
                   and f"{name}.{n}" not in ids]
        assert not missing, (name, missing)
    for old in ("ballrace.validation.explorer", "ballrace.validation.teach"):
        assert f"{old}.html" not in api, old     # teaching's old paths: no duplicate page
    for path, case in _all_cases():
        page = site / "cases" / f"{path.stem}.html"
        assert f"case-{case['id']}" in _parse(page).ids
