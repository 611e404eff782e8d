r"""``ballrace shaft CASE.toml``: an elastic shaft on its ball or roller bearings, from a case file.

Registered on the main Typer app by :func:`register` (see :mod:`ballrace.cli`).  The case
file is read, its units parsed, by :mod:`ballrace.casefiles.shaft` (where its format is
documented); :func:`analyze` returns plain SI numbers (what ``--json`` prints) and the
command renders them.
"""
from __future__ import annotations

import json
import logging
import math
from typing import Annotated, Optional

import numpy as np
import typer

from ballrace.casefiles.shaft import ShaftCase, load_shaft_case, parse_shaft_case
from ballrace.console import UNITS_HELP

__all__ = ["register", "analyze", "load_shaft_case", "parse_shaft_case", "ShaftCase"]

log = logging.getLogger(__name__)


#: The ISO 281 note of a seat: when the moment the seat carries, taken as a couple of
#: forces 2|M|/d_m at the pitch radius, exceeds this fraction of the seat's force
#: resultant, the note says that P = X Fr + Y Fa (ISO 281) does not see it.
MOMENT_NOTE_RATIO = 0.25

#: Forces and moments smaller than this fraction of the largest load (moments: of the
#: largest load times the shaft length) are round-off of the equilibrium solve and are
#: printed as 0 in the table (the --json output keeps them).
ROUND_OFF = 1e-9

_NO_EFFECT = r"(shaft|housing)_temperature_change = .* has no effect"


def _thermal_note(case: ShaftCase) -> str | None:
    """The note when the case's temperature changes cannot change a load."""
    o = case.solve_options
    names = [f"{k} = {o[k]:g} K" for k, on in (
        ("shaft_temperature_change", o["shaft_temperature_change"] != 0.0),
        ("housing_temperature_change", o["housing_temperature_change"] != 0.0
         and o["housing_expansion"] != 0.0)) if on]
    n_loc = sum(not s.floating and s.bearing.carries_axial for s in case.seats)
    if not names or n_loc > 1:
        return None
    return (f"[operation] {' and '.join(names)} change nothing here: "
            + ("only one seat locates" if n_loc else "no seat locates")
            + " the shaft axially (the others float), so shaft and housing grow freely; "
            "temperatures load the bearings only between two or more locating seats")


