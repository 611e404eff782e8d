"""Sphinx extension: the validation-case pages, generated from ``validation/cases/*.toml``.

At ``builder-inited`` every case file becomes one reStructuredText page under
``docs/cases/`` (git-ignored, rewritten on each build) listing each case with its source,
kind, calculation, inputs (as written in the file, with units), sweep, expected values,
tolerances and the stated reason for each tolerance — so a reader can audit the suite
without running it.  The TOML is read as written ([defaults] merged into each case the
way the runner merges them); nothing is evaluated.
"""
from __future__ import annotations

import tomllib
from pathlib import Path

CASES_DIR = Path(__file__).resolve().parents[2] / "validation" / "cases"
OUT = "cases"

_KIND_NOTE = {
    "published": "the expected numbers are printed in the cited source",
    "independent derivation": "computed by a method sharing no code with the library",
    "FE check": "the finite-element model against the analytic solution",
    "regression baseline": "a self-generated snapshot",
}


def merge_defaults(defaults: dict, case: dict) -> dict:
    """Merge a file's ``[defaults]`` into one case (inputs and source merged key by key)."""
    out = dict(defaults)
    for key, val in case.items():
        if key in ("inputs", "source") and isinstance(val, dict) \
                and isinstance(out.get(key), dict):
            out[key] = {**out[key], **val}
        else:
            out[key] = val
    return out


def on_demand(case: dict) -> bool:
    """The runner leaves this case out of its default selection (tag ``on-demand``, see
    :data:`ballrace.validation.schema.ON_DEMAND`): it runs only when its file is named
    with ``--cases``."""
    from ballrace.validation.schema import ON_DEMAND

    return ON_DEMAND in (case.get("tags") or ())


def load_cases(path: Path) -> tuple[str, list[dict]]:
    """The leading comment block of a case file and its cases, defaults merged.

    In the comment, text in backticks and indented lines (a command to type) become
    literals, so that ``--cases`` is never typeset as a dash."""
    text = path.read_text(encoding="utf-8")
    data = tomllib.loads(text)
    intro = []
    for line in text.splitlines():
        if line.startswith("#"):
            body = line[1:]
            if body.startswith("   ") and body.strip():        # "#   ballrace validate ..."
                intro.append(f"`{body.strip()}`")
            else:
                intro.append(body.strip())
        elif line.strip():
            break
    defaults = data.get("defaults", {})
    return " ".join(x for x in intro if x and not set(x) <= set("-= ")), [
        merge_defaults(defaults, c) for c in data.get("case", [])]


def _lit(value) -> str:
    """A TOML value as inline literal text."""
    if isinstance(value, str):
        s = value
    elif isinstance(value, dict):
        s = "{" + ", ".join(f"{k} = {_plain(v)}" for k, v in value.items()) + "}"
    else:
        s = _plain(value)
    s = s.replace("`", "'")
    return f"``{s}``" if s.strip() else "(empty)"


def _plain(value) -> str:
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, list):
        return "[" + ", ".join(_plain(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k} = {_plain(v)}" for k, v in value.items()) + "}"
    return repr(value)


def _text(value) -> str:
    """Free text (titles, reasons, notes) safe for a table cell or paragraph."""
    s = " ".join(str(value).split())
    for ch in ("\\", "*", "`", "|", "_"):
        s = s.replace(ch, "\\" + ch)
    return s


def _prose(value) -> str:
    """Free text with its `backticked` spans as inline literals (commands, options)."""
    import re

    def text(p):                     # keep the spaces around a literal
        return (" " if p[:1].isspace() else "") + _text(p) + (" " if p[-1:].isspace() else "")

    parts = re.split(r"`([^`]+)`", " ".join(str(value).split()))
    return "".join(_lit(p) if i % 2 else text(p) for i, p in enumerate(parts))


def _table(header: list[str], rows: list[list[str]], widths: str) -> list[str]:
    out = [".. list-table::", "   :header-rows: 1", f"   :widths: {widths}", ""]
    for row in [header] + rows:
        out.append(f"   * - {row[0]}")
        out.extend(f"     - {cell}" for cell in row[1:])
    out.append("")
    return out


def _tolerance(spec: dict) -> str:
    parts = []
    for key in ("rtol", "atol"):
        if key in spec:
            val = spec[key]
            parts.append(f"{key} = {val}" if isinstance(val, str) else f"{key} = {_plain(val)}")
    return ", ".join(parts) or "—"


def _expected(spec) -> str:
    if not isinstance(spec, dict):
        return _lit(spec)
    if "value" in spec:
        return _lit(spec["value"])
    bounds = []
    if "min" in spec:
        bounds.append(f"≥ {_lit(spec['min'])}")
    if "max" in spec:
        bounds.append(f"≤ {_lit(spec['max'])}")
    return " and ".join(bounds) or "—"


