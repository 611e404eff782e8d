"""The subsurface-stress explorer (ballrace.teach): its computation against the library,
its bad-input handling, the server, the export, and (when playwright and a Chromium are
installed: ``.ci/browser``) the page in a real browser.

The expected values are the library's own functions called directly
(:func:`hertz.point_contact`, :func:`subsurface.stress`, ``max_shear``, ``orthogonal_shear``)
— the explorer only samples and scales them — plus published anchors: the circle's
tau_max = 0.31 p0 at 0.48 a (Johnson 1985 §3.4, nu = 0.3) and tau0 = 0.2139 p0 at
z0 = 0.3509 b (Lundberg & Palmgren 1947, t = 1.2808), and the Hertz scaling
a ∝ Q^(1/3), p0 ∝ Q^(1/3), delta ∝ Q^(2/3) (Johnson 1985 eq. 4.22–4.23).
"""
from __future__ import annotations

import gzip
import json
import math
import os
import re
import signal
import subprocess
import sys
import threading
import urllib.error
import urllib.request
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from ballrace import Material
from ballrace.analytic import hertz, subsurface
from ballrace.teach import commands as tcmd
from ballrace.teach import compute as tc
from ballrace.teach import page as tpage
from ballrace.teach import server as tsrv
from teachweb import chromium, live_server, post

STEEL = Material(E=200e9, nu=0.3)   # E' = 2/[2(1 - nu^2)/E] = E/(1 - nu^2) for two steel bodies


def _contact(load=2000.0, rx1=6.35e-3, ry1=6.35e-3, rx2=math.inf, ry2=math.inf, nu=0.3):
    return hertz.point_contact(load, rx1, ry1, rx2, ry2, Material(E=200e9, nu=nu))


# ------------------------------------------------------------------ the computation
def test_table_equals_library_circle():
    r = tc.compute(tc.DEFAULTS)
    t = r["table"]
    c = _contact()
    o = subsurface.orthogonal_shear(c)
    m = subsurface.max_shear(c, nu=0.3)
    v = subsurface.von_mises(c, nu=0.3)
    for key, want in (("a", c.a), ("b", c.b), ("p0", c.p_max), ("delta", c.approach),
                      ("tau0", o.tau0), ("z0", o.z0), ("tau_max", m.tau_max),
                      ("tau_max_depth", m.depth), ("vm_max", v.sigma_vm), ("vm_depth", v.depth)):
        assert t[key] == pytest.approx(float(want), rel=1e-12), key
    # published anchors (Johnson 1985 §3.4; Lundberg & Palmgren 1947)
    assert t["tau_max"] / t["p0"] == pytest.approx(0.31, abs=0.005)
    assert t["tau_max_depth"] / t["a"] == pytest.approx(0.48, abs=0.005)
    assert t["tau0"] / t["p0"] == pytest.approx(0.2139, abs=1e-4)
    assert t["z0"] / t["b"] == pytest.approx(0.3509, abs=1e-4)
    assert r["pending"] is False


def test_load_scaling_reuses_the_shape():
    """a, p0 ∝ Q^(1/3), delta ∝ Q^(2/3); the sampled fields in units of p0 and b are the
    same object for two loads (the cache), and the scaled maxima follow."""
    r1 = tc.compute({**tc.DEFAULTS, "load": "1000 N"})
    r8 = tc.compute({**tc.DEFAULTS, "load": "8000 N"})
    t1, t8 = r1["table"], r8["table"]
    assert t8["a"] / t1["a"] == pytest.approx(2.0, rel=1e-12)
    assert t8["p0"] / t1["p0"] == pytest.approx(2.0, rel=1e-12)
    assert t8["delta"] / t1["delta"] == pytest.approx(4.0, rel=1e-12)
    assert t8["z0"] / t1["z0"] == pytest.approx(2.0, rel=1e-12)
    assert r1["dimless"] == r8["dimless"]
    c8 = _contact(8000.0)
    assert t8["tau_max"] == pytest.approx(float(subsurface.max_shear(c8).tau_max), rel=1e-12)


