"""Terminal output of the command line: literal text, unit systems and tables that fit.

Everything the CLI prints goes through here, so that

* text from case files and library messages is printed literally: rich markup such as
  ``[bold]`` or ``[link=...]`` is not interpreted, bracketed units (``[m]``, ``[rad]``)
  survive, and control characters (ESC, OSC 8 hyperlinks, bells) are shown escaped
  instead of reaching the terminal (:func:`literal`);
* tables are shown in engineering units by default (mm, µm, MPa, N, deg) with the unit
  in every column header, or in SI / US customary units on request
  (:data:`SYSTEMS`, :func:`convert`);
* wide tables never wrap or truncate: at 80 columns, or when piped, the columns are
  split over several tables that each fit (:func:`print_columns`).

The library itself stays SI; ``--json`` prints SI values.
"""
from __future__ import annotations

import functools
import math
import re

__all__ = ["UNITS_HELP", "SYSTEMS", "convert", "unit_label", "literal", "make_console",
           "print_columns", "print_sections", "fmt"]

#: Display unit (label, pint expression) per kind of quantity and unit system.
SYSTEMS = {
    "si": {"length": ("m", "m"), "small": ("m", "m"), "force": ("N", "N"),
           "stress": ("Pa", "Pa"), "modulus": ("Pa", "Pa"), "angle": ("rad", "rad"),
           "stiffness": ("N/m^1.5", "N/m**1.5"), "speed": ("m/s", "m/s"),
           "moment": ("N·m", "N*m"), "temperature": ("K", "K"), "mass": ("kg", "kg")},
    "eng": {"length": ("mm", "mm"), "small": ("µm", "um"), "force": ("N", "N"),
            "stress": ("MPa", "MPa"), "modulus": ("GPa", "GPa"), "angle": ("deg", "deg"),
            "stiffness": ("N/mm^1.5", "N/mm**1.5"), "speed": ("m/s", "m/s"),
            "moment": ("N·m", "N*m"), "temperature": ("°C", "degC"), "mass": ("kg", "kg")},
    "us": {"length": ("in", "in"), "small": ("µin", "uin"), "force": ("lbf", "lbf"),
           "stress": ("ksi", "kpsi"), "modulus": ("Mpsi", "Mpsi"), "angle": ("deg", "deg"),
           "stiffness": ("lbf/in^1.5", "lbf/in**1.5"), "speed": ("ft/min", "ft/min"),
           "moment": ("lbf·in", "lbf*in"), "temperature": ("°F", "degF"), "mass": ("lb", "lb")},
}

#: Help text of the ``--units`` option of the table-printing commands.
UNITS_HELP = ("Units of the printed tables: eng (mm, µm, MPa, N, deg), si (m, Pa, N, rad) "
              "or us (in, µin, ksi, lbf, deg).  --json is always SI.")

#: SI unit (pint expression) of each kind.
_SI = {"length": "m", "small": "m", "force": "N", "stress": "Pa", "modulus": "Pa",
       "angle": "rad", "stiffness": "N/m**1.5", "speed": "m/s", "moment": "N*m",
       "temperature": "K", "mass": "kg"}

#: Absolute temperatures are affine, not a factor: K -> display (°C, K, °F).
_TEMPERATURE = {"eng": lambda k: k - 273.15, "si": lambda k: k,
                "us": lambda k: (k - 273.15) * 1.8 + 32.0}


@functools.cache
def _factor(kind: str, system: str) -> float:
    from ballrace.units import ureg

    return float(ureg().Quantity(1.0, _SI[kind]).to(SYSTEMS[system][kind][1]).magnitude)


def convert(value, kind: str | None, system: str = "eng"):
    """SI value -> display value of ``kind`` in ``system`` (``kind=None``: unchanged).

    Examples
    --------
    >>> convert(6.35e-3, "length"), convert(2.1e9, "stress"), unit_label("stress")
    (6.35, 2100.0, 'MPa')
    >>> round(convert(4448.2216152605, "force", "us"), 9), unit_label("force", "us")
    (1000.0, 'lbf')
    >>> round(convert(343.15, "temperature"), 9), round(convert(343.15, "temperature", "us"), 9)
    (70.0, 158.0)
    """
    if kind is None or value is None:
        return value
    if system not in SYSTEMS:
        raise ValueError(f"units must be one of {', '.join(SYSTEMS)}; got {system!r}")
    if kind == "temperature":
        return _TEMPERATURE[system](value)
    return value * _factor(kind, system)


def unit_label(kind: str | None, system: str = "eng") -> str:
    """Label of the display unit of ``kind`` ("" for dimensionless)."""
    return "" if kind is None else SYSTEMS[system][kind][0]


# ------------------------------------------------------------------------- literal text
#: C0/C1 control characters (ESC starts colour, cursor and OSC 8 hyperlink sequences) and
#: the bidirectional overrides that can make a terminal show text in another order.
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")


def literal(text) -> "rich.text.Text":  # noqa: F821
    """``text`` as a rich Text printed literally: no markup, control characters escaped.

    >>> literal("[/bold] x [m] \\x1b]8;;http://e\\x1b\\\\").plain
    '[/bold] x [m] \\\\x1b]8;;http://e\\\\x1b\\\\'
    """
    from rich.text import Text

    s = _CONTROL.sub(lambda m: f"\\x{ord(m.group()):02x}" if ord(m.group()) < 256
                     else f"\\u{ord(m.group()):04x}", str(text))
    return Text(s)


def make_console(stderr: bool = False):
    """A rich Console; highlighting off so numbers are not recoloured."""
    from rich.console import Console

    return Console(stderr=stderr, highlight=False)


