"""Draw :class:`ballrace.validation.figures.Figure` panels with matplotlib (Agg) to PNG bytes.

Only renders: the numbers come from :mod:`ballrace.validation.figures`.
"""
from __future__ import annotations

import base64
import io
import logging
from pathlib import Path

__all__ = ["render_png", "png_data_uri", "file_data_uri"]

log = logging.getLogger(__name__)


def _pyplot():
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def _lines(ax, p) -> None:
    for s in p["series"]:
        if p.get("markers_only"):
            ax.plot(s["x"], s["y"], "o-", ms=4, lw=0.8, label=s.get("label"))
        else:
            ax.plot(s["x"], s["y"], lw=1.4, label=s.get("label"))
    for h in p.get("hlines", ()):
        ax.axhline(h["y"], ls="--", lw=0.8, color="k", alpha=0.6)
        ax.annotate(h["label"], (ax.get_xlim()[1], h["y"]), ha="right", va="bottom", fontsize=7)
    for v in p.get("vlines", ()):
        ax.axvline(v["x"], ls=":", lw=0.8, color="k")
    if "hband" in p:
        ax.axhspan(-p["hband"], p["hband"], color="0.85", zorder=0)
    if p.get("logx"):
        ax.set_xscale("log")
    if p.get("invert_y"):
        ax.invert_yaxis()
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="best")


def _contour(fig, ax, p) -> None:
    import numpy as np

    f = np.asarray(p["field"])
    cs = ax.contourf(p["x"], p["y"], f, levels=20, cmap=p.get("cmap", "viridis"))
    ax.contour(p["x"], p["y"], f, levels=10, colors="k", linewidths=0.3)
    fig.colorbar(cs, ax=ax, shrink=0.85)
    for m in p.get("markers", ()):
        ax.plot(m["x"], m["y"], "w+", ms=10, mew=2)
        ax.annotate(m["label"], (m["x"], m["y"]), color="w", fontsize=7,
                    xytext=(4, 4), textcoords="offset points")
    if p.get("invert_y"):
        ax.invert_yaxis()
    ax.set_aspect("equal")


def _bars(ax, p) -> None:
    import numpy as np

    vals = np.asarray(p["values"])
    y = np.arange(len(vals))
    colors = ["tab:green" if ok else "tab:red" for ok in p["ok"]]
    ax.barh(y, vals, color=colors, left=1e-6 if p.get("logx") else 0)
    ax.set_yticks(y, p["labels"], fontsize=5)
    ax.invert_yaxis()
    if p.get("logx"):
        ax.set_xscale("log")
    ax.axvline(p.get("line", 1.0), color="k", lw=1)
    ax.grid(alpha=0.3, axis="x")


def render_png(figure, *, dpi: int = 90) -> bytes:
    """PNG bytes of a figure's panels (one row of subplots, or a column for bar charts)."""
    plt = _pyplot()
    panels = figure.panels
    n = len(panels)
    if n == 1 and panels[0]["kind"] == "bars":
        h = max(3.0, 0.11 * len(panels[0]["labels"]))
        fig, axes = plt.subplots(1, 1, figsize=(9, h))
        axes = [axes]
    else:
        cols = min(n, 4)
        rows = (n + cols - 1) // cols
        fig, axes = plt.subplots(rows, cols, figsize=(4.4 * cols, 3.6 * rows), squeeze=False)
        axes = list(axes.ravel())
        for ax in axes[n:]:
            ax.set_visible(False)
    try:
        for ax, p in zip(axes, panels):
            kind = p["kind"]
            if kind == "lines":
                _lines(ax, p)
            elif kind == "contour":
                _contour(fig, ax, p)
            elif kind == "bars":
                _bars(ax, p)
            else:
                raise ValueError(f"unknown panel kind {kind!r}")
            ax.set_title(p.get("title", ""), fontsize=9)
            ax.set_xlabel(p.get("xlabel", ""), fontsize=8)
            ax.set_ylabel(p.get("ylabel", ""), fontsize=8)
            ax.tick_params(labelsize=7)
        fig.suptitle(figure.title, fontsize=10)
        fig.tight_layout()
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=dpi)
        return buf.getvalue()
    finally:
        plt.close(fig)


def png_data_uri(png: bytes) -> str:
    """``data:image/png;base64,...`` for embedding."""
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


def file_data_uri(path) -> str | None:
    """Data URI of a PNG file, or None if it is missing."""
    p = Path(path)
    if not p.is_file():
        log.warning("render %s not found", p)
        return None
    return png_data_uri(p.read_bytes())