def analyze(case: ShaftCase) -> dict:
    """Solve a :class:`ShaftCase`; plain SI numbers (``--json``)."""
    import warnings

    from ballrace.analytic import shaft as S

    notes = list(case.notes)
    thermal = _thermal_note(case)
    with warnings.catch_warnings():
        if thermal:                             # said in a note instead
            warnings.filterwarnings("ignore", message=_NO_EFFECT, category=UserWarning)
        r = S.solve(case.shaft, case.seats, case.loads, gravity=case.gravity,
                    **case.solve_options)
    if thermal:
        notes.append(thermal)
    try:
        lf = S.rating_lives(r, rotating=case.rotating_ring,
                            dynamic_rating=[c for c in case.ratings] if any(
                                c is not None for c in case.ratings) else None)
    except ValueError as exc:
        lf = None
        notes.append(f"lives not available: {exc}")
    seats = []
    for k, s in enumerate(case.seats):
        b = r.bearings[k]
        rows = b if isinstance(b, tuple) else (b,)
        if s.ball_bearing is None:              # a roller seat (or another seat bearing)
            d = _roller_seat(s, rows, r, k)
        else:
            d = _ball_seat(s, rows, r, k)
        if lf is not None:
            d["L10r"] = float(lf.seat_lives[k])
            d["L10_iso281"] = lf.catalog_lives[k]
            if case.speed_rpm:
                d["L10r_h"] = float(lf.hours(case.speed_rpm)[0][k])
                if lf.catalog_lives[k] is not None:
                    d["L10_iso281_h"] = lf.catalog_lives[k] * 1e6 / (60 * case.speed_rpm)
        seats.append(d)
    for d, st in zip(seats, case.seats):
        if lf is not None and d.get("L10_iso281") is None:
            why = ("its rows share the thrust in a way the catalogue formula does not know"
                   if len(st.mounts) > 1 else
                   "the X/Y tables do not cover its load")
            notes.append(f"{d['name']}: no ISO 281 catalogue life ({why}); its life is "
                         "L10r (ISO/TS 16281)")
        elif lf is not None:
            note = _moment_note(d, d["pitch_diameter"] if st.ball_bearing is None
                                else st.ball_bearing.pitch_diameter)
            if note:
                notes.append(note)
    L = case.shaft.length
    xs = np.linspace(0.0, L, 201)
    disp = r.displacement(xs)
    at = r.displacement(np.array([p.position for p in case.loads])) if case.loads else \
        np.zeros((0, 5))
    out = {
        "title": case.title,
        "units": {"length": "m", "force": "N", "moment": "N m", "angle": "rad",
                  "life": "1e6 rev (…_h: hours)"},
        "shaft": {"length": L, "sections": [list(s) for s in case.shaft.sections],
                  "elements": int(r.nodes.size - 1), "mass": case.shaft.mass,
                  "material": {"E": case.shaft.material.E, "nu": case.shaft.material.nu,
                               "density": case.shaft.material.density,
                               "name": case.shaft.material.name},
                  "iterations": int(r.iterations), "residual": float(r.relative_residual),
                  "max_deflection": float(np.hypot(disp[:, 1], disp[:, 2]).max()),
                  "equilibrium_residual": [float(v) for v in r.equilibrium_residual()]},
        "loads": [dict(name=p.name, position=p.position, vector=[float(v) for v in p.vector],
                       displacement=[float(v) for v in u],
                       deflection=float(np.hypot(u[1], u[2])),
                       slope=float(np.hypot(u[3], u[4])))
                  for p, u in zip(case.loads, at)],
        "seats": seats,
        "deflection": {"x": [float(v) for v in xs], "v": [float(v) for v in disp[:, 1]],
                       "w": [float(v) for v in disp[:, 2]], "u": [float(v) for v in disp[:, 0]]},
        "life": None if lf is None else {
            "kind": lf.kind, "weibull_slope": lf.weibull_slope, "system": float(lf.system),
            "system_h": float(lf.hours(case.speed_rpm)[1]) if case.speed_rpm else None},
        "notes": notes,
        "duty": None,
    }
    rollers = any(st.ball_bearing is None for st in case.seats)
    if rollers and lf is not None:              # ball and roller seats: e per seat
        out["life"]["seat_weibull_slopes"] = [float(e) for e in lf.seat_weibull_slopes]
    if case.duty:
        def scaled(p, f):
            return S.PointLoad(p.position, *(f * p.vector), name=p.name)

        kw = dict(rotating=case.rotating_ring,
                  dynamic_rating=[c for c in case.ratings] if any(
                      c is not None for c in case.ratings) else None,
                  gravity=case.gravity, **case.solve_options)
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message=_NO_EFFECT, category=UserWarning)
            dc = S.duty_cycle(case.shaft, case.seats,
                              [([scaled(p, f) for p in case.loads], t, n)
                               for t, n, f in case.duty], **kw)
        out["duty"] = {"fractions": [t for t, _, _ in case.duty],
                       "speed_rpm": [n for _, n, _ in case.duty],
                       "load_factor": [f for _, _, f in case.duty],
                       "case_hours": [[float(v) for v in row] for row in dc.case_hours],
                       "seat_hours": [float(v) for v in dc.seat_hours],
                       "system_hours": float(dc.system_hours),
                       "weibull_slope": dc.weibull_slope}
        if rollers:
            out["duty"]["seat_weibull_slopes"] = [float(e) for e in dc.seat_weibull_slopes]
    return out


