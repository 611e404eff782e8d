r"""ISO/TS 16281:2008 reference rating life of roller bearings from slice (lamina) loads.

The roller-bearing load distribution of ISO/TS 16281 cuts every roller into n_s slices
(laminae) of equal width and gives the load q_jk of slice k of roller j at the inner and
the outer raceway (arrays of shape (Z, n_s)).  From them, step by step:

1. **Raceway capacities tied to the catalogue rating C** (ISO 281 C_r, which contains
   b_m and f_c; :func:`ballrace.analytic.roller.ratings.dynamic_rating`):

   .. math::
       Q_{ci} = \frac{C}{\lambda\nu\ 0.378\ Z \cos\alpha\ i^{7/9}}
                \left[1 + \left(1.038\left(\frac{1-\gamma}{1+\gamma}\right)^{143/108}
                \right)^{9/2}\right]^{2/9},\qquad
       Q_{ce} = \frac{C}{\lambda\nu\ 0.364\ Z \cos\alpha\ i^{7/9}}
                \left[1 + \left(1.038\left(\frac{1-\gamma}{1+\gamma}\right)^{143/108}
                \right)^{-9/2}\right]^{2/9}

   with λν = 0.83 and γ = D_we cos α / D_pw.  Dividing by λν removes the reduction for
   edge stresses and uneven load along the roller that ISO 281's f_c contains, because
   the lamina loads carry the profile, tilt and uneven load instead.  They do not carry an
   edge *peak*: independent slices have none (the half-space line contact,
   :meth:`RollerLoadDistribution.roller_contact
   <ballrace.analytic.roller.loaddist.RollerLoadDistribution.roller_contact>`, shows it),
   so an edge-loaded roller's L10r misses that peak's stress.  0.378 and
   0.364 are Lundberg & Palmgren's load-integral ratios J_r/J_1 and J_r/J_2 of a line
   contact at ε = 0.5 (exactly 0.37637 and 0.36304 with the load–deflection exponent
   10/9), and 1.038 = 0.378/0.364 is the ratio of the two ring ratings, so that the ring
   ratings C_i = 0.378 Z cos α Q_ci λν i^(7/9), C_e likewise, recombine to exactly C:
   (C_i^(-9/2) + C_e^(-9/2))^(-2/9) = C.
2. **Lamina capacities** q_c = Q_c n_s^(-7/9): the line-contact rating grows with the
   contact length as L^(7/9), so n_s slices of length L/n_s each rate n_s^(-7/9) Q_c.
3. **Equivalent lamina loads**: over the ring that rotates relative to the load, each
   point meets every roller's load (4th-power mean, the life exponent of a line contact);
   the stationary ring keeps its loaded points (power 9/2 = 4 × 9/8, the Weibull slope
   9/8):

   .. math::
       q_{ke,rot} = \left(\frac{1}{Z}\sum_j q_{jk}^{4}\right)^{1/4},\qquad
       q_{ke,stat} = \left(\frac{1}{Z}\sum_j q_{jk}^{9/2}\right)^{2/9}
4. **Basic reference rating life** and the dynamic equivalent reference load:

   .. math::
       L_{10r} = \left[\sum_{k=1}^{n_s}\left(\frac{q_{kei}}{q_{ci}}\right)^{9/2}
                 + \left(\frac{q_{kee}}{q_{ce}}\right)^{9/2}\right]^{-8/9},\qquad
       P_{ref} = \frac{C}{L_{10r}^{3/10}}

   (the sum runs over the slices of every row when i = 2).  The inner- and outer-ring
   lives L_i = [Σ_k (q_kei/q_ci)^(9/2)]^(-8/9) combine as
   L10r = (L_i^(-9/8) + L_e^(-9/8))^(-8/9).

Identities (asserted in ``tests/test_roller_ratings.py``)
---------------------------------------------------------
* **Any number of slices.**  Equal slice loads q_jk = Q_j / n_s give the same L10r for
  every n_s: each of the n_s terms is n_s^(-9/2) · n_s^(7/9·9/2) = n_s^(-1) times the
  one-slice term.
* **Straight rollers, zero clearance, pure radial load.**  With Q_j = Q_max cos^(10/9) ψ_j
  and F_r = Σ Q_j cos ψ_j, the raceway equivalent loads are Q_ei = (J_1/J_r) F_r /
  (Z cos α) and Q_ee = (J_2/J_r) F_r/(Z cos α) (Z large), so

  .. math::
      L_{10r} = K \left(\frac{C}{\lambda\nu\,F_r}\right)^{4},\qquad
      K = \left[\frac{(0.378\,J_1/J_r)^{9/2}}{1 + T^{9/2}}
          + \frac{(0.364\,J_2/J_r)^{9/2}}{1 + T^{-9/2}}\right]^{-8/9}

  with T = 1.038 ((1−γ)/(1+γ))^(143/108); K = 0.983 … 0.986 for γ = 0.01 … 0.5 (it
  would be exactly 1 with the unrounded load-integral ratios).  The fixed factor is on the
  load: L10r^(1/4) F_r / C = K^(1/4)/0.83 ≈ 1.200, independent of the load, whereas
  ISO 281 gives L10^(3/10) F_r / C = 1; the two lives are equal only at
  C/F_r = (0.83^4/K)^(3/2) ≈ 0.335, so for any real load ISO/TS 16281 with straight
  rollers gives the longer life.

Sources and their checks
------------------------
ISO/TS 16281:2008 itself was not read.  Every constant and exponent above is the same in
two independent public transcriptions of its roller-bearing clauses (open-source code),
and a commercial program's ISO/TS 16281 report of a 13-roller cylindrical roller bearing
(C = 32 500 N) is reproduced: its raceway ratings Q_ci = 8165.4 N and Q_ce = 13 681.3 N
are consistent with one γ to 0.03 %, and its Q_ei = 4331.1 N, Q_ee = 4523.2 N give
L10r = 11.430 and P_ref = 15 648 N by the formulas of step 4, as reported.  The edge
stress concentration factor of the standard's slices (its eq. 60) is not applied here.

References
----------
ISO/TS 16281:2008 *Rolling bearings — Methods for calculating the modified reference rating
life for universally loaded bearings* (roller bearings: the lamina method); G. Lundberg and
A. Palmgren, *Dynamic capacity of roller bearings* (1952) (ring equivalent loads of line
contact, exponents 4 and 9/2); T. A. Harris (2001) *Rolling Bearing Analysis* 4th ed. §18.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._checks import check_choice, check_integer, check_nonnegative, check_positive, check_range
from ..iso16281 import ReferenceLifeMethods
from .ratings import LAMBDA_NU, life_modification_factor

__all__ = [
    "RING_LOAD_RATIOS",
    "RING_RATING_RATIO",
    "raceway_capacities",
    "lamina_capacities",
    "equivalent_lamina_loads",
    "ReferenceRatingLife",
    "lamina_reference_life",
    "reference_rating_life",
]

#: Lundberg & Palmgren's load-integral ratios (J_r/J_1, J_r/J_2) of a line contact at
#: ε = 0.5, as ISO/TS 16281 rounds them [-].
RING_LOAD_RATIOS = (0.378, 0.364)
#: Ratio of the inner- to the outer-ring rating factor in ISO/TS 16281 [-].
RING_RATING_RATIO = 1.038


def _s(x):
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def raceway_capacities(C, n_rollers, roller_diameter, pitch_diameter, contact_angle=0.0,
                       n_rows: int = 1):
    r"""Basic dynamic load ratings of the inner and outer raceway of a roller bearing [N].

    Q_ci and Q_ce of ISO/TS 16281 (step 1 of the module notes): the roller load that the
    raceway endures for 1e6 revolutions, tied to the bearing's rating C.

    Parameters
    ----------
    C : float
        Basic dynamic radial load rating C_r (ISO 281) [N], > 0.
    n_rollers : int
        Rollers per row Z [-], >= 3.
    roller_diameter, pitch_diameter : float
        D_we, D_pw [m].
    contact_angle : float
        Nominal contact angle α [rad], in [0, pi/2): the angle C is rated at.
    n_rows : int
        Rows i [-].

    Returns
    -------
    (Q_ci, Q_ce) : floats [N].

    Examples
    --------
    >>> qi, qe = raceway_capacities(75809.0, 14, 0.013, 0.07065)
    >>> round(qi), round(qe)
    (17730, 29038)
    """
    C = float(check_positive(C, "C", "N", bounded=True))
    Z = float(check_integer(n_rollers, "n_rollers", 3))
    D = float(check_positive(roller_diameter, "roller_diameter", "m", bounded=True))
    dpw = float(check_positive(pitch_diameter, "pitch_diameter", "m", bounded=True))
    a = float(check_range(contact_angle, "contact_angle", 0.0, np.pi / 2, low_inclusive=True,
                          unit="rad"))
    i = float(check_integer(n_rows, "n_rows", 1))
    if D >= dpw:
        raise ValueError(f"roller_diameter must be < pitch_diameter [m]; got D_we = {D!r}, "
                         f"D_pw = {dpw!r}")
    g = D * np.cos(a) / dpw
    T = RING_RATING_RATIO * ((1.0 - g) / (1.0 + g)) ** (143.0 / 108.0)
    base = C / (LAMBDA_NU * Z * np.cos(a) * i ** (7.0 / 9.0))
    ri, re = RING_LOAD_RATIOS
    Qci = base / ri * (1.0 + T ** 4.5) ** (2.0 / 9.0)
    Qce = base / re * (1.0 + T ** -4.5) ** (2.0 / 9.0)
    return float(Qci), float(Qce)


def lamina_capacities(C, n_rollers, roller_diameter, pitch_diameter, n_slices,
                      contact_angle=0.0, n_rows: int = 1):
    r"""Basic dynamic load ratings of one slice of the inner and outer raceway [N].

    .. math:: q_{ci} = Q_{ci}\, n_s^{-7/9},\qquad q_{ce} = Q_{ce}\, n_s^{-7/9}

    Parameters
    ----------
    C, n_rollers, roller_diameter, pitch_diameter, contact_angle, n_rows
        As in :func:`raceway_capacities`.
    n_slices : int
        Slices per roller n_s [-], >= 1.

    Returns
    -------
    (q_ci, q_ce) : floats [N].

    Examples
    --------
    >>> qi, qe = lamina_capacities(75809.0, 14, 0.013, 0.07065, 30)
    >>> round(qi), round(qe)
    (1258, 2061)
    """
    ns = float(check_integer(n_slices, "n_slices", 1))
    Qci, Qce = raceway_capacities(C, n_rollers, roller_diameter, pitch_diameter,
                                  contact_angle, n_rows)
    f = ns ** (-7.0 / 9.0)
    return Qci * f, Qce * f


def equivalent_lamina_loads(slice_loads, rotating: bool):
    r"""Dynamic equivalent load of every slice position of a raceway [N].

    .. math::
        q_{ke} = \left(\frac{1}{Z}\sum_j q_{jk}^{w}\right)^{1/w},\qquad
        w = 4 \ \text{(ring rotating relative to the load)},\quad
        w = 9/2 \ \text{(stationary)}

    Parameters
    ----------
    slice_loads : array_like
        q_jk [N], >= 0, shape (..., Z, n_s): rollers on the second-last axis, slices on
        the last.
    rotating : bool
        The raceway's ring rotates relative to the load.

    Returns
    -------
    ndarray
        q_ke [N], shape (..., n_s).

    Examples
    --------
    >>> q = [[100.0, 100.0], [0.0, 0.0]]
    >>> equivalent_lamina_loads(q, rotating=True).round(3)       # 100 / 2^(1/4)
    array([84.09, 84.09])
    """
    q = check_nonnegative(slice_loads, "slice_loads", "N")
    if q.ndim < 2:
        raise ValueError(f"slice_loads must have shape (..., Z, n_slices); got {q.shape}")
    w = 4.0 if rotating else 4.5
    top = np.max(q, axis=-2, keepdims=True)          # scaled: no underflow of tiny loads
    top = np.where(top > 0, top, 1.0)
    return np.mean((q / top) ** w, axis=-2) ** (1.0 / w) * top[..., 0, :]


@dataclass(frozen=True)
class ReferenceRatingLife(ReferenceLifeMethods):
    """ISO/TS 16281 reference rating life of a roller bearing (frozen; arrays over leading
    load-case axes, floats for one load case).  ``hours``, ``a_iso`` (with the roller a_ISO)
    and ``modified``: :class:`ballrace.analytic.iso16281.ReferenceLifeMethods`.

    Attributes
    ----------
    L10r : Basic reference rating life [1e6 rev].
    L_inner, L_outer : Ring lives [1e6 rev].
    q_ci, q_ce : Lamina dynamic load ratings of the inner and outer raceway [N].
    q_ei, q_ee : Equivalent lamina loads, shape (..., [rows,] n_s) [N].
    P_ref : Dynamic equivalent reference load C / L10r^(3/10) [N].
    C : Basic dynamic load rating used [N].
    rotating : Ring rotating relative to the load ("inner" or "outer").
    n_slices : Slices per roller [-].
    """

    L10r: float
    L_inner: float
    L_outer: float
    q_ci: float
    q_ce: float
    q_ei: np.ndarray
    q_ee: np.ndarray
    P_ref: float
    C: float
    rotating: str
    n_slices: int

    @property
    def Q_ci(self):
        """Raceway capacity of the inner ring for the whole roller, q_ci n_s^(7/9) [N]
        (the name of the ball-bearing result)."""
        return self.q_ci * self.n_slices ** (7.0 / 9.0)

    @property
    def Q_ce(self):
        """Raceway capacity of the outer ring for the whole roller, q_ce n_s^(7/9) [N]."""
        return self.q_ce * self.n_slices ** (7.0 / 9.0)

    @property
    def Q_ei(self):
        """Equivalent roller load of the inner raceway, Q_ci L_inner^(-1/4) [N]: the load of
        a uniformly loaded roller (equal slices) that gives the inner ring the same life,
        L_inner = (Q_ci / Q_ei)^4 (the ball result's Q_ei with the line-contact exponent)."""
        return _s(self.Q_ci * np.asarray(self.L_inner, float) ** -0.25)

    @property
    def Q_ee(self):
        """Equivalent roller load of the outer raceway, Q_ce L_outer^(-1/4) [N]."""
        return _s(self.Q_ce * np.asarray(self.L_outer, float) ** -0.25)

    def life_modification_factor(self):
        """a_ISO function of radial roller bearings
        (:func:`ballrace.analytic.roller.ratings.life_modification_factor`)."""
        return life_modification_factor


def lamina_reference_life(slice_loads, C, roller_diameter, pitch_diameter, contact_angle=0.0,
                          n_rows: int = 1, *, slice_loads_outer=None,
                          rotating: str = "inner") -> ReferenceRatingLife:
    r"""ISO/TS 16281 basic reference rating life L10r from the slice loads of every roller.

    Steps 1–4 of the module notes.

    Parameters
    ----------
    slice_loads : array_like
        Slice loads q_jk at the inner raceway [N], >= 0, shape (..., Z, n_s) for one row,
        (..., i, Z, n_s) for i rows; leading axes are load cases.
    C : float
        Basic dynamic load rating of the bearing (ISO 281 C_r) [N], > 0.
    roller_diameter, pitch_diameter : float
        D_we, D_pw [m].
    contact_angle : float
        Nominal contact angle α [rad], in [0, pi/2).
    n_rows : int
        Rows i [-].
    slice_loads_outer : array_like, optional
        Slice loads at the outer raceway [N], the shape of ``slice_loads``; default the
        same loads (a cylindrical roller without centrifugal force carries the same load
        at both raceways; a tapered roller's differ by the flange load).
    rotating : {"inner", "outer"}
        Ring rotating relative to the load.

    Returns
    -------
    ReferenceRatingLife

    References
    ----------
    ISO/TS 16281:2008 (lamina method for roller bearings; see the module notes for the
    sources and their checks).

    Examples
    --------
    14 rollers of a 210-size bearing, the three most loaded carrying a uniform 4000, 3000
    and 3000 N over 10 slices each:

    >>> q = np.zeros((14, 10)); q[0] = 400.0; q[1] = q[13] = 300.0
    >>> r = lamina_reference_life(q, 75809.0, 0.013, 0.07065)
    >>> round(r.L10r), round(r.P_ref)
    (2958, 6893)
    """
    check_choice(rotating, "rotating", ("inner", "outer"))
    qi = check_nonnegative(slice_loads, "slice_loads", "N")
    qo = qi if slice_loads_outer is None else check_nonnegative(slice_loads_outer,
                                                                "slice_loads_outer", "N")
    if qo.shape != qi.shape:
        raise ValueError(f"slice_loads_outer must have the shape of slice_loads {qi.shape}; "
                         f"got {qo.shape}")
    i = int(check_integer(n_rows, "n_rows", 1))
    need = 2 if i == 1 else 3
    if qi.ndim < need or (i > 1 and qi.shape[-3] != i):
        raise ValueError(f"slice_loads must have shape (..., Z, n_slices) for one row or "
                         f"(..., n_rows, Z, n_slices) for {i} rows; got {qi.shape}")
    Z, ns = qi.shape[-2], qi.shape[-1]
    if Z < 3:
        raise ValueError(f"slice_loads must hold the loads of every roller (Z >= 3) on its "
                         f"second-last axis; got shape {qi.shape}")
    C = float(check_positive(C, "C", "N", bounded=True))
    qci, qce = lamina_capacities(C, Z, roller_diameter, pitch_diameter, ns, contact_angle, i)
    rot = rotating == "inner"
    qei = equivalent_lamina_loads(qi, rotating=rot)
    qee = equivalent_lamina_loads(qo, rotating=not rot)
    axes = (-1,) if i == 1 else (-2, -1)
    ri, re = qei / qci, qee / qce
    # sums scaled by the largest ratio m: L = (sum (r/m)^4.5)^(-8/9) m^-4, so that tiny
    # loads give a long life instead of an underflow to zero
    m = np.maximum(np.max(ri, axis=axes), np.max(re, axis=axes))
    if np.any(m == 0.0):
        raise ValueError("slice_loads are all zero: the bearing carries no load (infinite life)")
    mk = np.expand_dims(m, axes)
    si = np.sum((ri / mk) ** 4.5, axis=axes)
    se = np.sum((re / mk) ** 4.5, axis=axes)
    with np.errstate(divide="ignore", over="ignore"):
        scale = m ** -4.0
        Li = np.where(si > 0, np.where(si > 0, si, 1.0) ** (-8.0 / 9.0) * scale, np.inf)
        Le = np.where(se > 0, np.where(se > 0, se, 1.0) ** (-8.0 / 9.0) * scale, np.inf)
        L = (si + se) ** (-8.0 / 9.0) * scale
    return ReferenceRatingLife(L10r=_s(L), L_inner=_s(Li), L_outer=_s(Le), q_ci=qci, q_ce=qce,
                               q_ei=qei, q_ee=qee, P_ref=_s(C / L ** 0.3), C=C,
                               rotating=rotating, n_slices=int(ns))


def reference_rating_life(bearing, result, *, dynamic_rating=None,
                          rotating: str = "inner") -> ReferenceRatingLife:
    r"""ISO/TS 16281 basic reference rating life from a roller bearing and its solution.

    Reads the geometry from ``bearing`` (``n_rollers``, ``roller_diameter``,
    ``pitch_diameter``, ``contact_angle`` [rad], optional ``n_rows``) and the slice loads
    from ``result`` (``slice_loads`` [N], shape (Z, n_s), the outer raceway; optional
    ``slice_loads_inner`` where the inner raceway's differ) and calls
    :func:`lamina_reference_life`.

    Parameters
    ----------
    bearing : object
        A roller bearing with the attributes above; its ``dynamic_rating()`` is the
        default C.
    result : object
        A load-distribution result with ``slice_loads``.
    dynamic_rating : float, optional
        C [N]; default ``bearing.dynamic_rating()``.
    rotating : {"inner", "outer"}
        Ring rotating relative to the load.

    Returns
    -------
    ReferenceRatingLife

    Examples
    --------
    >>> from types import SimpleNamespace as NS
    >>> b = NS(n_rollers=14, roller_diameter=0.013, pitch_diameter=0.07065,
    ...        contact_angle=0.0, dynamic_rating=lambda: 75809.0)
    >>> q = np.zeros((14, 10)); q[0] = 400.0; q[1] = q[13] = 300.0
    >>> round(reference_rating_life(b, NS(slice_loads=q)).L10r)
    2958
    """
    for name in ("n_rollers", "roller_diameter", "pitch_diameter", "contact_angle"):
        if not hasattr(bearing, name):
            raise TypeError(f"bearing must have {name} (a roller bearing); got "
                            f"{type(bearing).__name__}")
    if not hasattr(result, "slice_loads"):
        raise TypeError(f"result must have slice_loads [N] (a roller-bearing solution); got "
                        f"{type(result).__name__}")
    if dynamic_rating is None:
        if not callable(getattr(bearing, "dynamic_rating", None)):
            raise TypeError("give dynamic_rating [N]: the bearing has no dynamic_rating()")
        dynamic_rating = bearing.dynamic_rating()
    outer = np.asarray(result.slice_loads, dtype=float)
    inner = getattr(result, "slice_loads_inner", None)
    inner = outer if inner is None else inner
    i = getattr(bearing, "n_rows", 1)
    if outer.shape[-2] != bearing.n_rollers:
        raise ValueError(f"result.slice_loads has {outer.shape[-2]} rollers on its "
                         f"second-last axis; the bearing has {bearing.n_rollers}")
    return lamina_reference_life(inner, dynamic_rating, bearing.roller_diameter,
                                 bearing.pitch_diameter, bearing.contact_angle, i,
                                 slice_loads_outer=outer, rotating=rotating)
