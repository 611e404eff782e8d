"""The HTML report: parses, embeds its images, omits (with a note) plots whose module is missing."""
from __future__ import annotations

import json
import math
import sys
from pathlib import Path
from html.parser import HTMLParser

import pytest

from ballrace.validation.runner import run_cases
from ballrace.validation.schema import load_cases, parse_cases
from caseref import case_header


class _Collect(HTMLParser):
    def __init__(self):
        super().__init__()
        self.stack, self.imgs, self.tables, self.text = [], [], 0, []

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            self.imgs.append(dict(attrs))
            return
        if tag in ("meta", "br", "col", "wbr"):   # void elements
            return
        self.tables += tag == "table"
        self.stack.append(tag)

    def handle_endtag(self, tag):
        assert self.stack and self.stack[-1] == tag, f"</{tag}> closes <{self.stack[-1:]}>"
        self.stack.pop()

    def handle_data(self, data):
        self.text.append(data)


def _parse(html: str) -> _Collect:
    p = _Collect()
    p.feed(html)
    p.close()
    assert p.stack == [], f"unclosed tags {p.stack}"
    return p


_BEARING = ("bearing-tata-8-balls-570lb", "bearing-ricci-218-eccentric",
            "bearing-209-radial-jones", "bearing-harris-218-thrust")


@pytest.fixture(scope="module")
def run():
    cases = (load_cases("hertz_approximations.toml")[-2:] + load_cases("subsurface.toml")[:2]
             + [c for c in load_cases("bearing.toml") if c.id in _BEARING]
             + [c for c in load_cases("hertz*.toml") if c.id == "hertz-nafems-d3613"])
    wrong = parse_cases(case_header(
        "wrong-b", "a failing case with markup <script>alert(1)</script>",
        "hertz.point_contact", kind="published", author="X & Y", year=2000,
        reference="eq. <1>") + """\
inputs = { load = "1000 N", rx1 = "5 mm", ry1 = "5 mm", E1 = "200 GPa", nu1 = 0.3 }
expected.a = { value = "0.5 mm", rtol = 1e-3, reason = "wrong on purpose" }
""")
    return run_cases(cases + wrong, serial=True)


def test_report_html_parses_and_embeds_images(run, tmp_path):
    from ballrace.reports.html import write_report

    path = write_report(run, tmp_path)
    html = path.read_text()
    p = _parse(html)
    assert p.tables >= 4
    srcs = [i["src"] for i in p.imgs]
    assert len(srcs) >= 4 and all(s.startswith("data:image/png;base64,") for s in srcs)
    assert "src=\"http" not in html and "<link" not in html      # self-contained
    text = " ".join(p.text)
    for token in ("Hertz contact", "Subsurface stresses", "Bearing geometry", "Environment",
                  "numpy", "wrong-b", "wrong on purpose", "Ricci (2009)"):
        assert token in text, token
    assert "<script>alert" not in html and "&lt;script&gt;" in html   # autoescaped
    data = json.loads((tmp_path / "results.json").read_text())
    assert data["summary"]["fail"] == 1 and data["summary"]["total"] == len(run.results)
    assert data["baseline"]["values"]            # results.json doubles as a baseline


def test_bearing_plot_uses_the_load_distribution(run):
    from ballrace.validation.figures import bearing_figures

    figs = bearing_figures(run)
    assert any(f.id == "bearing-bearing-ricci-218-eccentric" and f.panels for f in figs)


def test_missing_module_plots_are_omitted_with_a_note(run, tmp_path, monkeypatch):
    from ballrace.reports.html import render_html

    monkeypatch.setitem(sys.modules, "ballrace.analytic.subsurface", None)   # import fails
    html = render_html(run)
    _parse(html)
    assert "omitted" in html and "subsurface" in html.lower()


def test_report_without_plots(run):
    from ballrace.reports.html import render_html

    html = render_html(run, plots=False)
    assert "<img" not in html and "Plots were turned off" in html