def case_rst(case: dict) -> list[str]:
    """The reStructuredText of one case."""
    cid = str(case.get("id", "?"))
    title = f"{cid}"
    out = [f".. _case-{cid}:", "", title, "~" * max(len(title), 4), ""]
    if "title" in case:
        out += [f"*{_text(case['title'])}*", ""]
    src = case.get("source", {})
    if isinstance(src, dict):
        src_txt = ", ".join(_text(src[k]) for k in ("author", "year", "reference") if k in src)
    else:
        src_txt = _text(src)
    kind = str(case.get("kind", "—"))
    fields = [("kind", f"{_text(kind)}" + (f" ({_KIND_NOTE[kind]})" if kind in _KIND_NOTE
                                          else "")),
              ("calculation", _lit(case.get("calculation", "—"))),
              ("source", src_txt or "—")]
    if "fem_levels" in case:
        fields.append(("FE levels", ", ".join(_lit(x) for x in case["fem_levels"])))
    if on_demand(case):
        fields.append(("runs", "on demand only: ``ballrace validate`` leaves it out unless "
                               "its file is named with ``--cases``"))
    for name, val in fields:
        out += [f":{name}: {val}"]
    out.append("")
    inputs = case.get("inputs", {})
    if inputs:
        out += ["**Inputs**", ""]
        out += _table(["input", "value"], [[_lit(k), _lit(v)] for k, v in inputs.items()],
                      "30 70")
    if case.get("sweep"):
        out += ["**Sweep** (every combination is run)", ""]
        out += _table(["input", "values"],
                      [[_lit(k), _lit(v)] for k, v in case["sweep"].items()], "30 70")
    if case.get("reduce"):
        out += ["**Reduced to**", ""]
        out += _table(["output", "reduction"],
                      [[_lit(k), _lit(v)] for k, v in case["reduce"].items()], "30 70")
    expected = case.get("expected", {})
    if expected:
        out += ["**Expected**", ""]
        rows = []
        for name, spec in expected.items():
            spec_d = spec if isinstance(spec, dict) else {}
            rows.append([_lit(name), _expected(spec), _tolerance(spec_d),
                         _text(spec_d.get("reason", "—"))])
        out += _table(["output", "expected", "tolerance", "why this tolerance"], rows,
                      "18 22 15 45")
    if case.get("notes"):
        out += [f"*Notes:* {_text(case['notes'])}", ""]
    return out


def _count(n: int, n_on_demand: int) -> str:
    """``"12 cases"``, ``"2 cases, on demand"``, ``"5 cases, 1 of them on demand"``."""
    word = "case" if n == 1 else "cases"
    if not n_on_demand:
        return f"{n} {word}"
    if n_on_demand == n:
        return f"{n} {word}, on demand"
    return f"{n} {word}, {n_on_demand} of them on demand"


def file_rst(path: Path) -> tuple[str, int]:
    """The page of one case file and its number of cases."""
    intro, cases = load_cases(path)
    name = path.stem
    head = f"{name} ({_count(len(cases), sum(map(on_demand, cases)))})"
    out = [f".. _cases-{name}:", "", head, "=" * len(head), "",
           f"Generated from ``validation/cases/{path.name}`` when the site was built.", ""]
    if intro:
        out += [_prose(intro), ""]
    out += ["Contents: " + ", ".join(f":ref:`{c.get('id')} <case-{c.get('id')}>`"
                                     for c in cases), ""]
    for c in cases:
        out += case_rst(c)
    return "\n".join(out) + "\n", len(cases)


def write_pages(srcdir: Path, cases_dir: Path = CASES_DIR) -> list[Path]:
    """Write ``cases/index.rst`` and one page per case file; return the files written."""
    outdir = Path(srcdir) / OUT
    outdir.mkdir(exist_ok=True)
    files = sorted(cases_dir.glob("*.toml"))
    written, summary, total, total_od = [], [], 0, 0
    for path in files:
        text, n = file_rst(path)
        n_od = sum(map(on_demand, load_cases(path)[1]))
        total += n
        total_od += n_od
        summary.append((path.stem, n, n_od))
        target = outdir / f"{path.stem}.rst"
        if not target.exists() or target.read_text(encoding="utf-8") != text:
            target.write_text(text, encoding="utf-8")   # unchanged pages keep their mtime
        written.append(target)
    for stale in outdir.glob("*.rst"):
        if stale.name != "index.rst" and stale not in written:
            stale.unlink()
    runs = (f"``ballrace validate`` runs {total - total_od} of them; the other {total_od}, "
            "tagged ``on-demand`` (long FE sweeps), run only when their file is named "
            "with ``--cases``" if total_od else
            f"``ballrace validate`` runs all {total}")
    index = ["Validation cases", "================", "",
             f"Every reference case of ``ballrace validate`` — {total} cases in "
             f"{len(files)} files — with its source, inputs, expected values and the reason "
             "for each tolerance, generated from ``validation/cases/*.toml`` at build time. "
             f"{runs}.  How the runner uses them: :doc:`/validation`.", "",
             ".. list-table::", "   :header-rows: 1", "", "   * - file", "     - cases",
             "     - run by default"]
    for stem, n, n_od in summary:
        index += [f"   * - :doc:`{stem}`", f"     - {n}", f"     - {n - n_od}"]
    index += ["   * - all files", f"     - {total}", f"     - {total - total_od}"]
    index += ["", ".. toctree::", "   :hidden:", ""] + [f"   {s[0]}" for s in summary]
    text = "\n".join(index) + "\n"
    target = outdir / "index.rst"
    if not target.exists() or target.read_text(encoding="utf-8") != text:
        target.write_text(text, encoding="utf-8")
    return [target] + written


def _generate(app):
    write_pages(Path(app.srcdir), Path(app.config.casepages_dir or CASES_DIR))


def setup(app):
    app.add_config_value("casepages_dir", "", "env")
    app.connect("builder-inited", _generate)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
