"""The HTML report: parses, embeds its images, omits (with a note) plots whose module is missing."""
from __future__ import annotations

import json
import sys
from html.parser import HTMLParser

import pytest

from ballrace.validation.runner import run_cases
from ballrace.validation.schema import load_cases, parse_cases


class _Collect(HTMLParser):
    def __init__(self):
        super().__init__()
        self.stack, self.imgs, self.tables, self.text = [], [], 0, []

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            self.imgs.append(dict(attrs))
            return
        if tag in ("meta", "br"):
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


@pytest.fixture(scope="module")
def run():
    cases = (load_cases("hertz_approximations.toml")[-2:] + load_cases("subsurface.toml")[:2]
             + load_cases("bearing.toml")[:2])
    wrong = parse_cases("""
[[case]]
id = "wrong-<b>"
title = "a failing case with markup <script>alert(1)</script>"
kind = "published"
calculation = "hertz.point_contact"
source = { author = "X & Y", year = 2000, reference = "eq. <1>" }
inputs = { load = "1000 N", rx1 = "5 mm", ry1 = "5 mm", E1 = "200 GPa", nu1 = 0.3 }
expected.a = { value = "0.5 mm", rtol = 1e-3, reason = "wrong on purpose" }
""".replace('"wrong-<b>"', '"wrong-b"'))
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
                  "git commit", "numpy", "wrong-b", "wrong on purpose", "Ricci (2009)"):
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