# --------------------------------------------------------------------------- report as read
class _Tables(HTMLParser):
    """Rows of every table as lists of cell texts, with the table's class and header."""

    def __init__(self):
        super().__init__()
        self.tables, self.cell, self.styles, self._in_style = [], None, [], False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "table":
            self.tables.append({"class": a.get("class", ""), "rows": [], "cols": []})
        elif tag == "col" and self.tables:
            self.tables[-1]["cols"].append(a.get("style", ""))
        elif tag == "tr" and self.tables:
            self.tables[-1]["rows"].append([])
        elif tag in ("td", "th") and self.tables:
            self.cell = {"tag": tag, "class": a.get("class", ""), "text": ""}
        elif tag == "style":
            self._in_style = True

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self.cell is not None:
            self.tables[-1]["rows"][-1].append(self.cell)
            self.cell = None
        elif tag == "style":
            self._in_style = False

    def handle_data(self, data):
        if self.cell is not None:
            self.cell["text"] += data
        if self._in_style:
            self.styles.append(data)


def _tables(html):
    t = _Tables()
    t.feed(html)
    return t


@pytest.fixture(scope="module")
def html(run):
    from ballrace.reports.html import render_html

    return render_html(run)


def test_case_tables_fit_the_page_and_print(html):
    t = _tables(html)
    cases = [x for x in t.tables if "cases" in x["class"]]
    assert len(cases) >= 3
    for tab in cases:
        head = [c["text"] for c in tab["rows"][0]]
        assert head == ["case", "status", "quantity", "expected", "got", "error", "tolerance",
                        "why this tolerance"]        # source and time live in the case cell
        widths = [float(c.split("width:")[1].rstrip("%;")) for c in tab["cols"]]
        assert len(widths) == len(head) and sum(widths) == pytest.approx(100.0)
        assert all(len(r) <= len(head) for r in tab["rows"])
    css = "".join(t.styles)
    assert "table-layout: fixed" in css and "max-width: 1240px" in css
    assert "@media print" in css and "@page" in css and "table-header-group" in css


def _row(html, case_id, quantity):
    for tab in _tables(html).tables:
        case = None
        for r in tab["rows"]:
            texts = [c["text"].strip() for c in r]
            if texts and texts[0].startswith(case_id):
                case, texts = case_id, texts[2:]
            if case == case_id and texts and texts[0] == quantity:
                return texts
    raise AssertionError(f"no row {case_id}/{quantity}")


def test_values_are_in_engineering_units(html, run, tmp_path):
    # NAFEMS D3613: p0 = 3585 MPa, b = 6.21 mm, shown as such (results.json stays SI)
    q, expected, got, err, *_ = _row(html, "hertz-nafems-d3613", "p_max")
    assert expected == "3585 MPa" and got.endswith(" MPa") and float(got.split()[0]) == \
        pytest.approx(3585.0, rel=2e-4)
    q, expected, got, *_ = _row(html, "hertz-nafems-d3613", "b")
    assert expected == "6.21 mm" and got.endswith(" mm")
    # Tata: 310 lbf published, shown in newtons
    q, expected, got, *_ = _row(html, "bearing-tata-8-balls-570lb", "Q_1")
    assert expected == f"{310 * 4.4482216152605:.6g} N"
    from ballrace.reports.html import write_results

    data = json.loads(write_results(run, tmp_path).read_text())
    c = next(c for c in data["cases"] if c["id"] == "hertz-nafems-d3613")
    assert next(x for x in c["comparisons"] if x["name"] == "p_max")["expected"] == 3585e6


