"""The explorer's roller mode: a profiled roller on a raceway (``ballrace.teach``).

* :func:`ballrace.teach.compute.compute_roller` returns the numbers of
  :func:`ballrace.analytic.roller.line_contact` and
  :func:`ballrace.analytic.roller.subsurface_stress` for the same inputs;
* the server refuses out-of-range inputs (tilt, load, the profile's sizes) with one line
  naming the input, and a load too light for a fast stress computation with the load that
  would do;
* ``ballrace teach roller`` prints the centre and end pressures and stress maxima, within
  80 columns and without ANSI codes when piped; its errors are one line, exit code 2;
* in a browser (skipped without Playwright and Chromium) the page switches to roller mode
  and draws its plots with no console error.
"""
from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
import urllib.request

import numpy as np
import pytest
from typer.testing import CliRunner

from ballrace import Material
from ballrace.analytic import roller
from ballrace.teach import compute as tc
from ballrace.teach import page as tpage
from teachweb import chromium, live_server, post

STEEL = Material(E=200e9, nu=0.3)
ROLLER = {**tc.DEFAULTS, "mode": "roller"}


def _library(profile="iso", Q=2000.0, tilt=0.0, R1=6e-3, R2=30e-3, L=12e-3):
    c = roller.line_contact(Q, R1, R2, L, STEEL, STEEL, profile=profile, tilt=tilt,
                            n_slices=tc.ROLLER_SLICES)
    return c, roller.subsurface_stress(c, 0.3, n_depth=tc.ROLLER_DEPTHS)


CASES = [
    ({"profile": "straight"}, dict(profile="straight")),
    ({"profile": "iso"}, dict(profile="iso")),
    ({"profile": "lundberg", "tilt": "1 mrad", "load": "5 kN"},
     dict(profile="lundberg", tilt=1e-3, Q=5000.0)),
    ({"profile": "johns-gohar", "r_race": "-40 mm"}, dict(profile="johns-gohar", R2=-40e-3)),
    ({"profile": "crowned", "flat": "8 mm", "crown": "0.5 m", "tilt": "-0.5 mrad"},
     dict(profile=roller.Crowned(8e-3, 0.5), tilt=-0.5e-3)),
    ({"profile": "straight", "r_race": "inf", "length": "20 mm", "load": "10 kN"},
     dict(profile="straight", R2=math.inf, L=20e-3, Q=1e4)),
]