def _ball_seat(s, rows, r, k) -> dict:
    """The ``--json`` row of a ball seat ``s`` (k-th of the solved shaft ``r``; ``rows``
    its rows' load distributions)."""
    from ballrace.analytic import ratings
    from ballrace.analytic.duplex import DuplexPair

    s0 = r.static_safety
    Q = np.concatenate([np.atleast_1d(x.ball_loads) for x in rows])
    pmax = max(float(np.max(x.inner.p_max)) for x in rows) if Q.max() > 0 else 0.0
    pmax = max(pmax, max(float(np.max(x.outer.p_max)) for x in rows) if Q.max() > 0 else 0)
    beta = np.concatenate([np.atleast_1d(x.contact_angles)[np.atleast_1d(x.ball_loads) > 0]
                           for x in rows]) if Q.max() > 0 else np.zeros(1)
    R = r.reactions[k]
    kind = ratings.bearing_type(s.ball_bearing)
    pair = isinstance(s.bearing, DuplexPair)
    d = dict(name=s.name, position=s.position,
             bearing=("pair " + s.bearing.arrangement) if pair else "single",
             direction=s.direction, floating=s.floating,
             clearance=(s.ball_bearing.diametral_clearance if s.clearance is None
                        else s.clearance),
             operating_clearance=None if pair else (
                 s.ball_bearing.diametral_clearance if s.clearance is None else s.clearance),
             reaction=[float(v) for v in R], radial_load=float(np.hypot(R[1], R[2])),
             moment=float(np.hypot(R[3], R[4])),
             max_ball_load=float(Q.max()), max_pressure=pmax,
             static_safety=float(s0[k]),
             contact_angle_min=float(beta.min()), contact_angle_max=float(beta.max()),
             contact_angle_limit=(ratings.DEEP_GROOVE_ANGLE_LIMIT if kind == "deep-groove"
                                  else None),
             misalignment=float(r.misalignment[k]),
             misalignment_limit=ratings.PERMISSIBLE_MISALIGNMENT[kind],
             radial_deflection=float(np.hypot(*r.ring_displacements[k, 1:3])),
             axial_deflection=float(r.ring_displacements[k, 0]),
             stiffness=[[float(v) for v in row] for row in r.seat_stiffness[k]])
    return d


def _roller_seat(s, rows, r, k) -> dict:
    """The ``--json`` row of a seat whose rows are not ball rows (a roller bearing's: their
    :class:`~ballrace.analytic.roller.loaddist.RollerLoadDistribution`), from what the
    seat bearing and its rows' results say (the seat contract, duck-typed): the ball row's
    keys where they mean the same (``max_roller_load`` for ``max_ball_load``; the contact
    angle is the bearing's, fixed), and the roller's own (``edge_load_ratio``: the largest
    end-slice load over the most loaded roller's mean slice load,
    :func:`~ballrace.analytic.roller.bearing.edge_load_ratio`; slices; the life's Weibull
    slope and exponent)."""
    from ballrace.analytic.life import BALL_WEIBULL_SLOPE
    from ballrace.analytic.roller.bearing import edge_load_ratio

    brg = s.bearing
    R = r.reactions[k]
    one = rows[0].bearing                      # the single bearing of the rows
    Q = np.concatenate([np.atleast_1d(x.roller_loads) for x in rows])
    angle = float(getattr(one, "contact_angle", 0.0))
    return dict(name=s.name, position=s.position, bearing=brg.seat_name,
                rolling_element="roller", carries_axial=bool(brg.carries_axial),
                direction=s.direction, floating=s.floating,
                clearance=float(rows[0].clearance),
                operating_clearance=float(rows[0].clearance) if brg.accepts_clearance else None,
                reaction=[float(v) for v in R], radial_load=float(np.hypot(R[1], R[2])),
                moment=float(np.hypot(R[3], R[4])),
                max_roller_load=float(Q.max()),
                max_pressure=max(float(np.max(x.max_pressure)) for x in rows),
                static_safety=float(r.static_safety[k]),
                contact_angle_min=angle, contact_angle_max=angle, contact_angle_limit=None,
                misalignment=float(r.misalignment[k]),
                misalignment_limit=getattr(brg, "permissible_misalignment", None),
                edge_load_ratio=max(edge_load_ratio(x.slice_loads) for x in rows),
                n_slices=int(one.n_slices), pitch_diameter=float(one.pitch_diameter),
                radial_deflection=float(np.hypot(*r.ring_displacements[k, 1:3])),
                axial_deflection=float(r.ring_displacements[k, 0]),
                stiffness=[[float(v) for v in row] for row in r.seat_stiffness[k]],
                life_exponent=float(brg.life_exponent),
                weibull_slope=float(getattr(brg, "weibull_slope", BALL_WEIBULL_SLOPE)))