@settings(max_examples=25, deadline=None)
@given(Q=st.floats(10.0, 1e5), ratio=st.sampled_from(["6.35 mm", "25.4 mm", "100 mm"]))
def test_scaling_invariants(Q, ratio):
    """Hertz: a, b, z0 and tau_max's depth scale as Q^(1/3), p0 and the stresses as
    Q^(1/3), delta as Q^(2/3) (Johnson 1985 eqs. 4.22-4.23) against a 1000 N reference."""
    base = {**tc.DEFAULTS, "ry1": ratio, "load": "1000 N"}
    t0 = tc.compute(base)["table"]
    t = tc.compute({**base, "load": f"{Q!r} N"})["table"]
    s = (Q / 1000.0) ** (1 / 3)
    for k, e in (("a", 1), ("b", 1), ("z0", 1), ("tau_max_depth", 1), ("p0", 1), ("tau0", 1),
                 ("tau_max", 1), ("vm_max", 1), ("delta", 2)):
        assert t[k] == pytest.approx(t0[k] * s**e, rel=1e-9), k


@pytest.mark.parametrize("mu", [0.0, 0.25])
def test_sections_equal_stress(mu):
    """The packed sections are subsurface.stress at the grid points, to the 16-bit
    quantisation (1/65535 of each field's range), mirrored halves included."""
    params = {**tc.DEFAULTS, "mode": "bearing", "traction": str(mu)}
    r = tc.compute(params)
    c = hertz.elliptical_contact(2000.0, *_bearing_radii(), STEEL.reduced_modulus)
    assert r["table"]["a"] == pytest.approx(float(c.a), rel=1e-12)
    b, p0 = float(c.b), float(c.p_max)
    for which, coords in (("sec_y0", lambda u, z: (u * b, 0.0, z * b)),
                          ("sec_x0", lambda u, z: (0.0, u * b, z * b))):
        sec = r["dimless"][which]
        u = np.linspace(*sec["u"][:2], sec["u"][2])
        z = np.linspace(*sec["z"][:2], sec["z"][2])
        U, Z = np.meshgrid(u, z)
        s = subsurface.stress(c, *coords(U, Z), nu=0.3, traction=mu)
        want = {"tau_xz": s.sxz, "tresca": s.tresca, "von_mises": s.von_mises,
                "sigma_x": s.sxx, "sigma_z": s.szz}
        for name, arr in want.items():
            got = tc.unpack(sec["fields"][name])
            span = sec["fields"][name]["hi"] - sec["fields"][name]["lo"]
            np.testing.assert_allclose(got, arr / p0, rtol=0, atol=0.6 * span / 65535 + 1e-12,
                                       err_msg=f"{which} {name}")


def _bearing_radii():
    """Rx, Ry of the default bearing: 12.7 mm ball, d_m 65 mm, f 0.52, inner race, 0 deg
    (Hamrock & Dowson 1981 eqs. 2.18–2.25: Rx = D/2 (1 - D/d_m), Ry = f D/(2f - 1))."""
    D, dm, f = 12.7e-3, 65e-3, 0.52
    return 0.5 * D * (1 - D / dm), f * D / (2 * f - 1)


def test_axis_profile_and_volume_equal_stress():
    r = tc.compute({**tc.DEFAULTS, "rx1": "5 mm", "ry1": "20 mm"})
    c = _contact(rx1=5e-3, ry1=20e-3)
    b, p0 = float(c.b), float(c.p_max)
    ax = r["dimless"]["axis"]
    z = np.linspace(*ax["z"][:2], ax["z"][2])
    s = subsurface.stress(c, 0.0, 0.0, z * b, nu=0.3)
    np.testing.assert_allclose(ax["curves"]["von_mises"], s.von_mises / p0, rtol=1e-5, atol=1e-6)
    np.testing.assert_allclose(ax["curves"]["sigma_z"], s.szz / p0, rtol=1e-5, atol=1e-6)
    vol = r["dimless"]["vol"]
    vm = tc.unpack(vol["vm"])
    X, Y, Z = np.meshgrid(*(np.linspace(*vol[k][:2], vol[k][2]) for k in "xyz"), indexing="ij")
    want = subsurface.stress(c, X * b, Y * b, Z * b, nu=0.3).von_mises / p0
    np.testing.assert_allclose(vm, want, atol=0.6 * (vol["vm"]["hi"] - vol["vm"]["lo"]) / 65535)


