"""The explorer's page: one HTML file with its CSS and JavaScript inline (a canvas front
end, no external asset), served live by :mod:`ballrace.teach.server` or written as a
self-contained handout with a precomputed parameter grid embedded (:func:`export_html`,
``ballrace teach export``).  The page's sources are in ``teach/static/``.  The handout's
grid is the ball modes'; its roller mode needs the live server (the handout says so).
"""
from __future__ import annotations

import base64
import gzip
import json
import logging
from pathlib import Path

from .compute import DEFAULTS, FIELDS, export_grid

__all__ = ["page", "export_html"]

log = logging.getLogger(__name__)

_STATIC = Path(__file__).with_name("static")


def page(data: dict | None = None, initial: dict | None = None) -> str:
    """The explorer's HTML page: CSS and JavaScript inline; ``data`` embedded (export);
    ``initial`` inputs replace those of :data:`~ballrace.teach.compute.DEFAULTS`."""
    html = (_STATIC / "explorer.html").read_text(encoding="utf-8")
    css = (_STATIC / "explorer.css").read_text(encoding="utf-8")
    js = (_STATIC / "explorer.js").read_text(encoding="utf-8")
    blob = ""
    if data is not None:
        raw = json.dumps(data, separators=(",", ":")).encode("utf-8")
        blob = base64.b64encode(gzip.compress(raw, 9, mtime=0)).decode("ascii")
    init = json.dumps({**DEFAULTS, **(initial or {})}).replace("</", "<\\/")
    fields = json.dumps(FIELDS)
    return (html.replace("/*CSS*/", css)
            .replace("/*JS*/", js.replace("</", "<\\/"))
            .replace("__DEFAULTS__", init).replace("__FIELDS__", fields)
            .replace("__DATA__", blob))


def export_html(path, grid: dict | None = None, progress=None) -> Path:
    """Write the self-contained explorer handout to ``path``; returns the path.

    The grid (default :data:`~ballrace.teach.compute.EXPORT_GRID`) is computed by
    :func:`~ballrace.teach.compute.export_grid`, ``progress`` as there.
    """
    data = export_grid(grid, progress)
    if progress:
        n = len(data["tables"])
        progress(n, n, "compressing and writing the page")
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(page(data), encoding="utf-8")
    log.info("wrote %s (%d bytes)", path, path.stat().st_size)
    return path