def _moment_note(d: dict, pitch_diameter: float) -> str | None:
    """The note that the ISO 281 life of a seat does not see its moment, when the moment
    matters (:data:`MOMENT_NOTE_RATIO`); None otherwise."""
    R = d["reaction"]
    F = math.hypot(d["radial_load"], R[0])
    couple = 2.0 * d["moment"] / pitch_diameter
    if not couple > MOMENT_NOTE_RATIO * F:
        return None
    text = (f"{d['name']}: the catalog equivalent load P = X Fr + Y Fa ignores the moment "
            f"{d['moment']:.4g} N m the seat carries (a couple of {couple:.4g} N at the pitch "
            f"radius against {F:.4g} N of force)")
    if d["L10r"] < d["L10_iso281"]:
        return text + (f", so the ISO 281 life above is not conservative (L10r / L10 = "
                       f"{d['L10r'] / d['L10_iso281']:.3g}); use L10r (ISO/TS 16281), from "
                       "the load distribution")
    return text + "; L10r (ISO/TS 16281), from the load distribution, includes it"


def _render(r: dict, units: str = "eng") -> None:
    from ballrace.analytic import ratings
    from ballrace.console import convert as cv
    from ballrace.console import fmt, literal, make_console, print_columns, print_sections
    from ballrace.console import unit_label as ul

    con = make_console()
    sh = r["shaft"]
    rows = [("length", sh["length"], "length"), ("beam elements", sh["elements"], None),
            ("mass", sh["mass"], "mass"), ("largest lateral deflection", sh["max_deflection"],
                                          "small"),
            ("Newton iterations", sh["iterations"], None),
            ("relative residual", sh["residual"], None)]
    if r["life"]:
        lf = r["life"]
        rows.append((f"system life {lf['kind']} ({_slope_text(lf)})",
                     lf["system"], "=1e6 rev"))
        if lf["system_h"] is not None:
            rows.append(("system life", lf["system_h"], "=h"))
    print_sections(con, [(r["title"] or "shaft", rows)], units)

    def g(x, kind, digits=5):
        return fmt(cv(x, kind, units), digits)

    # round-off of the equilibrium solve (a floating seat's 5e-8 N of thrust) prints as 0
    fscale = max([abs(v) for s in r["seats"] for v in s["reaction"][:3]]
                 + [abs(v) for p in r["loads"] for v in p["vector"][:3]] + [0.0])
    mscale = fscale * sh["length"]

    def force(x):
        return g(0.0 if abs(x) < ROUND_OFF * fscale else x, "force")

    def moment(x):
        return g(0.0 if abs(x) < ROUND_OFF * mscale else x, "moment", 4)

    F, M, Ln, Sm, A = (ul(k, units) for k in ("force", "moment", "length", "small", "angle"))
    flagged = rflagged = False
    t1, t2, t3, t4 = [], [], [], []
    for s in r["seats"]:
        R = s["reaction"]
        bad_s0 = s["static_safety"] < 1.0
        lim = s["contact_angle_limit"]
        bad_beta = lim is not None and max(abs(s["contact_angle_min"]),
                                           abs(s["contact_angle_max"])) > lim
        bad_tilt = (s["misalignment_limit"] is not None
                    and s["misalignment"] > s["misalignment_limit"])
        roller = s.get("rolling_element") == "roller"
        flagged |= not roller and (bad_s0 or bad_beta or bad_tilt)
        rflagged |= roller and (bad_s0 or bad_tilt)
        oc = s["operating_clearance"]
        n = s["name"]
        thrust = (f" {'+' if s['direction'] > 0 else '-'}x"
                  if s.get("carries_axial", True) else "")
        t1.append([n, g(s["position"], "length"), force(s["radial_load"]), force(R[0]),
                   force(R[1]), force(R[2])])
        t2.append([n, f"{s['bearing']}{thrust}"
                   + (" floating" if s["floating"] else ""), moment(R[3]), moment(R[4]),
                   fmt(s["misalignment"] * 1e3, 3) + (" !" if bad_tilt else "")])
        t3.append([n, "-" if oc is None else g(oc, "small", 4),
                   g(s["max_roller_load" if roller else "max_ball_load"], "force"),
                   g(s["max_pressure"], "stress", 4),
                   fmt(s["static_safety"], 3) + (" !" if bad_s0 else ""),
                   "roller" if roller else
                   f"{g(s['contact_angle_min'], 'angle', 3)}.."
                   f"{g(s['contact_angle_max'], 'angle', 3)}" + (" !" if bad_beta else "")])
        t4.append([n, g(s["radial_deflection"], "small", 4),
                   fmt(s["L10r_h"], 4) if s.get("L10r_h") is not None else "-",
                   fmt(s["L10_iso281_h"], 4) if s.get("L10_iso281_h") is not None else "-"])
    print_columns(con, "Seats: forces carried (shaft frame)",
                  ["seat", f"x [{Ln}]", f"Fr [{F}]", f"Fa [{F}]", f"Fy [{F}]", f"Fz [{F}]"], t1)
    print_columns(con, "Seats: moments carried and tilt",
                  ["seat", "bearing", f"My [{M}]", f"Mz [{M}]", "tilt [mrad]"], t2)
    print_columns(con, "Seats: contacts",
                  ["seat", f"P_d [{Sm}]", f"Q_max [{F}]", f"p_max [{ul('stress', units)}]",
                   "s0", f"beta [{A}]"], t3)
    print_columns(con, "Seats: deflection and lives",
                  ["seat", f"radial defl. [{Sm}]", "L10r [h]", "ISO 281 L10 [h]"], t4)
    legend = ("Fr = sqrt(Fy^2 + Fz^2); P_d: the seat's operating diametral clearance "
              "(negative: preload)")
    if any(s.get("rolling_element") != "roller" for s in r["seats"]):      # ball seats
        legend += ("; s0 = (4200 MPa / p_max)^3 from the most loaded contact "
                   "(ISO 76 bases C0 on 4200 MPa); L10r: ISO/TS 16281 life from the ball "
                   "loads, ISO 281 L10 from P = X Fr + Y Fa")
    if any(s.get("rolling_element") == "roller" for s in r["seats"]):
        legend += ("; roller seats: Q_max the largest roller load, p_max and s0 = "
                   "(4000 MPa / p_max)^2 of the most loaded slice of the lamina model (ISO 76 "
                   "bases C0r on 4000 MPa), beta shown as \"roller\" (the contact angle is the "
                   "bearing's: 0, or the cup angle), L10r from the slice loads (ISO/TS 16281), "
                   "ISO 281 L10 = (C/P)^(10/3), lives combined with e = 9/8")
    if r["loads"]:
        dscale = max([p["deflection"] for p in r["loads"]] + [0.0])
        tscale = max([p["slope"] for p in r["loads"]] + [0.0])

        def small(x):
            return g(0.0 if abs(x) < ROUND_OFF * dscale else x, "small", 4)

        def mrad(x):
            return fmt(0.0 if abs(x) < ROUND_OFF * tscale else x * 1e3, 4)

        headers = ["load", f"x [{Ln}]", f"F [{F}]", f"deflection [{Sm}]", "slope [mrad]"]
        rows = [[p["name"], g(p["position"], "length"), force(math.hypot(*p["vector"][:3])),
                 small(p["deflection"]), mrad(p["slope"])] for p in r["loads"]]
        print_columns(con, "Load points: shaft deflection and slope", headers, rows)
        legend += ("; F: magnitude of the load's force; deflection and slope: sqrt(v^2 + w^2) "
                   "and the rotation of the shaft "
                   "section at the load point (a gear's mesh misalignment; components in "
                   "--json)")
    notes = [legend]
    if flagged:
        notes.append(
            "! beyond a limit: s0 < 1 (the contact pressure exceeds the 4200 MPa of C0, "
            "ISO 76), a deep-groove bearing beyond "
            f"{math.degrees(ratings.DEEP_GROOVE_ANGLE_LIMIT):.0f} deg of contact angle, or a "
            "tilt beyond the permissible misalignment of the bearing type (deep-groove "
            f"{math.degrees(ratings.PERMISSIBLE_MISALIGNMENT['deep-groove']) * 60:.0f} arcmin, "
            "angular-contact "
            f"{math.degrees(ratings.PERMISSIBLE_MISALIGNMENT['angular-contact']) * 60:.0f} "
            "arcmin; ballrace.analytic.ratings)")
    if rflagged:
        from ballrace.analytic.roller import bearing as rb

        lims = rb.PERMISSIBLE_MISALIGNMENT
        notes.append(
            "! roller seats: s0 < 1 (the lamina pressure exceeds the 4000 MPa of C0r, ISO 76) "
            "or a tilt beyond the permissible misalignment (cylindrical "
            f"{math.degrees(lims['cylindrical']) * 60:.0f} arcmin, tapered "
            f"{math.degrees(lims['tapered']) * 60:.0f} arcmin; "
            "ballrace.analytic.roller.bearing)")
    if r.get("duty"):
        d = r["duty"]
        rows = [(f"{s['name']}: L10r (Palmgren-Miner)", h, "=h")
                for s, h in zip(r["seats"], d["seat_hours"])]
        rows.append((f"system ({_slope_text(d)})", d["system_hours"], "=h"))
        print_sections(con, [(f"Duty cycle ({len(d['fractions'])} cases)", rows)], units)
    for n in notes + r["notes"]:
        con.print(literal(f"note: {n}"), style="dim")


