"""The explorer's server against requests a page of another site could make, and the
page's drawing details, on the real server (an ephemeral port, in a thread).

* Host and Origin: a page whose name was made to point at 127.0.0.1 (DNS rebinding) sends
  its own name as Host; the server answers only 127.0.0.1, localhost and [::1] with its
  port, and a POST whose Origin is another site, with a bare 403.
* ``/api/case`` reads the ``--case`` file and ``.toml`` files under the start folder only;
  a path elsewhere gets one refusal, the same whether the file exists or not, with none of
  its keys.
* Each request is bounded: body, query, input length, exponents pint would evaluate to
  huge integers, |traction| <= 1 (the library's maxima searches beyond 1 take a minute).
* ``teach export`` reports its progress on stderr.
* In a browser (skipped without Playwright and Chromium; ``.ci/browser``): a zero field in
  the neutral colour, the maximum's label inside the plot when the maximum is at the
  surface, the field list not cut off, the views not squeezed in a narrow window.
"""
from __future__ import annotations

import http.client
import json
import logging
import threading
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from ballrace.teach import commands as tcmd
from ballrace.teach import compute as tc
from ballrace.teach import server as tsrv
from teachweb import chromium as _chromium   # the browser the explorer tests drive

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
REFUSED = "reads only the case file it was started with"


@pytest.fixture(scope="module")
def folders(tmp_path_factory):
    """A start folder with case files (one in a subfolder, a symbolic link leading out, a
    non-TOML file) and, beside it, an outside folder with a case file of distinctive keys."""
    base = tmp_path_factory.mktemp("explorer")
    root, outside = base / "start", base / "outside"
    (root / "sub").mkdir(parents=True)
    outside.mkdir()
    case = (EXAMPLES / "bearing_209.toml").read_text()
    (root / "inside.toml").write_text(case)
    (root / "sub" / "deep.toml").write_text(case)
    (root / "notes.txt").write_text(case)
    (outside / "secret.toml").write_text('[zzsecretsection]\nzzsecretkey = "zzsecretvalue"\n')
    (outside / "cli.toml").write_text(case)
    (root / "link.toml").symlink_to(outside / "secret.toml")
    return root, outside


@pytest.fixture(scope="module")
def server(folders):
    root, outside = folders
    srv = tsrv.make_server(0, root=root, cases=(outside / "cli.toml",))
    th = threading.Thread(target=srv.serve_forever, kwargs={"poll_interval": 0.05}, daemon=True)
    th.start()
    yield srv.server_address[1]
    srv.shutdown()
    srv.server_close()


