"""The explorer's local HTTP server (``ballrace teach serve``) and its request checks.

The standard library's :class:`http.server.ThreadingHTTPServer` bound to 127.0.0.1: ``GET
/`` is the page of :mod:`ballrace.teach.page`, ``POST /api/compute`` one state of
:func:`ballrace.teach.compute.compute`, ``GET /api/case`` the inputs of a bearing case
file.  Every request is checked before any work: its ``Host`` and ``Origin`` must name this
server (a page of another site gets a 403), its size and every input are bounded
(:func:`check_request`, :func:`check_text`: a 400 with one line), and a case file is read
only from the folder the server was started in (:func:`resolve_case`).
"""
from __future__ import annotations

import json
import logging
import re
import threading
from pathlib import Path

from .compute import DEFAULTS, InputError, case_inputs, compute_safe, one_line
from .page import page

__all__ = ["MAX_BODY", "MAX_QUERY", "MAX_TEXT", "MAX_CASE_BYTES", "RequestError",
           "check_text", "check_request", "resolve_case", "make_server"]

log = logging.getLogger(__name__)

# Bounds of the work one request may ask for (the server refuses more with a 400).  The
# grids are fixed (ballrace.teach.compute), so a request chooses only the inputs; these
# bound their size (and TRACTION_MAX there the slowest search; in roller mode TILT_MAX,
# ROLLER_LOAD_MAX and SLICE_OVER_WIDTH_MAX, checked by compute_roller before any work).
MAX_BODY = 16_384        # bytes of a POST /api/compute body
MAX_QUERY = 2_048        # characters of a GET query string
MAX_TEXT = 100           # characters of one input
MAX_CASE_BYTES = 1_000_000   # size of a case file /api/case reads
_PARAMS = frozenset(DEFAULTS) | {"set_ratio", "_maxima"}
_POW = re.compile(r"\^|\*\*")
_POW_ARG = re.compile(r"\s*\(?\s*[+-]?\d{1,2}(?:\.\d{1,3})?(?![\d.])\s*\)?")


class RequestError(ValueError):
    """A request the server refuses before any computation (HTTP 400): too large, an
    unknown input, an exponent that would make pint compute a huge integer."""

    def __init__(self, field: str, message: str):
        super().__init__(message)
        self.field = field


def check_text(field: str, text) -> str:
    """One input of a request, bounded: at most :data:`MAX_TEXT` characters, and every
    exponent (``^`` or ``**``) a plain number of at most two digits that is not raised
    again (pint evaluates ``9^9^9`` as an integer of 370 million digits).

    Raises :class:`RequestError`; returns the text.
    """
    s = str(text)
    if len(s) > MAX_TEXT:
        raise RequestError(field, f"{field}: at most {MAX_TEXT} characters; got {len(s)}")
    for m in _POW.finditer(s):
        rest = s[m.end():]
        arg = _POW_ARG.match(rest)
        if arg is None or _POW.match(rest[arg.end():].lstrip()):
            raise RequestError(field, f"{field}: {s!r}: an exponent must be a number of at "
                               "most two digits, not raised again (e.g. '200 N/mm^2')")
    return s


def check_request(body) -> tuple[dict, bool]:
    """The inputs of a POST /api/compute body, bounded (see :func:`check_text`): a JSON
    object of at most the page's inputs; returns ``(params, maxima)``.

    Raises :class:`RequestError` naming the input.
    """
    if not isinstance(body, dict):
        raise RequestError("general", "the request body must be a JSON object")
    unknown = sorted(str(k) for k in body if k not in _PARAMS)
    if unknown:
        name = check_text("general", unknown[0][:40])
        raise RequestError("general", f"unknown input {name!r}; the inputs are "
                           f"{', '.join(sorted(_PARAMS))}")
    maxima = bool(body.pop("_maxima", True))
    params = {}
    for k, v in body.items():
        if v is not None and not isinstance(v, (str, int, float)):
            raise RequestError(k, f"{k}: give a text or a number; got {type(v).__name__}")
        params[k] = None if v is None else check_text(k, v)
    return params, maxima


def resolve_case(text, root, allowed=()) -> Path:
    """The case file ``text`` names, if the explorer may read it: one of ``allowed`` (the
    ``--case`` file), or a ``.toml`` file in the folder ``root`` or below it (a relative
    path is taken from ``root``; symbolic links are followed before the check, so none
    leads out).  Anything else is one refusal that says nothing of the file.

    Raises :class:`~ballrace.teach.compute.InputError` for the field ``case``.
    """
    root = Path(root).resolve()
    refuse = InputError("case", "case: the explorer reads only the case file it was started "
                        "with (--case) and .toml case files in the folder it was started in "
                        "or below it")
    s = str(text).strip()
    if not s:
        raise InputError("case", "case: give the path of a bearing case file (.toml), "
                         "relative to the folder the explorer was started in")
    try:
        real = (root / s).resolve()          # an absolute s replaces root
    except (OSError, ValueError, RuntimeError):
        raise refuse from None
    if real not in {Path(a).resolve() for a in allowed} and (
            real.suffix.lower() != ".toml" or not real.is_relative_to(root)):
        raise refuse
    if not real.is_file():
        raise InputError("case", f"case: no case file {s!r} in the folder the explorer was "
                         "started in")
    if real.stat().st_size > MAX_CASE_BYTES:
        raise InputError("case", f"case: {s!r} is larger than {MAX_CASE_BYTES // 1000} kB; "
                         "a case file is a few kB")
    return real



def _hosts(host: str, port: int) -> frozenset:
    """The Host headers the server answers: its loopback names with its port (a page of
    another site whose name was made to point at 127.0.0.1 sends its own name)."""
    names = {"127.0.0.1", "localhost", "[::1]", f"[{host}]" if ":" in host else host}
    out = {f"{n}:{port}" for n in names}
    if port == 80:
        out |= names
    return frozenset(n.lower() for n in out)