def test_engineering_units_choose_one_unit_per_check():
    from ballrace.reports.html import engineering_unit, format_eng

    assert engineering_unit("[length]", 12.7e-3) == ("mm", 1e3)
    assert engineering_unit("[length]", 0.2e-6) == ("µm", 1e6)
    assert engineering_unit("[pressure]", 200e9) == ("GPa", 1e-9)
    assert engineering_unit("1 / [time]", 1047.2)[0] == "rpm"
    assert format_eng(1047.1975511965977, "1 / [time]") == "10000 rpm"
    assert format_eng(math.radians(40.0), "[angle]") == "40 deg"
    # the reference picks the unit: a small got beside a large expected keeps the unit
    assert format_eng(1e-7, "[length]", reference=1e-3) == "1×10⁻⁴ mm"


def test_overview_is_readable_at_one_screen(run):
    from ballrace.validation.figures import overview_figure

    f = overview_figure(run)
    strip, bars = f.panels
    assert strip["kind"] == "strip" and bars["kind"] == "bars"
    n = sum(len(r.comparisons) for r in run.results
            if any(c.allowed and c.error is not None for c in r.comparisons))
    assert len(strip["rows"]) == len({r.area for r in run.results if r.comparisons})
    assert sum(len(v) for v in strip["values"]) <= sum(len(r.comparisons) for r in run.results)
    assert n > 0 and len(bars["labels"]) <= 20
    assert list(bars["values"]) == sorted(bars["values"], reverse=True)      # worst first
    assert bars["labels"][0] == "wrong-b: a" and not bars["ok"][0]           # the failing one
    assert f.size[0] <= 14 and f.size[1] <= 6                     # one screen at 90 dpi


def test_header_names_no_dask_address_and_labels_time(run):
    import dataclasses

    from ballrace.reports.html import render_html

    r2 = dataclasses.replace(run, scheduler="dask tcp://127.0.0.1:40123 (1 worker(s), 2 "
                                            "thread(s))")
    html = render_html(r2, plots=False)
    assert "127.0.0.1" not in html and "dask, local (1 worker(s)" in html
    text = " ".join(_parse(html).text)
    assert "wall time" in text and "case time" in text and "summed" in text
    summary = next(t for t in _tables(html).tables if t["class"] == "summary")
    total = summary["rows"][-1]
    assert total[0]["text"] == "all areas"
    assert float(total[-1]["text"]) == pytest.approx(sum(r.duration for r in run.results),
                                                     abs=0.01)


def test_environment_gives_the_version_without_git(run, monkeypatch):
    from ballrace.reports.html import render_html
    from ballrace.validation import environment as envmod

    monkeypatch.setattr(envmod, "_in_checkout", lambda: False)
    env = envmod.environment()
    assert env["git_commit"] is None and env["packages"]["ballrace"]
    html = render_html(run, plots=False)
    row = next(r for t in _tables(html).tables for r in t["rows"]
               if r and r[0]["text"] == "ballrace")
    assert env["packages"]["ballrace"] in row[1]["text"] and "installed package" in row[1]["text"]
    assert "unknown" not in row[1]["text"]


def _by_id(figs, fid):
    return next(f for f in figs if f.id == fid)