def _request(port, method, path, body=None, host="default", headers=()):
    """(status, body text) of one request; ``host`` None sends no Host header."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    try:
        conn.putrequest(method, path, skip_host=True, skip_accept_encoding=True)
        if host == "default":
            host = f"127.0.0.1:{port}"
        if host is not None:
            conn.putheader("Host", host)
        for k, v in headers:
            conn.putheader(k, v)
        data = b"" if body is None else body
        if method == "POST" and not any(k.lower() == "content-length" for k, _ in headers):
            conn.putheader("Content-Length", str(len(data)))
        conn.endheaders(data or None)
        r = conn.getresponse()
        return r.status, r.read().decode("utf-8", "replace")
    finally:
        conn.close()


def _post(port, obj, **kw):
    status, text = _request(port, "POST", "/api/compute", json.dumps(obj).encode(), **kw)
    return status, json.loads(text) if text.startswith("{") else text


def _case(port, path, race="inner"):
    from urllib.parse import urlencode

    status, text = _request(port, "GET", "/api/case?" + urlencode({"path": path, "race": race}))
    assert status == 200, text
    return json.loads(text)


# ------------------------------------------------------------------ Host and Origin
@pytest.mark.parametrize("host", ["evil.example", "evil.example:{port}", "127.0.0.1:1",
                                  "127.0.0.1", "localhost.evil.example:{port}",
                                  "127.0.0.2:{port}", None])
def test_foreign_host_is_refused_without_detail(server, host):
    host = None if host is None else host.format(port=server)
    for method, path, body in (("GET", "/", None), ("GET", "/api/case?path=inside.toml", None),
                               ("POST", "/api/compute", b"{}")):
        status, text = _request(server, method, path, body, host=host)
        assert (status, text) == (403, "forbidden\n"), (host, path)


@pytest.mark.parametrize("host", ["127.0.0.1:{port}", "localhost:{port}", "LOCALHOST:{port}",
                                  "[::1]:{port}"])
def test_own_host_is_served(server, host):
    status, text = _request(server, "GET", "/", host=host.format(port=server))
    assert status == 200 and "<canvas" in text


def test_two_host_headers_are_refused(server):
    status, _ = _request(server, "GET", "/", headers=[("Host", "evil.example")])
    assert status == 403


def test_post_from_another_origin_is_refused(server):
    status, text = _post(server, {}, headers=[("Origin", "http://evil.example")])
    assert (status, text) == (403, "forbidden\n")
    status, text = _post(server, {}, headers=[("Origin", "null")])
    assert status == 403
    status, r = _post(server, {"load": "1 kN"}, headers=[("Origin", f"http://127.0.0.1:{server}")])
    assert status == 200 and r["ok"] and r["table"]["load"] == pytest.approx(1000.0)


def test_security_headers_on_the_page(server):
    conn = http.client.HTTPConnection("127.0.0.1", server, timeout=60)
    try:
        conn.request("GET", "/")
        r = conn.getresponse()
        r.read()
        assert "frame-ancestors 'none'" in r.getheader("Content-Security-Policy")
        assert "connect-src 'self'" in r.getheader("Content-Security-Policy")
        assert r.getheader("X-Content-Type-Options") == "nosniff"
    finally:
        conn.close()


def test_allowed_hosts():
    assert tsrv._hosts("127.0.0.1", 8765) == {"127.0.0.1:8765", "localhost:8765", "[::1]:8765"}
    assert "localhost" in tsrv._hosts("127.0.0.1", 80)        # port 80 is left out by browsers
    assert "[::1]:9" in tsrv._hosts("::1", 9)


# ------------------------------------------------------------------ /api/case
def test_case_under_the_start_folder_is_read(server):
    for path in ("inside.toml", "sub/deep.toml", "sub/../inside.toml", "./inside.toml"):
        r = _case(server, path, "outer")
        assert r["ok"], (path, r)
        # the 209 bearing (Hamrock & Dowson 1981 Table 3.2): D = 12.7 mm, d_m = 65 mm
        assert r["inputs"]["D"] == "12.7 mm" and r["inputs"]["dm"] == "65 mm"
        assert r["inputs"]["race"] == "outer"


def test_case_given_on_the_command_line_is_read_wherever_it_is(server, folders):
    r = _case(server, str(folders[1] / "cli.toml"))
    assert r["ok"] and r["inputs"]["f"] == "0.52"


def test_case_elsewhere_is_one_refusal_that_tells_nothing(server, folders):
    root, outside = folders
    answers = set()
    for path in ("../outside/secret.toml", "../outside/none.toml", str(outside / "secret.toml"),
                 str(outside / "none.toml"), "/etc/passwd", "/etc/hostname", "/nonexistent.toml",
                 "link.toml", "notes.txt", "..", "/", "sub", "../../../../../../etc/passwd",
                 "inside.toml\x00.txt", str(root.parent)):
        r = _case(server, path)
        assert r["ok"] is False and r["field"] == "case", path
        answers.add(r["error"])
    # one message for all: it does not tell whether the file exists, nor what it holds
    assert len(answers) == 1, answers
    msg = answers.pop()
    assert REFUSED in msg
    assert "zzsecret" not in msg and str(root) not in msg and "no such" not in msg


def test_case_missing_under_the_start_folder_names_the_typed_path(server, folders):
    r = _case(server, "sub/missing.toml")
    assert r["ok"] is False and "no case file 'sub/missing.toml'" in r["error"]
    assert str(folders[0]) not in r["error"]


def test_case_request_bounds(server):
    from urllib.parse import urlencode

    status, text = _request(server, "GET", "/api/case?" + urlencode(
        {"path": "a" * (tsrv.MAX_QUERY + 10) + ".toml"}))
    assert status == 400 and f"longer than {tsrv.MAX_QUERY}" in json.loads(text)["error"]
    status, text = _request(server, "GET", "/api/case?path=inside.toml&race=middle")
    assert status == 400 and json.loads(text)["field"] == "race"


def test_resolve_case_large_file_refused(tmp_path):
    big = tmp_path / "big.toml"
    big.write_bytes(b"#" * (tsrv.MAX_CASE_BYTES + 1))
    with pytest.raises(tc.InputError, match="larger than"):
        tsrv.resolve_case("big.toml", tmp_path)
    (tmp_path / "small.toml").write_text("[case]\n")
    assert tsrv.resolve_case("small.toml", tmp_path) == (tmp_path / "small.toml").resolve()


# ------------------------------------------------------------------ bounded requests
def test_body_larger_than_the_bound_is_refused_unread(server):
    t0 = time.perf_counter()
    status, r = _post(server, {}, headers=[("Content-Length", str(10**9))])
    assert status == 400 and r["field"] == "general" and str(tsrv.MAX_BODY) in r["error"]
    status, r = _post(server, {}, headers=[("Content-Length", "-1")])
    assert status == 400
    status, r = _post(server, {}, headers=[("Content-Length", "many")])
    assert status == 400
    assert time.perf_counter() - t0 < 10


@pytest.mark.parametrize("body,field,text", [
    ({"load": "1" * 200 + " N"}, "load", f"at most {tsrv.MAX_TEXT} characters"),
    ({"load": "9^9^9 N"}, "load", "exponent"),
    ({"load": "9**9**9 N"}, "load", "exponent"),
    ({"load": "9^(9^9) N"}, "load", "exponent"),
    ({"load": "9**-(9**9) N"}, "load", "exponent"),
    ({"load": "2 N^999"}, "load", "exponent"),
    ({"E": "200 N/mm^2^9"}, "E", "exponent"),
    ({"grid": "1000"}, "general", "unknown input 'grid'"),
    ({"load": ["1 kN"]}, "load", "give a text or a number"),
])
def test_request_bounds(server, body, field, text):
    t0 = time.perf_counter()
    status, r = _post(server, {**tc.DEFAULTS, **body})
    assert status == 400 and r["ok"] is False, r
    assert r["field"] == field and text in r["error"] and "\n" not in r["error"]
    assert time.perf_counter() - t0 < 10          # refused before any computation


def test_bounded_inputs_still_accept_what_people_type(server):
    status, r = _post(server, {**tc.DEFAULTS, "E": "200000 N/mm^2", "load": "0.5 kN",
                               "rx1": "0.25 in", "ry1": "0.25 in", "nu": 0.3})
    assert status == 200 and r["ok"], r
    # 200000 N/mm^2 = 200 GPa; 0.25 in = 6.35 mm: the same contact as the defaults at 500 N
    ref = tc.compute({**tc.DEFAULTS, "load": "500 N"})["table"]
    assert r["table"]["a"] == pytest.approx(ref["a"], rel=1e-12)


def test_check_text():
    assert tsrv.check_text("E", "210 kN/mm**2") == "210 kN/mm**2"
    assert tsrv.check_text("E", "3e7 lbf/in^2") == "3e7 lbf/in^2"
    with pytest.raises(tsrv.RequestError, match="exponent"):
        tsrv.check_text("E", "2^2^2^2^2 Pa")


@pytest.mark.parametrize("mu", ["1.5", "-10", "10"])
def test_traction_beyond_one_is_an_input_error_at_once(server, mu):
    t0 = time.perf_counter()
    status, r = _post(server, {**tc.DEFAULTS, "ry1": "100 mm", "traction": mu})
    assert status == 200 and r["ok"] is False and r["field"] == "traction"
    assert "traction must be in [-1, 1]" in r["error"]
    assert time.perf_counter() - t0 < 10


def test_server_alive_after_all_that(server):
    status, r = _post(server, {**tc.DEFAULTS, "traction": "1"})
    assert status == 200 and r["ok"] is True


# ------------------------------------------------------------------ export progress
def test_export_grid_reports_each_shape(caplog):
    grid = {"ratio": (1.0, 2.0), "load": (500.0, 1000.0, 2000.0), "nu": (0.3,), "mu": (0.0,)}
    calls = []
    with caplog.at_level(logging.INFO, logger="ballrace.teach.compute"):
        tc.export_grid(grid, lambda done, n, text: calls.append((done, n, text)))
    assert [(d, n) for d, n, _ in calls] == [(0, 6), (3, 6), (6, 6)]
    assert calls[0][2] == "shape 1/2: Ry/Rx = 1, nu = 0.3, traction = 0"
    assert calls[1][2] == "shape 2/2: Ry/Rx = 2, nu = 0.3, traction = 0"
    logged = caplog.text
    assert "export: 6 grid points, 2 shapes" in logged
    assert "export: shape 2/2: Ry/Rx = 2, nu = 0.3, traction = 0 in" in logged


def test_export_command_prints_progress_on_stderr(tmp_path, monkeypatch):
    from ballrace.cli import app

    monkeypatch.setattr(tcmd, "SMALL_GRID", {"ratio": (1.0, 2.0), "load": (1000.0,),
                                             "nu": (0.3,), "mu": (0.0,)})
    out = tmp_path / "h.html"
    res = CliRunner().invoke(app, ["teach", "export", str(out), "--small"])
    assert res.exit_code == 0, res.output
    err = res.stderr.splitlines()
    assert err[0].startswith("ballrace explorer: computing 2 grid points (2 shapes)")
    assert err[1].startswith("  0/2 grid points, shape 1/2: Ry/Rx = 1")
    assert err[2].startswith("  1/2 grid points, shape 2/2: Ry/Rx = 2")
    assert err[-1].startswith("  2/2 grid points, compressing and writing the page")
    assert res.stdout.startswith("wrote ") and out.exists()


def test_progress_lines_one_per_tenth(capsys):
    p = tcmd._ProgressLines(90)
    for done in range(0, 91, 3):
        p(done, 90, "x")
    p(90, 90, "compressing")
    lines = capsys.readouterr().err.splitlines()
    # 0, then the first call of each new tenth of 90 (9, 18, ..., 81), then 90 twice (the
    # end of the last shape and the writing)
    assert [int(s.split("/")[0]) for s in lines] == [0, 9, 18, 27, 36, 45, 54, 63, 72, 81,
                                                     90, 90]


# ------------------------------------------------------------------ in a real browser
@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    sync_api = pytest.importorskip("playwright.sync_api", reason="pip install playwright")
    exe = _chromium()
    if exe is None:
        pytest.skip("no chromium (apt-get install chromium; see .ci/browser)")
    srv = tsrv.make_server(0)
    th = threading.Thread(target=srv.serve_forever, kwargs={"poll_interval": 0.05}, daemon=True)
    th.start()
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=exe, args=["--no-sandbox"])
        yield b, f"http://127.0.0.1:{srv.server_address[1]}/"
        b.close()
    srv.shutdown()
    srv.server_close()


def _open(browser, query, width=1280):
    b, url = browser
    page = b.new_page(viewport={"width": width, "height": 900})
    page.goto(url + query)
    page.wait_for_selector("body[data-ready]", timeout=120_000)
    return page


_PIXEL = """([id, x, y]) => Array.from(document.querySelector(id).getContext('2d')
    .getImageData(x, y, 1, 1).data.slice(0, 3))"""


def test_browser_zero_field_is_neutral(browser):
    """tau_xz in the plane x = 0 without traction is zero by symmetry: the section is the
    diverging map's centre (247, 247, 247), not its dark-blue end (33, 102, 172)."""
    page = _open(browser, "?field=tau_xz")
    try:
        # the plot box is [50, 10, w - 110, h - 50]: a point inside it, clear of the text
        for xy in ([60, 300], [200, 40], [330, 250]):
            assert page.evaluate(_PIXEL, ["#c-secx", *xy]) == [247, 247, 247], xy
        # the other section is drawn in colour: a pixel at the LP depth is not neutral
        assert page.evaluate(_PIXEL, ["#c-secy", 120, 70]) != [247, 247, 247]
        assert page.get_attribute("#c-secx", "data-zero") == "1"
        assert page.get_attribute("#c-secy", "data-zero") == "0"
    finally:
        page.close()


