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
        style = s.get("style", "markers" if p.get("markers_only") else "line")
        kw = {"color": s["color"]} if s.get("color") is not None else {}   # fixed colour
        if style == "markers":
            ax.plot(s["x"], s["y"], "o-", ms=4, lw=0.8, label=s.get("label"), **kw)
        elif style == "dashed-markers":
            ax.plot(s["x"], s["y"], "s--", ms=3.5, lw=0.8, mfc="none", label=s.get("label"),
                    **kw)
        elif style == "published":
            ax.plot(s["x"], s["y"], "o", ms=9, mfc="none", mec="tab:red", mew=1.6,
                    label=s.get("label"), zorder=5)
        elif style == "published-level":
            ax.plot(s["x"], s["y"], ":", color="tab:red", lw=1.6, label=s.get("label"),
                    zorder=5)
        else:
            ax.plot(s["x"], s["y"], "--" if style == "dashed" else "-", lw=1.4,
                    label=s.get("label"), **kw)
    for h, ls in zip(p.get("hlines", ()), ("--", ":", "-.", (0, (5, 1, 1, 1)))):
        ax.axhline(h["y"], ls=ls, lw=0.9, color="k", alpha=0.7, label=h["label"])
    for v in p.get("vlines", ()):
        ax.axvline(v["x"], ls=":", lw=0.8, color="k")
    if "hband" in p:
        ax.axhspan(-p["hband"], p["hband"], color="0.85", zorder=0)
    if p.get("logx"):
        ax.set_xscale("log")
    if p.get("logy"):
        ax.set_yscale("log")
    if "xticks" in p:
        ax.set_xticks(p["xticks"])
    if p.get("invert_y"):
        ax.invert_yaxis()
    ax.grid(alpha=0.3)
    if p.get("legend") == "none":
        pass
    elif p.get("legend") == "below":
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=1,
                  frameon=False)
    else:
        ax.legend(fontsize=7, loc="best")


def _contour(fig, ax, p) -> None:
    import numpy as np

    f = np.asarray(p["field"])
    cs = ax.contourf(p["x"], p["y"], f, levels=20, cmap=p.get("cmap", "viridis"))
    ax.contour(p["x"], p["y"], f, levels=10, colors="k", linewidths=0.3)
    cb = fig.colorbar(cs, ax=ax, shrink=0.85)
    cb.ax.tick_params(labelsize=7)
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
    ax.set_yticks(y, p["labels"], fontsize=7)
    ax.invert_yaxis()
    if p.get("logx"):
        ax.set_xscale("log")
        ax.set_xlim(0.5e-6, 3.0 * max(float(np.max(vals)), 1.0))
    ax.axvline(p.get("line", 1.0), color="k", lw=1)
    ax.grid(alpha=0.3, axis="x")


def _strip(ax, p) -> None:
    """One row of jittered dots per group (``rows``, ``values``, ``ok``)."""
    import numpy as np

    rng = np.random.default_rng(0)          # fixed jitter: the same run draws the same picture
    for i, (vals, ok) in enumerate(zip(p["values"], p["ok"])):
        vals, ok = np.asarray(vals, dtype=float), np.asarray(ok, dtype=bool)
        y = i + rng.uniform(-0.28, 0.28, vals.size)
        ax.scatter(vals[ok], y[ok], s=9, color="tab:green", alpha=0.7, lw=0)
        ax.scatter(vals[~ok], y[~ok], s=22, color="tab:red", lw=0, zorder=3)
    ax.set_yticks(range(len(p["rows"])), p["rows"], fontsize=8)
    ax.set_ylim(len(p["rows"]) - 0.5, -0.5)
    if p.get("logx"):
        ax.set_xscale("log")
        top = max([float(np.max(v)) for v in p["values"] if len(v)] + [1.0])
        ax.set_xlim(0.5 * min(float(np.min(v)) for v in p["values"] if len(v)), 3.0 * top)
    ax.axvline(p.get("line", 1.0), color="k", lw=1)
    ax.grid(alpha=0.3, axis="x")


_DRAW = {"lines": lambda fig, ax, p: _lines(ax, p), "contour": _contour,
         "bars": lambda fig, ax, p: _bars(ax, p), "strip": lambda fig, ax, p: _strip(ax, p)}


def render_png(figure, *, dpi: int = 90) -> bytes:
    """PNG bytes of a figure's panels: one row of up to four (wider rows wrap), sized by
    ``figure.size`` [in] when given, with each panel's optional ``width`` ratio."""
    plt = _pyplot()
    panels = figure.panels
    n = len(panels)
    cols = min(n, 4)
    rows = (n + cols - 1) // cols
    size = tuple(getattr(figure, "size", ()) or ()) or (4.4 * cols, 3.6 * rows)
    ratios = [p.get("width", 1.0) for p in panels[:cols]] + [1.0] * (cols - min(n, cols))
    fig, axes = plt.subplots(rows, cols, figsize=size, squeeze=False, layout="constrained",
                             gridspec_kw={"width_ratios": ratios})
    axes = list(axes.ravel())
    for ax in axes[n:]:
        ax.set_visible(False)
    try:
        for ax, p in zip(axes, panels):
            kind = p["kind"]
            if kind not in _DRAW:
                raise ValueError(f"unknown panel kind {kind!r}")
            _DRAW[kind](fig, ax, p)
            ax.set_title(p.get("title", ""), fontsize=9)
            ax.set_xlabel(p.get("xlabel", ""), fontsize=8)
            ax.set_ylabel(p.get("ylabel", ""), fontsize=8)
            ax.tick_params(labelsize=7)
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