def test_bearing_figures_plot_the_published_values(run):
    from ballrace.validation.figures import bearing_figures

    figs = bearing_figures(run)
    tata = _by_id(figs, "bearing-bearing-tata-8-balls-570lb")
    assert len(tata.panels) == 1                       # radial: no flat 0 deg angle panel
    assert "Contact angle 0 deg at every ball" in tata.caption
    pub = next(s for s in tata.panels[0]["series"] if s["style"] == "published")
    lbf = 4.4482216152605
    pts = sorted(zip(pub["x"], pub["y"]))
    assert pts == [(pytest.approx(-45.0), pytest.approx(184 * lbf)),
                   (pytest.approx(0.0), pytest.approx(310 * lbf)),
                   (pytest.approx(45.0), pytest.approx(184 * lbf))]
    ricci = _by_id(figs, "bearing-bearing-ricci-218-eccentric")
    beta = next(p for p in ricci.panels if p["title"] == "contact angles")
    bpub = next(s for s in beta["series"] if s["style"] == "published")
    assert pytest.approx(44.317) in list(bpub["y"]) and 0.0 in list(bpub["x"])
    balls = next(s for s in beta["series"] if s["style"] == "markers")
    assert balls["x"][0] == -180.0 and balls["x"][-1] == 180.0      # psi = 180 at both ends
    assert balls["y"][0] == balls["y"][-1]
    harris = _by_id(figs, "bearing-bearing-harris-218-thrust")      # 41.6 deg at every ball
    level = next(s for p in harris.panels for s in p["series"] if s["style"] == "published-level")
    assert list(level["y"]) == [pytest.approx(41.6), pytest.approx(41.6)]
    jones = _by_id(figs, "bearing-bearing-209-radial-jones")
    curve = next(s for s in jones.panels[0]["series"] if s["style"] == "dashed")
    balls = next(s for s in jones.panels[0]["series"] if s["style"] == "markers")
    r = next(r for r in run.results if r.id == "bearing-209-radial-jones")
    # Jones's Q_max = Z_w F_r / Z at psi = 0, within his +-2 % of the exact maximum
    assert max(curve["y"]) == pytest.approx(r.outputs["jones_zw"] * 8900.0 / 9, rel=1e-9)
    assert max(curve["y"]) == pytest.approx(max(balls["y"]), rel=0.02)


def test_a_figure_module_plugs_in_with_one_line(run, monkeypatch):
    import types

    from ballrace.reports.html import render_html
    from ballrace.validation import figures

    mod = types.ModuleType("fake_figures_life")
    mod.life_figures = lambda run: [figures.Figure(
        "life-aiso", "life", "a_ISO curves", caption="plugged in",
        panels=({"kind": "lines", "title": "t", "series": [{"x": [0, 1], "y": [1, 2],
                                                             "label": "a"}]},))]
    monkeypatch.setitem(sys.modules, "fake_figures_life", mod)
    # one line in FIGURE_SOURCES (the standard sources are left out to keep the test fast)
    monkeypatch.setattr(figures, "FIGURE_SOURCES",
                        ["ballrace.validation.figures:overview_figure",
                         "fake_figures_life:life_figures", "no_such_module_x:figs"])
    html = render_html(run)
    p = _parse(html)
    assert 'id="fig-life-aiso"' in html and "plugged in" in html
    assert 'id="life"' in html                      # a section of its own although no life case
    assert "No module named" in " ".join(p.text)    # the broken source is a note, not a crash