def test_traction_maxima_pending_then_equal_library():
    params = {**tc.DEFAULTS, "rx1": "7 mm", "ry1": "7 mm", "traction": "0.3"}
    tc._CACHE.clear()
    fast = tc.compute(params, maxima=False)
    assert fast["pending"] is True and fast["table"]["tau_max"] is None
    full = tc.compute(params)
    c = _contact(rx1=7e-3, ry1=7e-3)
    m = subsurface.max_shear(c, nu=0.3, traction=0.3)
    assert full["table"]["tau_max"] == pytest.approx(float(m.tau_max), rel=1e-12)
    assert full["table"]["tau_max_x"] == pytest.approx(float(m.x), rel=1e-12, abs=1e-15)
    assert tc.compute(params, maxima=False)["pending"] is False      # now cached


def test_bearing_outer_race_and_ratio_slider():
    r = tc.compute({**tc.DEFAULTS, "mode": "bearing", "race": "outer", "angle": "40 deg"})
    D, dm, f, beta = 12.7e-3, 65e-3, 0.52, math.radians(40)
    g = D * math.cos(beta) / dm
    c = hertz.elliptical_contact(2000.0, 0.5 * D * (1 + g), f * D / (2 * f - 1),
                                 STEEL.reduced_modulus)
    assert r["table"]["a"] == pytest.approx(float(c.a), rel=1e-12)
    # the ellipticity slider sets body 1's ry so that Ry/Rx = 8 (body 2 flat)
    r = tc.compute({**tc.DEFAULTS, "set_ratio": "8"})
    assert r["inputs"]["ry1"] == "50.8 mm"
    assert r["table"]["Ry"] / r["table"]["Rx"] == pytest.approx(8.0, rel=1e-12)


# ------------------------------------------------------------------ bad input
BAD = [
    ({"rx1": "0 mm"}, "rx1", "non-zero"),
    ({"ry1": "-2 mm"}, "ry2", "curvature sum in the y plane"),
    ({"ry2": "-5 mm"}, "ry2", "concave body is more curved"),
    ({"ry1": "inf"}, "ry2", "line"),
    ({"load": "0 N"}, "load", "load must be > 0"),
    ({"load": "-3 N"}, "load", "load must be > 0"),
    ({"nu": "0.7"}, "nu", "nu must be in (-1, 0.5)"),
    ({"nu": "-1"}, "nu", "nu must be in (-1, 0.5)"),
    ({"load": "3 kgg"}, "load", "cannot parse"),
    ({"load": "3 kg"}, "load", "dimension [force]"),
    ({"rx1": "6,35 mm"}, "rx1", "comma"),
    ({"E": "-200 GPa"}, "E", "E must be > 0"),
    ({"traction": "12"}, "traction", "traction must be in [-1, 1]"),
    ({"traction": "-1.01"}, "traction", "traction must be in [-1, 1]"),
    ({"mode": "bearing", "f": "0.45"}, "f", "f_inner"),
    ({"mode": "bearing", "D": "80 mm"}, "D", "ball_diameter"),
    ({"mode": "bearing", "angle": "12 mm"}, "angle", "angle"),
    ({"set_ratio": "-2"}, "ratio", "ratio"),
]


@pytest.mark.parametrize("change,field,text", BAD)
def test_bad_input_one_line(change, field, text):
    r = tc.compute_safe({**tc.DEFAULTS, **change})
    assert r["ok"] is False
    assert r["field"] == field
    assert text in r["error"]
    assert "\n" not in r["error"] and "Traceback" not in r["error"]


# ------------------------------------------------------------------ the server
@pytest.fixture(scope="module")
def server():
    with live_server() as url:
        yield url


def test_server_page_is_self_contained(server):
    with urllib.request.urlopen(server + "/", timeout=30) as f:
        html = f.read().decode()
    assert "<canvas" in html and "DecompressionStream" in html
    # no asset from elsewhere: no src/href to any URL, no fetch of another host
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//""", html)
    assert "http://" not in html and "https://" not in html


def test_server_survives_bad_input(server):
    for change, field, _ in BAD:
        _, r = post(server, {**tc.DEFAULTS, **change})
        assert r["ok"] is False and r["field"] == field
    for body in (b"not json", b"[1, 2]"):          # a malformed request: 400, one line
        req = urllib.request.Request(server + "/api/compute", data=body, method="POST")
        with pytest.raises(urllib.error.HTTPError) as err:
            urllib.request.urlopen(req, timeout=30)
        r = json.loads(err.value.read())
        assert err.value.code == 400
        assert r["ok"] is False and "\n" not in r["error"]
    _, r = post(server, {**tc.DEFAULTS, "load": "1 kN"})
    assert r["ok"] is True and r["table"]["load"] == pytest.approx(1000.0)