def _slope_text(life: dict) -> str:
    """"e = 1.111", or with ball and roller seats (different slopes, ``weibull_slope``
    nan) "e = 1.111, 1.125 per seat"."""
    e = life["weibull_slope"]
    if e is not None and math.isfinite(e):
        return f"e = {e:.4g}"
    return "e = " + ", ".join(f"{v:.4g}" for v in life["seat_weibull_slopes"]) + " per seat"


def plot(r: dict, path) -> float:
    """Picture of the shaft, its seats, loads, exaggerated deflection line and forces, in the
    two lateral planes (x-y above, x-z below); returns the deflection scale factor."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    L = r["shaft"]["length"]
    fig, axes = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    x = np.array(r["deflection"]["x"])
    v = np.array(r["deflection"]["v"])
    w = np.array(r["deflection"]["w"])
    Dmax = max(s[1] for s in r["shaft"]["sections"])
    vmax = max(np.abs(v).max(), np.abs(w).max(), 1e-300)
    scale = 0.6 * Dmax / vmax
    # one arrow scale for both planes: the largest lateral force component
    Fmax = max([abs(c) for s in r["seats"] for c in s["reaction"][1:3]]
               + [abs(c) for p in r["loads"] for c in p["vector"][1:3]] + [1e-300])
    arrow = 0.8 * Dmax * 1e3 / Fmax
    for ax, j, defl, name, colour in ((axes[0], 1, v, "y", "C0"), (axes[1], 2, w, "z", "C2")):
        x0 = 0.0
        for length, D, d in r["shaft"]["sections"]:
            ax.add_patch(plt.Rectangle((x0 * 1e3, -D / 2 * 1e3), length * 1e3, D * 1e3,
                                       fc="0.85", ec="0.4"))
            x0 += length
        ax.plot(x * 1e3, defl * scale * 1e3, colour, lw=2,
                label=f"{'v' if j == 1 else 'w'} ({name}) x {scale:.3g}")
        for s in r["seats"]:
            xs = s["position"] * 1e3
            ax.plot([xs], [-Dmax * 0.75e3], "k^", ms=12)
            Fs = -s["reaction"][j]               # force of the bearing on the shaft
            ax.annotate("", (xs, 0), (xs, -Fs * arrow),
                        arrowprops=dict(arrowstyle="->", color="C3"))
            ax.text(xs, -Dmax * 1.05e3, f"{s['name']}\n{s['reaction'][j]:.4g} N", ha="center",
                    va="top", fontsize=8)
        for p in r["loads"]:
            xp = p["position"] * 1e3
            Fp = p["vector"][j]
            ax.annotate("", (xp, 0), (xp, -Fp * arrow),
                        arrowprops=dict(arrowstyle="->", color="C1", lw=2))
            ax.text(xp, Dmax * 1.1e3, f"{p['name']}\n{Fp:.4g} N", ha="center", fontsize=8)
        ax.set_ylim(-1.6 * Dmax * 1e3, 1.6 * Dmax * 1e3)
        ax.set_ylabel(f"{name} [mm]")
        ax.set_title(f"x-{name} plane: {name} forces on the shaft (seats: the load they carry)",
                     fontsize=9)
        ax.legend(loc="upper right", fontsize=8)
    axes[1].set_xlim(-0.05 * L * 1e3, 1.05 * L * 1e3)
    axes[1].set_xlabel("x [mm]")
    fig.suptitle((r["title"] or "shaft") + f"\ndeflection exaggerated x {scale:.3g}",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return scale


def _clean(obj):
    """JSON-safe copy: NaN / inf become null (as ``ballrace bearing --json``)."""
    from ballrace.commands.bearing import jsonable as clean

    return clean(obj)


def register(app) -> None:
    """Add the ``shaft`` command to a Typer app."""

    @app.command("shaft")
    def shaft_cmd(
        case_file: Annotated[str, typer.Argument(
            help="Shaft case file (TOML, kind = \"shaft\"; docs/shaft.md).")],
        as_json: Annotated[bool, typer.Option(
            "--json", help="Machine-readable JSON (SI units).")] = False,
        units: Annotated[str, typer.Option("--units", help=UNITS_HELP)] = "eng",
        plot_file: Annotated[Optional[str], typer.Option(
            "--plot", help="Write a picture of the shaft (PNG/SVG/PDF) to this file.")] = None,
    ):
        """An elastic shaft on its ball or roller bearings: reactions, element loads,
        deflection, lives."""
        from ballrace.commands import run_case_file

        result = run_case_file(case_file, units, "shaft", load_shaft_case, analyze,
                               lambda exc: str(exc).splitlines()[0] if "\n" in str(exc)
                               else str(exc))
        if plot_file:
            scale = plot(result, plot_file)
            if not as_json:
                typer.echo(f"picture: {plot_file} (deflection scale x {scale:.3g})")
        if as_json:
            typer.echo(json.dumps(_clean(result), indent=2))
            return
        _render(result, units)