def test_fem_picture_compares_fe_and_analytic_on_one_section(tmp_path):
    """fem.render on a result whose 'FE' fields are the analytic ones: the mirrored section
    matches subsurface.stress everywhere (tau_xz odd in x), and the PNG is drawn without VTK."""
    import types

    import numpy as np

    from ballrace import Material
    from ballrace.analytic import hertz, subsurface
    from ballrace.fem.render import render, section_comparison

    steel = Material(E=200e9, nu=0.3)
    c = hertz.point_contact(2000.0, 6.35e-3, 6.35e-3, 26.15e-3, -6.604e-3, steel)
    bx = float(c.semi_axis_x)
    xs, zs = np.linspace(0.0, 1.6 * bx, 33), np.linspace(0.04, 1.6, 31) * bx
    X, Z = np.meshgrid(xs, zs, indexing="ij")
    s = subsurface.stress(c, X, 0 * X, Z, nu=0.3)
    za = np.linspace(0.02, 2.5, 40) * bx
    ax_ = subsurface.axis_stress(c, za, nu=0.3)
    fields = {"section_x": xs, "section_z": zs, "tau_xz": s.sxz, "von_mises": s.von_mises,
              "max_shear": s.tresca, "axis_z": za, "axis_tresca": ax_.tresca,
              "axis_von_mises": ax_.von_mises,
              "analytic": {"tau_xz": s.sxz, "von_mises": s.von_mises, "max_shear": s.tresca}}
    case = types.SimpleNamespace(name="synthetic", load=2000.0, analytic=c, material2=steel)
    r = types.SimpleNamespace(fields=fields, case=case, analytic=c, mode="half-space",
                              gap="hertz", level="quick",
                              z0=float(subsurface.orthogonal_shear(c).z0),
                              max_shear_depth=float(subsurface.max_shear(c).depth),
                              von_mises_depth=float(subsurface.von_mises(c).depth))
    for field in ("tau_xz", "von_mises", "max_shear"):
        x, z, fe, an = section_comparison(r, field)
        assert x[0] == pytest.approx(-x[-1]) and fe.shape == (2 * xs.size - 1, zs.size)
        # the mirrored quarter section equals the analytic field evaluated on the whole one
        Xm, Zm = np.meshgrid(x, z, indexing="ij")
        sm = subsurface.stress(c, Xm, 0 * Xm, Zm, nu=0.3)
        ref = {"tau_xz": sm.sxz, "von_mises": sm.von_mises, "max_shear": sm.tresca}[field]
        for got in (fe, an):
            assert np.max(np.abs(got - ref)) <= 1e-9 * np.max(np.abs(ref)), field
    # contact pressure: tents carrying Hertz's pressure at their nodes
    from ballrace.fem.model import PressureGrid

    g = PressureGrid(1.5 * bx, 1.5 * float(c.semi_axis_y), 12, 12)
    nx_, ny_ = g.nodes()
    fields.update(grid=g, lam=np.asarray(c.pressure(nx_, ny_)))
    had_vtk = "vtkmodules" in sys.modules
    for field in ("tau_xz", "von_mises", "max_shear", "pressure"):
        out = render(r, field, str(tmp_path / f"{field}.png"))
        png = (tmp_path / f"{field}.png").read_bytes()
        assert out.endswith(f"{field}.png") and png[:8] == b"\x89PNG\r\n\x1a\n"
        assert len(png) > 20_000, field                   # a picture, not an empty canvas
    assert had_vtk or "vtkmodules" not in sys.modules


def test_report_folder_has_no_separate_renders(tmp_path):
    from typer.testing import CliRunner

    from ballrace.cli import app

    res = CliRunner().invoke(app, ["validate", "--cases", "subsurface*", "--fem", "none",
                                   "--serial", "--report", str(tmp_path / "rep")])
    assert res.exit_code == 0, res.output
    assert sorted(p.name for p in (tmp_path / "rep").iterdir()) == ["index.html",
                                                                     "results.json"]


def test_numbers_never_wrap_and_names_wrap_at_underscores():
    """Print/PDF: a number and its unit are one unbreakable piece; quantity names break
    only after an underscore; a count of hours says "h"."""
    from types import SimpleNamespace as NS

    from ballrace.reports import html

    c = NS(name="L10h_hours", dimension="", expected=246674.0, maximum=None, minimum=None,
           got=246670.0, error=-4.0, rel_error=-4.0 / 246674.0, tolerance="±1e-3 rel")
    assert str(html._cfmt(c, "got")) == '<span class="n">246670 h</span>'
    assert str(html._wbr("max_shear_depth")) == "max_<wbr>shear_<wbr>depth"
    b = NS(name="angle_error", dimension="[angle]", expected=None, maximum=1e-9, minimum=None,
           got=2e-10, error=-8e-10, rel_error=None)
    cell = str(html._err(b))
    assert cell.startswith('margin <span class="n">') and "×10⁻" in cell
    tol = str(html._tol("±5.72958e-08 deg + ±1e-06 rel"))
    assert tol == ('<span class="n">±5.72958e-08 deg</span> + '
                   '<span class="n">±1e-06 rel</span>')
    prose = str(html._prose("half a unit = 1.4e-5); <b>ok</b>"))
    assert prose == 'half a unit = <span class="n">1.4e-5);</span> &lt;b&gt;ok&lt;/b&gt;'
    css = (Path(html.__file__).parent / "templates" / "report.html.j2").read_text()
    assert ".n { white-space: nowrap; }" in css and "overflow-wrap: anywhere" not in css