def test_browser_surface_maximum_label_inside_the_plot(browser):
    """Traction 0.4 on the circle (above the critical 0.288 for Tresca,
    subsurface.critical_traction): the Tresca maximum is at the surface.  Its label is
    drawn below the top of the plot: the canvas rows above the plot box stay white."""
    page = _open(browser, "?traction=0.4&field=tresca")
    try:
        page.wait_for_function("!document.querySelector('td.pending')", timeout=120_000)
        page.select_option("#field", "tresca")
        for cv in ("#c-secy", "#c-secx"):
            rows = page.evaluate("""(id) => { const c = document.querySelector(id);
                const d = c.getContext('2d').getImageData(0, 0, c.width, 4).data;
                let n = 0; for (let i = 0; i < d.length; i += 4) if (d[i] + d[i+1] + d[i+2] < 600) n++;
                return n; }""", cv)
            assert rows == 0, cv
            assert int(page.get_attribute(cv, "data-label-top")) >= 10, cv
    finally:
        page.close()


@pytest.mark.parametrize("width", [1280, 700])
def test_browser_field_list_not_cut_and_views_not_squeezed(browser, width):
    page = _open(browser, "", width)
    try:
        for sel in ("#field", "#mode"):
            room, need = page.evaluate("""(sel) => { const s = document.querySelector(sel);
                const ctx = document.createElement('canvas').getContext('2d');
                ctx.font = getComputedStyle(s).font;
                const w = Math.max(...Array.from(s.options).map((o) => ctx.measureText(o.text).width));
                return [s.clientWidth, w]; }""", sel)
            assert room >= need + 24, (sel, room, need)      # 24 px: padding and the arrow
        w = page.evaluate("document.querySelector('#c-secy').getBoundingClientRect().width")
        assert w >= 280
    finally:
        page.close()