def make_server(port: int = 0, host: str = "127.0.0.1", initial: dict | None = None,
                root=None, cases=()):
    """A ThreadingHTTPServer serving the explorer (not started); port 0 picks a free port;
    ``initial`` inputs (strings, as :data:`~ballrace.teach.compute.DEFAULTS`) are the page's
    first state.

    ``GET /api/case`` reads only the files of ``cases`` (the ``--case`` file) and ``.toml``
    files in the folder ``root`` (default: the current folder) or below it (see
    :func:`resolve_case`).  A request whose ``Host`` is not 127.0.0.1, localhost or [::1]
    with the server's port, or whose ``Origin`` is another site, is refused (403); a request
    larger than the bounds (:data:`MAX_BODY`, :data:`MAX_QUERY`, :func:`check_text`) gets a
    400 with a one-line message.
    """
    from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
    from urllib.parse import parse_qs, urlparse

    html = page(None, initial).encode("utf-8")
    root = Path(root if root is not None else Path.cwd()).resolve()
    cases = tuple(Path(c).resolve() for c in cases)
    # one view computation at a time, and one maxima search at a time: the slow searches
    # with traction (second request) never hold up the views of the next change
    locks = {False: threading.Lock(), True: threading.Lock()}
    # the page talks to this server only and is shown in no other site's frame
    csp = "connect-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'none'"

    class Handler(BaseHTTPRequestHandler):
        server_version = "ballrace-explorer"
        sys_version = ""
        timeout = 30                            # a client that stalls is dropped

        def log_message(self, fmt, *args):      # no request log on the terminal
            log.debug("explorer: " + fmt, *args)

        def _send(self, code: int, body: bytes, ctype: str) -> None:
            try:
                self.send_response(code)
                self.send_header("Content-Type", ctype)
                self.send_header("Content-Length", str(len(body)))
                self.send_header("Cache-Control", "no-store")
                self.send_header("X-Content-Type-Options", "nosniff")
                self.send_header("Referrer-Policy", "no-referrer")
                if ctype.startswith("text/html"):
                    self.send_header("Content-Security-Policy", csp)
                self.end_headers()
                self.wfile.write(body)
            except (BrokenPipeError, ConnectionResetError):
                pass

        def _json(self, obj, code: int = 200) -> None:
            self._send(code, json.dumps(obj).encode("utf-8"), "application/json")

        def _refuse(self, field: str, message: str) -> None:
            self._json({"ok": False, "field": field, "error": message}, 400)

        def _allowed(self) -> bool:
            """The Host (and Origin, when sent) name this server; else a bare 403."""
            hosts = _hosts(*self.server.server_address[:2])
            got = self.headers.get_all("Host") or []
            origin = self.headers.get_all("Origin") or []
            ok = (len(got) == 1 and got[0].strip().lower() in hosts and len(origin) <= 1
                  and all(o.strip().lower() in {"http://" + h for h in hosts}
                          for o in origin))
            if not ok:
                self.close_connection = True
                self._send(403, b"forbidden\n", "text/plain")
            return ok

        def do_GET(self):  # noqa: N802 - http.server's name
            if not self._allowed():
                return
            url = urlparse(self.path)
            if url.path in ("/", "/index.html"):
                self._send(200, html, "text/html; charset=utf-8")
            elif url.path == "/api/case":
                if len(url.query) > MAX_QUERY:
                    self._refuse("case", f"case: the query is longer than {MAX_QUERY} "
                                 "characters")
                    return
                q = {k: v[0] for k, v in parse_qs(url.query).items()}
                race = q.get("race", "inner")
                if race not in ("inner", "outer"):
                    self._refuse("race", "race must be 'inner' or 'outer'")
                    return
                text, path = q.get("path", ""), None
                try:
                    path = resolve_case(text, root, cases)
                    inputs = case_inputs(str(path), race)
                except InputError as exc:      # the path as typed, not as resolved
                    msg = str(exc) if path is None else str(exc).replace(str(path), text)
                    self._json({"ok": False, "field": "case", "error": msg})
                except Exception:
                    log.debug("explorer: case file", exc_info=True)
                    self._json({"ok": False, "field": "case",
                                "error": "case: the file cannot be read as a case file"})
                else:
                    self._json({"ok": True, "inputs": inputs})
            elif url.path == "/favicon.ico":
                self._send(204, b"", "image/x-icon")
            else:
                self._send(404, b"not found", "text/plain")

        def do_POST(self):  # noqa: N802
            if not self._allowed():
                return
            if urlparse(self.path).path != "/api/compute":
                self._send(404, b"not found", "text/plain")
                return
            self.close_connection = True
            try:
                n = int(self.headers.get("Content-Length") or 0)
            except ValueError:
                n = -1
            if not 0 <= n <= MAX_BODY:
                self._refuse("general", f"the request body must be 0 to {MAX_BODY} bytes "
                             f"(Content-Length); got {self.headers.get('Content-Length')!r}"[:200])
                return
            try:
                body = json.loads(self.rfile.read(n) or b"{}")
                params, maxima = check_request(body)
            except RequestError as exc:
                self._refuse(exc.field, str(exc))
                return
            except (ValueError, UnicodeDecodeError, RecursionError) as exc:
                self._refuse("general", "the request body is not JSON: "
                             + one_line(exc)[:200])
                return
            with locks[maxima]:
                self._json(compute_safe(params, maxima))

    class Server(ThreadingHTTPServer):
        daemon_threads = True

        def handle_error(self, request, client_address):  # never a traceback on stderr
            log.debug("explorer: request error", exc_info=True)

    return Server((host, port), Handler)