def test_case_file_endpoint(server):
    path = Path(__file__).resolve().parents[1] / "examples" / "bearing_209.toml"
    with urllib.request.urlopen(server + f"/api/case?path={path}&race=outer", timeout=30) as f:
        r = json.loads(f.read())
    assert r["ok"] and r["inputs"]["D"] == "12.7 mm" and r["inputs"]["dm"] == "65 mm"
    assert r["inputs"]["f"] == "0.52" and r["inputs"]["mode"] == "bearing"
    with urllib.request.urlopen(server + "/api/case?path=nonexistent.toml", timeout=30) as f:
        r = json.loads(f.read())
    assert r["ok"] is False and "no case file 'nonexistent.toml'" in r["error"]
    # outside the start folder: refused, whether the file exists or not
    for outside in ("/nonexistent.toml", "/etc/hostname"):
        with urllib.request.urlopen(server + f"/api/case?path={outside}", timeout=30) as f:
            r = json.loads(f.read())
        assert r["ok"] is False and "reads only" in r["error"]


def test_serve_with_a_case_file():
    from ballrace.cli import app

    res = CliRunner().invoke(app, ["teach", "serve", "--case", "/nonexistent.toml"])
    assert res.exit_code == 2 and "no such file" in res.output and "Traceback" not in res.output
    path = Path(__file__).resolve().parents[1] / "examples" / "bearing_218.toml"
    initial = tc.case_inputs(str(path), "outer")
    srv = tsrv.make_server(0, initial=initial)
    try:
        th = threading.Thread(target=srv.serve_forever, kwargs={"poll_interval": 0.05},
                              daemon=True)
        th.start()
        with urllib.request.urlopen(f"http://127.0.0.1:{srv.server_address[1]}/",
                                    timeout=30) as f:
            html = f.read().decode()
    finally:
        srv.shutdown()
        srv.server_close()
    init = json.loads(re.search(r"const DEFAULTS = (\{.*?\});", html).group(1))
    assert init["mode"] == "bearing" and init["race"] == "outer" and init["angle"] == "40 deg"
    r = tc.compute(init)
    # the 218 bearing of Ricci (2009): D = 22.225 mm, d_e = 125.26 mm, f = 0.5232, 40 deg
    D, dm, f, beta = 22.225e-3, 125.26e-3, 0.5232, math.radians(40)
    g = D * math.cos(beta) / dm
    c = hertz.elliptical_contact(2000.0, 0.5 * D * (1 + g), f * D / (2 * f - 1),
                                 STEEL.reduced_modulus)
    assert r["table"]["a"] == pytest.approx(float(c.a), rel=1e-9)


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_serve_command_prints_port_and_stops_on_ctrl_c(tmp_path, sig):
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in sys.path if p)}
    proc = subprocess.Popen([sys.executable, "-m", "ballrace.cli", "teach", "serve"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
                            cwd=tmp_path)
    try:
        line = proc.stdout.readline()
        m = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        assert m, line
        with urllib.request.urlopen(m.group(0), timeout=30) as f:
            assert f.status == 200
        proc.send_signal(sig)
        out, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 0
    assert "stopped" in out
    assert "Traceback" not in err and "Traceback" not in out


def test_serve_bad_port():
    import socket

    from ballrace.cli import app

    res = CliRunner().invoke(app, ["teach", "serve", "--port", "70000"])
    assert res.exit_code == 2 and "--port must be in [0, 65535]" in res.output
    with socket.socket() as busy:
        busy.bind(("127.0.0.1", 0))
        busy.listen(1)
        port = busy.getsockname()[1]
        res = CliRunner().invoke(app, ["teach", "serve", "--port", str(port)])
    assert res.exit_code == 2 and f"cannot listen on 127.0.0.1:{port}" in res.output
    assert "Traceback" not in res.output


# ------------------------------------------------------------------ the export
SMALL = {"ratio": (1.0, 4.0), "load": (500.0, 4000.0), "nu": (0.3,), "mu": (0.0, 0.2)}


@pytest.fixture(scope="module")
def export_data():
    return tc.export_grid(SMALL)


def test_export_tables_equal_live_compute(export_data):
    g = export_data["grid"]
    for i, alpha in enumerate(g["ratio"]):
        for j, Q in enumerate(g["load"]):
            for m, mu in enumerate(g["mu"]):
                t = export_data["tables"][f"{i},{j},0,{m}"]
                c = _contact(Q, 6.35e-3, alpha * 6.35e-3)
                assert t["a"] == pytest.approx(float(c.a), rel=1e-12)
                assert t["p0"] == pytest.approx(float(c.p_max), rel=1e-12)
                assert t["z0"] == pytest.approx(float(subsurface.orthogonal_shear(c).z0),
                                                rel=1e-12)
                ms = subsurface.max_shear(c, nu=0.3, traction=mu)
                assert t["tau_max"] == pytest.approx(float(ms.tau_max), rel=1e-9)
                live = tc.compute(tc.export_params(alpha, Q, 0.3, mu))["table"]
                assert live == t


def test_export_page_size_and_no_network(tmp_path, export_data):
    html = tpage.page(export_data)
    assert "http://" not in html and "https://" not in html
    # the full grid: the gzipped size of one shape's fields times the number of shapes,
    # plus the tables, in base64, stays below 10 MB (the full export: docs/explorer.md)
    shape = gzip.compress(json.dumps(max(export_data["dimless"].values(),
                                         key=lambda d: len(json.dumps(d)))).encode(), 9)
    table = gzip.compress(json.dumps(export_data["tables"]).encode(), 9)
    G = tc.EXPORT_GRID
    n_shape = len(G["ratio"]) * len(G["nu"]) * len(G["mu"])
    n_table = n_shape * len(G["load"])
    estimate = (n_shape * len(shape) + n_table / len(export_data["tables"]) * len(table)) * 4 / 3
    assert estimate < 10e6


def test_export_command_small(tmp_path, monkeypatch):
    from ballrace.cli import app

    monkeypatch.setattr(tcmd, "SMALL_GRID", {"ratio": (1.0,), "load": (1000.0,), "nu": (0.3,),
                                             "mu": (0.0,)})
    out = tmp_path / "h.html"
    res = CliRunner().invoke(app, ["teach", "export", str(out), "--small"])
    assert res.exit_code == 0, res.output
    assert out.stat().st_size > 10_000 and "wrote" in res.output
    # default: under the ignored output folder; a file in the way is a one-line error
    monkeypatch.chdir(tmp_path)
    res = CliRunner().invoke(app, ["teach", "export", "--small"])
    assert res.exit_code == 0 and (tmp_path / "ballrace-out" / "teach" / "explorer.html").exists()
    (tmp_path / "f").write_text("x")
    res = CliRunner().invoke(app, ["teach", "export", str(tmp_path / "f" / "x.html")])
    assert res.exit_code == 2 and "exists and is not a folder" in res.output


# ------------------------------------------------------------------ in a real browser
def _num(text: str) -> float:
    return float(text.strip())


def _digits(v: float) -> float:
    """The value as the page prints it: 4 significant digits (toPrecision(4))."""
    return float(f"{v:.4g}")


@pytest.fixture(scope="module")
def browser_exe():
    """Playwright's sync API and a Chromium executable, or a skip (before any other work)."""
    sync_api = pytest.importorskip("playwright.sync_api", reason="pip install playwright")
    exe = chromium()
    if exe is None:
        pytest.skip("no chromium (apt-get install chromium; see .ci/browser)")
    return sync_api, exe


def test_in_browser(browser_exe, tmp_path, server, export_data):
    """Move the load and ellipticity controls of the live app, check a, b, p0, z0 against
    the library to the printed digits, a drawn 3-D view, bad input kept in place; open the
    export from file:// with no request and check its numbers.  (7–17 s on a 2-core
    machine: not marked slow.)"""
    sync_api, exe = browser_exe
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=exe, args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": 1280, "height": 900})
        live_requests = []
        page.on("request", lambda r: live_requests.append(r.url))
        page.goto(server + "/")
        page.wait_for_selector("body[data-ready]")

        def table():
            return {k: _num(page.inner_text(f'td[data-key="{k}"]'))
                    for k in ("a", "b", "p0", "z0")}

        def settle(action):
            before = page.get_attribute("body", "data-ready")
            action()
            page.wait_for_function("document.body.dataset.ready && "
                                   f'document.body.dataset.ready !== "{before}"')

        # load slider -> 10^3.9 N (the page writes 3 significant digits: 7940 N)
        settle(lambda: page.locator("#load-slider").fill("3.9"))
        assert page.input_value('[data-param="load"]') == "7940 N"
        # ellipticity slider -> Ry/Rx = 10^0.6 = 3.98
        settle(lambda: page.locator("#ratio").fill("0.6"))
        ry1 = page.input_value('[data-param="ry1"]')
        ry1 = float(ry1.split()[0]) * 1e-3
        c = _contact(7940.0, 6.35e-3, ry1)
        o = subsurface.orthogonal_shear(c)
        shown = table()
        assert shown == {"a": _digits(float(c.a) * 1e3), "b": _digits(float(c.b) * 1e3),
                         "p0": _digits(float(c.p_max) / 1e9), "z0": _digits(float(o.z0) * 1e3)}
        assert float(c.k) > 2.0
        # the 3-D view drew: triangles and non-white pixels
        assert int(page.get_attribute("#c-3d", "data-triangles")) > 100
        assert page.evaluate("""() => { const c = document.querySelector('#c-3d');
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0; for (let i = 0; i < d.length; i += 4) if (d[i] < 200) n++;
            return n; }""") > 2000
        # bad input: the error in place, the last valid state kept, the server alive
        page.fill('[data-param="ry2"]', "-3 mm")
        page.locator('[data-param="ry2"]').dispatch_event("change")
        page.wait_for_function(
            "document.querySelector('.err[data-for=\"ry2\"]').textContent.length > 0")
        err = page.inner_text('.err[data-for="ry2"]')
        assert "curvature sum" in err and "\n" not in err
        assert table() == shown
        settle(lambda: (page.fill('[data-param="ry2"]', "inf"),
                        page.locator('[data-param="ry2"]').dispatch_event("change")))
        assert page.inner_text('.err[data-for="ry2"]') == ""
        # compare: the pinned column shows the pinned state
        page.check("#compare")
        assert _num(page.inner_text('td[data-pin="a"]')) == shown["a"]

        assert live_requests and all(u.startswith(server) for u in live_requests), live_requests
        # the export from file://, no request to anything but the file itself
        out = tmp_path / "explorer.html"
        out.write_text(tpage.page(export_data), encoding="utf-8")
        requests = []
        page2 = browser.new_page()
        page2.on("request", lambda r: requests.append(r.url))
        page2.goto(out.as_uri())
        page2.wait_for_selector("body[data-ready]")
        page2.locator("#s-ratio").fill("1")
        page2.locator("#s-load").fill("1")
        page2.locator("#s-ratio").dispatch_event("input")
        t = export_data["tables"]["1,1,0,0"]
        for k, sc in (("a", 1e3), ("b", 1e3), ("p0", 1e-9), ("z0", 1e3), ("tau_max", 1e-6)):
            assert _num(page2.inner_text(f'td[data-key="{k}"]')) == _digits(t[k] * sc), k
        assert int(page2.get_attribute("#c-3d", "data-triangles")) > 100
        assert [u for u in requests if not u.startswith("file://")] == []
        browser.close()


def test_beyond_hertz_is_a_note_on_the_page_not_a_warning_on_the_console():
    """A load that makes a = 5.5 R (1e9 N on a 6.35 mm ball on a flat): the page says the
    numbers are extrapolations; nothing is printed by the server."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = tc.compute({**tc.DEFAULTS, "mode": "bodies", "load": "1e9 N", "rx1": "6.35 mm",
                        "ry1": "6.35 mm", "rx2": "inf", "ry2": "inf", "traction": "0"},
                       maxima=False)
        ok = tc.compute({**tc.DEFAULTS, "mode": "bodies", "load": "1000 N", "rx1": "6.35 mm",
                         "ry1": "6.35 mm", "rx2": "inf", "ry2": "inf", "traction": "0"},
                        maxima=False)
    assert "a / R = 5.5" in r["note"] and "extrapolations" in r["note"]
    assert ok["note"] == ""