@pytest.mark.parametrize("change, lib", CASES, ids=[c[0]["profile"] for c in CASES])
def test_compute_equals_library(change, lib):
    r = tc.compute({**ROLLER, **change})
    assert r["ok"] and r["kind"] == "roller"
    c, s = _library(**lib)
    t = r["table"]
    n = c.n_slices
    # the same calls: equal to the last bit (JSON keeps a float's repr)
    assert r["line"]["x"] == c.x.tolist()
    assert r["line"]["pressure"] == c.pressure.tolist()
    assert r["line"]["slice_loads"] == c.slice_loads.tolist()
    assert t["p_centre"] == c.pressure[n // 2] and t["p_max"] == c.max_pressure
    assert t["p_hertz"] == c.hertz_pressure and t["approach"] == c.approach
    assert t["edge_load"] == c.edge_load and t["tilt"] == c.tilt
    on = np.flatnonzero(c.in_contact)
    assert t["p_edge"] == max(c.pressure[on[0]], c.pressure[on[-1]])
    for key, crit in (("vm", "von_mises"), ("tr", "tresca")):
        for where in ("centre", "edge", "maximum"):
            v, x, z = getattr(s, where)(crit)
            assert r["marks"][f"{key}_{where}"] == [v, x, z]
            assert (t[f"{key}_{where}"], t[f"{key}_{where}_x"],
                    t[f"{key}_{where}_depth"]) == (v, x, z)
    # the map: the library's von Mises stress at every slice centre and depth, to the
    # 16-bit packing (rows: depth)
    vm = tc.unpack(r["map"]["vm"])
    assert vm.shape == (s.depth.size, s.x.size)
    span = float(s.von_mises.max() - s.von_mises.min())
    assert np.max(np.abs(vm - s.von_mises.T)) <= span / 65535 * 0.51
    assert r["map"]["z"] == s.depth.tolist() and r["map"]["vm_depth"] == \
        s.von_mises_depth.tolist()


def test_hertz_reference_by_hand():
    """The plot's reference line: 2-D Hertz p0 = sqrt(q E' / (2 pi R)), q = Q/L,
    E' = E/(1 - nu^2) for two equal bodies, 1/R = 1/R1 + 1/R2 (Johnson, Contact
    Mechanics, 1985, eq. 4.45).  6 mm roller on a 30 mm raceway, 2000 N over 12 mm:
    R = 5 mm, p0 = 1079.80 MPa."""
    r = tc.compute(ROLLER)
    Ep = 200e9 / (1 - 0.3 ** 2)
    R = 1 / (1 / 6e-3 + 1 / 30e-3)
    p0 = math.sqrt(2000.0 / 12e-3 * Ep / (2 * math.pi * R))
    assert r["table"]["R"] == pytest.approx(R, rel=1e-12)
    assert r["table"]["p_hertz"] == pytest.approx(p0, rel=1e-12)
    assert p0 == pytest.approx(1079.80e6, rel=1e-5)
    # Lundberg's profile, designed for this load: the pressure at the centre is the 2-D
    # Hertz p0 (ROLLER notes: uniform p0 along the roller on a half-space); 2 % for the
    # slice discretisation
    lb = tc.compute({**ROLLER, "profile": "lundberg"})["table"]
    assert lb["p_centre"] == pytest.approx(p0, rel=0.02)


def test_straight_roller_peaks_at_its_ends():
    """A straight roller: the pressure and the von Mises maximum are larger at the ends
    than at the centre (the edge peaks the lamina model cannot show)."""
    t = tc.compute({**ROLLER, "profile": "straight"})["table"]
    assert t["p_edge"] > 1.2 * t["p_centre"]
    assert t["vm_edge"] > 1.2 * t["vm_centre"]
    assert abs(t["vm_edge_x"]) == pytest.approx(6e-3 - 6e-3 / 41, rel=1e-9)   # end slice


def test_cached_and_dispatched_by_mode():
    a = tc.compute(ROLLER)
    b = tc.compute_safe(dict(ROLLER))           # compute() dispatches on mode "roller"
    assert a == b
    key = [k for k in tc._CACHE if k[0] == "roller"]
    assert key, "the roller state is cached"


# ------------------------------------------------------------------ bad input
BAD = [
    ({"tilt": "20 mrad"}, "tilt", "within ±10 mrad"),
    ({"tilt": "-1 deg"}, "tilt", "within ±10 mrad"),
    ({"tilt": "1"}, "tilt", "unit"),
    ({"load": "2 MN"}, "load", "(0, 1e+06]"),
    ({"load": "0 N"}, "load", "(0, 1e+06]"),
    ({"profile": "barrel"}, "profile", "straight, iso, lundberg, johns-gohar, crowned"),
    ({"profile": "crowned", "flat": "12 mm"}, "flat", "[0, L)"),
    ({"profile": "crowned", "crown": "1 mm"}, "crown", "crown radius must exceed"),
    ({"r_race": "-5 mm"}, "r_race", "|R2| > R1"),
    ({"r_race": "0 mm"}, "r_race", "nonzero"),
    ({"r_roller": "-6 mm"}, "r_roller", "roller radius"),
    ({"length": "0 mm"}, "length", "roller length"),
    ({"nu": "0.6"}, "nu", "nu"),
    ({"E": "-1 GPa"}, "E", "E"),
]


@pytest.mark.parametrize("change, field, text", BAD, ids=[b[1] + ":" + str(list(b[0].values())[-1])
                                                         for b in BAD])
def test_bad_input_one_line(change, field, text):
    r = tc.compute_safe({**ROLLER, **change})
    assert r["ok"] is False and r["field"] == field, r
    assert text in r["error"] and "\n" not in r["error"] and "Traceback" not in r["error"]


def test_light_load_refused_with_the_load_that_would_do():
    """A light load on a long roller would take seconds to minutes (the stress
    integration's nodes scale with the half-width): refused at once, with a load that
    passes."""
    import time

    t0 = time.perf_counter()
    r = tc.compute_safe({**ROLLER, "load": "10 N"})
    assert time.perf_counter() - t0 < 5.0
    assert r["ok"] is False and r["field"] == "load"
    assert "too light" in r["error"] and "more than 4 times" in r["error"]
    need = float(re.search(r"raise the load to about (\S+) N", r["error"]).group(1))
    assert 100.0 < need < 2000.0
    ok = tc.compute({**ROLLER, "load": f"{need:g} N"})
    c, _ = _library(Q=need)
    assert c.slice_width <= tc.SLICE_OVER_WIDTH_MAX * c.half_width.max()
    assert ok["table"]["load"] == need


@pytest.fixture(scope="module")
def server():
    with live_server() as url:
        yield url


def test_server_refuses_out_of_range_inputs(server):
    for change, field, text in BAD + [({"load": "10 N"}, "load", "too light")]:
        status, r = post(server, {**ROLLER, **change})
        assert status == 200 and r["ok"] is False and r["field"] == field, (change, r)
        assert text in r["error"] and "\n" not in r["error"]
    # an input the page does not have, a long one: 400 before any work
    for body, field in (({**ROLLER, "n_slices": "4001"}, "general"),
                        ({**ROLLER, "tilt": "1" * 200 + " mrad"}, "tilt")):
        with pytest.raises(urllib.error.HTTPError) as e:
            post(server, body)
        assert e.value.code == 400
        assert json.loads(e.value.read())["field"] == field
    status, r = post(server, {**ROLLER, "profile": "straight", "tilt": "2 mrad"})
    assert status == 200 and r["ok"] and r["kind"] == "roller"


def test_export_says_roller_mode_needs_the_server():
    html = tpage.page({"grid": {}, "geometry": {}, "tables": {}, "dimless": {}})
    assert "roller mode needs the live server" in " ".join(html.split())


# ------------------------------------------------------------------ the command
def _cli(*args, columns="80"):
    env = {**os.environ, "COLUMNS": columns, "NO_COLOR": ""}
    env.pop("NO_COLOR")
    exe = os.path.join(os.path.dirname(sys.executable), "ballrace")
    return subprocess.run([exe, "teach", "roller", *args],
                          capture_output=True, text=True, env=env, timeout=120)


def test_cli_roller_numbers_80_columns_no_ansi():
    for columns in ("80", "200"):
        res = _cli("--profile", "straight", "--tilt", "0.5 mrad", columns=columns)
        assert res.returncode == 0, res.stderr
        assert "\x1b" not in res.stdout
        assert max(len(line) for line in res.stdout.splitlines()) <= 80
    t = tc.compute({**ROLLER, "profile": "straight", "tilt": "0.5 mrad"})["table"]
    rows = {m.group(1).strip(): float(m.group(2)) for m in
            re.finditer(r"^ (\S.*?)\s{2,}(-?[\d.]+(?:e[+-]\d+)?)\s+\S+\s*$", res.stdout, re.M)}
    for label, key, scale in (("pressure at the centre", "p_centre", 1e-6),
                              ("pressure at the contact's end", "p_edge", 1e-6),
                              ("2-D Hertz p0 at Q/L", "p_hertz", 1e-6),
                              ("von Mises, centre", "vm_centre", 1e-6),
                              ("von Mises, end", "vm_edge", 1e-6),
                              ("von Mises, end: depth", "vm_edge_depth", 1e3),
                              ("Tresca, overall", "tr_maximum", 1e-6)):
        assert rows[label] == pytest.approx(t[key] * scale, rel=1e-5), label


def test_cli_roller_json_is_si():
    from ballrace.cli import app

    res = CliRunner().invoke(app, ["teach", "roller", "--json", "--load", "5 kN",
                                   "--profile", "crowned", "--flat", "6 mm", "--crown", "1 m"])
    assert res.exit_code == 0, res.output
    out = json.loads(res.stdout)
    c, s = _library(profile=roller.Crowned(6e-3, 1.0), Q=5000.0)
    assert out["result"]["p_max"] == c.max_pressure
    assert out["result"]["vm_centre"] == s.centre()[0]


@pytest.mark.parametrize("args, text", [
    (["--tilt", "1 deg"], "error: --tilt: tilt must be within ±10 mrad"),
    (["--roller-radius", "6"], "error: --roller-radius: "),
    (["--profile", "barrel"], "error: --profile: profile must be one of"),
    (["--profile", "crowned", "--crown", "1 mm"], "error: --crown: crown radius"),
    (["--load", "10 N"], "error: --load: load: 10 N is too light"),
    (["--raceway-radius", "-5 mm"], "error: --raceway-radius: "),
    (["--units", "cgs"], "error: --units must be one of eng, si, us"),
])
def test_cli_roller_errors(args, text):
    from ballrace.cli import app

    res = CliRunner().invoke(app, ["teach", "roller", *args])
    assert res.exit_code == 2
    assert res.stderr.startswith(text), res.stderr
    assert res.stderr.count("\n") == 1 and "Traceback" not in res.stderr


# ------------------------------------------------------------------ in a real browser
def test_in_browser_roller_mode(server):
    """Switch the live page to roller mode: both plots drawn (non-white pixels), the table's
    numbers those of the library to the printed digits, the crown inputs shown for the
    circular crown only, a bad tilt shown in place, and no console error."""
    sync_api = pytest.importorskip("playwright.sync_api", reason="pip install playwright")
    exe = chromium()
    if exe is None:
        pytest.skip("no chromium (apt-get install chromium; see .ci/browser)")
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=exe, args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": 1280, "height": 1000})
        errors = []
        page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(server + "/?profile=straight&tilt=0.5%20mrad")
        page.wait_for_selector("body[data-ready]")
        assert page.is_hidden("#c-rpress")

        def settle(action):
            before = page.get_attribute("body", "data-ready")
            action()
            page.wait_for_function("document.body.dataset.ready && "
                                   f'document.body.dataset.ready !== "{before}"')

        settle(lambda: page.select_option("#mode", "roller"))
        assert page.is_visible("#c-rpress") and page.is_visible("#c-rmap")
        assert page.is_hidden("#c-3d") and page.is_hidden("#traction-slider")
        assert page.is_hidden("#crown-inputs")
        assert page.get_attribute("#c-rpress", "data-points") == "41"
        assert page.get_attribute("#c-rmap", "data-cells") == str(41 * tc.ROLLER_DEPTHS)
        for cid in ("#c-rpress", "#c-rmap"):
            dark = page.evaluate(f"""() => {{ const c = document.querySelector('{cid}');
                const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
                let n = 0; for (let i = 0; i < d.length; i += 4) if (d[i] < 200) n++;
                return n; }}""")
            assert dark > 2000, cid
        c, s = _library(profile="straight", tilt=0.5e-3)
        shown = {k: float(page.inner_text(f'td[data-rkey="{k}"]'))
                 for k in ("p_hertz", "p_edge", "vm_centre", "vm_edge")}
        assert shown == {"p_hertz": float(f"{c.hertz_pressure / 1e9:.4g}"),
                         "p_edge": float(f"{c.max_pressure / 1e9:.4g}"),
                         "vm_centre": float(f"{s.centre()[0] / 1e6:.4g}"),
                         "vm_edge": float(f"{s.edge()[0] / 1e6:.4g}")}
        # the circular crown shows its two inputs
        page.select_option('[data-param="profile"]', "crowned")
        page.wait_for_function("!document.querySelector('#crown-inputs').hidden")
        # a bad tilt: the message in place, the state kept
        page.fill('[data-param="tilt"]', "30 mrad")
        page.locator('[data-param="tilt"]').dispatch_event("change")
        page.wait_for_function(
            "document.querySelector('.err[data-for=\"tilt\"]').textContent.length > 0")
        assert "within ±10 mrad" in page.inner_text('.err[data-for="tilt"]')
        assert page.get_attribute("#c-rmap", "data-cells") == str(41 * tc.ROLLER_DEPTHS)
        # and back to the ball: its views again
        settle(lambda: page.select_option("#mode", "bodies"))
        assert page.is_visible("#c-3d") and page.is_hidden("#c-rpress")
        assert errors == []
        browser.close()
