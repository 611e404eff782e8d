"""The explorer's live server and browser, shared by the explorer tests (test_explorer.py,
test_teach_roller.py, test_trust3_explorer.py)."""
from __future__ import annotations

import json
import os
import shutil
import threading
import urllib.request
from contextlib import contextmanager
from pathlib import Path

from ballrace.teach import server as tsrv


@contextmanager
def live_server():
    """The explorer's server on a free local port, in a daemon thread: yields its URL."""
    srv = tsrv.make_server(0)
    th = threading.Thread(target=srv.serve_forever, kwargs={"poll_interval": 0.05}, daemon=True)
    th.start()
    try:
        yield f"http://127.0.0.1:{srv.server_address[1]}"
    finally:
        srv.shutdown()
        srv.server_close()


def post(url, body):
    """POST ``body`` as JSON to ``url``/api/compute: (HTTP status, decoded answer)."""
    req = urllib.request.Request(url + "/api/compute", data=json.dumps(body).encode(),
                                 headers={"Content-Type": "application/json"}, method="POST")
    with urllib.request.urlopen(req, timeout=60) as f:
        return f.status, json.loads(f.read())


def chromium():
    """A Chromium executable ($BALLRACE_CHROMIUM first), or None."""
    for p in (os.environ.get("BALLRACE_CHROMIUM"), "/usr/bin/chromium", shutil.which("chromium"),
              shutil.which("chromium-browser")):
        if p and Path(p).exists():
            return p
    return None