def fmt(value, digits: int = 6) -> str:
    """A number for a table: plain digits, no e-notation for 1e-4 <= |x| < 1e9."""
    if value is None:
        return "-"
    if isinstance(value, str):
        return value
    v = float(value)
    if not math.isfinite(v):
        return "-" if math.isnan(v) else ("inf" if v > 0 else "-inf")
    if v == 0:
        return "0"
    if 1e-4 <= abs(v) < 1e9:
        mag = math.floor(math.log10(abs(v)))
        dec = max(0, digits - 1 - mag)
        s = f"{v:.{dec}f}"
        if "." in s:
            s = s.rstrip("0").rstrip(".")
        return s
    return f"{v:.{digits}g}"


# ------------------------------------------------------------------------- tables
def _cell(x):
    from rich.text import Text

    return x if isinstance(x, Text) else literal(x)


def _table(title, headers, rows, justify):
    from rich import box
    from rich.table import Table

    t = Table(title=None if title is None else _cell(title), box=box.SIMPLE_HEAD,
              title_justify="left", pad_edge=False)
    for h, j in zip(headers, justify):
        t.add_column(_cell(h), justify=j, no_wrap=True)
    for r in rows:
        t.add_row(*[_cell(c) for c in r])
    return t


def _width(cells) -> int:
    return max(len(str(c)) for c in cells)


def print_columns(console, title: str, headers, rows, *, key_columns: int = 1,
                  justify=None) -> None:
    """A table of ``headers`` x ``rows`` (strings), split into several tables if too wide.

    The first ``key_columns`` columns (e.g. the ball number) repeat in every part.  Cells
    never wrap: the split keeps each part within the console width.
    """
    headers = list(headers)
    n = len(headers)
    justify = list(justify or ["right"] * n)
    # a SIMPLE_HEAD table: one space of padding each side of a cell, one separator
    # between columns and one edge each side
    widths = [_width([headers[j]] + [r[j] for r in rows]) + 3 for j in range(n)]
    avail = max(console.width, 40) - 1
    keys = list(range(key_columns))
    base = sum(widths[j] for j in keys)
    groups, cur, used = [], [], base
    for j in range(key_columns, n):
        if cur and used + widths[j] > avail:
            groups.append(cur)
            cur, used = [], base
        cur.append(j)
        used += widths[j]
    if cur or not groups:
        groups.append(cur)
    for g, cols in enumerate(groups):
        idx = keys + cols
        part = title if len(groups) == 1 else f"{title} ({g + 1}/{len(groups)})"
        console.print(literal(part), style="bold")
        console.print(_table(None, [headers[j] for j in idx],
                             [[r[j] for j in idx] for r in rows], [justify[j] for j in idx]))


def print_sections(console, sections, system: str = "eng") -> None:
    """Print ``[(title, [(name, si_value, kind), ...]), ...]`` as quantity/value/unit tables.

    ``kind`` is a key of :data:`SYSTEMS` (converted to the display ``system``), ``None``
    for a dimensionless number, or a literal unit string prefixed with ``"="``
    (e.g. ``"=h"``: printed as is, value not converted).  A value may be a string
    (printed as is).  Adding a block of results to a command is adding a section.
    """
    for title, rows in sections:
        body = []
        for name, value, kind in rows:
            if isinstance(kind, str) and kind.startswith("="):
                body.append([name, fmt(value), kind[1:]])
            elif isinstance(value, str):
                body.append([name, value, unit_label(kind, system)])
            else:
                body.append([name, fmt(convert(value, kind, system)), unit_label(kind, system)])
        print_columns(console, title, ["quantity", "value", "unit"], body, key_columns=1,
                      justify=["left", "right", "left"])


# ------------------------------------------------------------------------- output folders
#: The folder that ``fem`` and ``teach`` write under unless ``--out`` says otherwise.
OUTPUT_ROOT = "ballrace-out"


def output_folder(folder, option: str = "--out"):
    """Create ``folder`` (and its parents) for a command's output; returns it as a Path.

    When the folder lies under ``ballrace-out/`` that root gets a ``.gitignore`` of ``*``
    (as pytest does for its cache), so the output is ignored by git wherever the command
    runs, inside a repository or not.  A path that exists as a file, or a folder that
    cannot be created, raises ``ValueError`` with a one-line reason naming ``option``.
    """
    import errno
    from pathlib import Path

    folder = Path(folder)
    for p in (folder, *folder.parents):
        if p.exists() and not p.is_dir():
            raise ValueError(f"{option} {folder}: {p} exists and is not a folder; "
                             f"give a folder path")
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        why = {errno.EACCES: "permission denied", errno.EROFS: "read-only file system",
               errno.ENOSPC: "no space left"}.get(exc.errno, exc.strerror or type(exc).__name__)
        raise ValueError(f"{option} {folder}: cannot create the folder ({why}); "
                         f"choose another with {option}") from None
    if not (folder.is_dir() and _writable(folder)):
        raise ValueError(f"{option} {folder}: cannot write there (permission denied); "
                         f"choose another folder with {option}")
    parts = folder.resolve().parts
    if OUTPUT_ROOT in parts:
        root = Path(*parts[:parts.index(OUTPUT_ROOT) + 1])
        ignore = root / ".gitignore"
        if not ignore.exists():
            try:
                ignore.write_text("# written by ballrace: command output, not for git\n*\n")
            except OSError:                                        # pragma: no cover
                pass
    return folder


def _writable(folder) -> bool:
    """Whether a file can be created in ``folder``: tried, not asked (``os.access`` says yes
    to root everywhere, also where the file system then refuses, e.g. /sys)."""
    import os
    import tempfile

    if not os.access(folder, os.W_OK | os.X_OK):
        return False
    try:
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError:
        return False
    return True
