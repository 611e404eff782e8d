r"""Ball-bearing kinematics: cage and ball speeds, spin, race control, defect frequencies.

Rigid-body kinematics of a ball rolling between two rings without gross slip, after
Jones (1959, 1960), Harris (2001) ch. 8 and Hamrock & Dowson (1981) §3.4
(eqs. 3.75–3.91).  Everything is a plain, vectorized function of the ball diameter
``D``, pitch diameter ``d_m``, contact angle(s) and the ring speeds; the results
broadcast.

Conventions
-----------
* Ring speeds ``speed_inner`` and ``speed_outer`` are absolute angular speeds about
  the bearing axis, positive in the same sense.  The functions are linear in them, so
  any consistent unit works ([rad/s], [rev/s] = [Hz], [rpm]); the docstrings say
  [rad/s].
* ``gamma = D cos(alpha) / d_m`` (Harris's gamma; ``rho = D / d_m`` is his gamma').
* Coordinates at a ball: x along the bearing axis, z radially outward.  The outer
  contact normal (ball centre to outer contact) is ``(sin a_o, cos a_o)``, the inner
  one points the opposite way, ``-(sin a_i, cos a_i)``.  The ball rotates relative to
  the cage with angular velocity ``omega_R (cos beta, 0, -sin beta)``: ``beta`` is the
  *pitch angle* of the ball axis (H&D's xi, Harris's beta) and ``omega_R`` the *ball
  speed about its own axis*, signed as in Harris (2001): **negative** when the inner
  ring turns in the positive sense and the outer ring stands still.
* The orbital speed of the ball centre equals the cage speed (no cage slip), so
  :func:`orbital_speed` is :func:`cage_speed`.

Race control (Jones 1959): with dry or boundary friction the ball rolls without spin
on the *controlling* race and all spin occurs on the other one.  ``control="outer"``
gives ``tan beta = sin a_o / (cos a_o + D/d_m)``, ``control="inner"`` gives
``tan beta = sin a_i / (cos a_i - D/d_m)`` (H&D eqs. 3.89–3.90).  ``control=
"perpendicular"`` puts the ball axis perpendicular to the line of contact (``beta``
equal to the mean contact angle), the textbook assumption behind the classical
formulas; it is exact for the cage speed when both contact angles are equal.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._checks import (as_array, broadcast, check_choice, check_integer, check_positive,
                      check_range)

__all__ = [
    "CONTROLS",
    "BallKinematics",
    "DefectFrequencies",
    "pitch_ratio",
    "cage_speed",
    "orbital_speed",
    "ball_speed",
    "pitch_angle",
    "ball_kinematics",
    "spin_to_roll",
    "defect_frequencies",
    "bearing_kinematics",
    "bearing_defect_frequencies",
]

CONTROLS = ("outer", "inner", "perpendicular")


def _scalar(x):
    x = np.asarray(x)
    return x[()] if x.ndim == 0 else x


def _check_geometry(D, d_m, name_alpha, alpha, **speeds):
    """Checked D, d_m and an angle, broadcast together and with the named ``speeds``."""
    D = check_positive(D, "D", "m", bounded=True)
    d_m = check_positive(d_m, "d_m", "m", bounded=True)
    a = check_range(alpha, name_alpha, -0.5 * np.pi, 0.5 * np.pi, low_inclusive=True,
                    high_inclusive=True, unit="rad")
    speeds = {n: as_array(v, n, bounded=True, tiny_ok=True, unit="rad/s")
              for n, v in speeds.items()}
    broadcast(D=D, d_m=d_m, **{name_alpha: a}, **speeds)
    if np.any(D >= d_m):
        raise ValueError(f"D must be < d_m [m]; got D={float(np.max(D)):g}, "
                         f"d_m={float(np.min(d_m)):g}")
    return D, d_m, a


def _check_angles(D, d_m, contact_angle_inner, contact_angle_outer, **speeds):
    """Checked D, d_m, alpha_i and alpha_o (alpha_o defaults to alpha_i)."""
    D, d_m, ai = _check_geometry(D, d_m, "contact_angle_inner", contact_angle_inner, **speeds)
    if contact_angle_outer is None:
        return D, d_m, ai, ai
    ao = check_range(contact_angle_outer, "contact_angle_outer", -0.5 * np.pi, 0.5 * np.pi,
                     low_inclusive=True, high_inclusive=True, unit="rad")
    broadcast(D=D, d_m=d_m, contact_angle_inner=ai, contact_angle_outer=ao, **speeds)
    return D, d_m, ai, ao


def pitch_ratio(D, d_m, contact_angle=0.0):
    r"""Harris's gamma = D cos(alpha) / d_m [-].

    .. math:: \gamma = \frac{D\cos\alpha}{d_m}

    Parameters
    ----------
    D : float or array_like
        Ball diameter [m].
    d_m : float or array_like
        Pitch diameter [m], > D.
    contact_angle : float or array_like
        Contact angle alpha [rad], in [-pi/2, pi/2].

    References
    ----------
    Harris (2001) *Rolling Bearing Analysis*, 4th ed., ch. 8; Hamrock & Dowson (1981)
    eq. (3.78).

    Examples
    --------
    >>> round(float(pitch_ratio(7.94e-3, 39.04e-3)), 5)
    0.20338
    """
    D, d_m, a = _check_geometry(D, d_m, "contact_angle", contact_angle)
    return _scalar(D * np.cos(a) / d_m)


def cage_speed(D, d_m, contact_angle=0.0, speed_inner=1.0, speed_outer=0.0):
    r"""Cage (fundamental train) angular speed for equal inner and outer contact angles.

    .. math:: \omega_c = \tfrac12\left[\omega_i (1-\gamma) + \omega_o (1+\gamma)\right],
              \qquad \gamma = D\cos\alpha / d_m

    This is also the orbital speed of the ball centres.  For unequal contact angles use
    :func:`ball_kinematics`.

    Parameters
    ----------
    D : float or array_like
        Ball diameter [m].
    d_m : float or array_like
        Pitch diameter [m].
    contact_angle : float or array_like
        Contact angle alpha [rad].
    speed_inner, speed_outer : float or array_like
        Absolute angular speeds of the inner and outer rings [rad/s].

    Returns
    -------
    float or ndarray
        Cage angular speed [rad/s] (same unit as the ring speeds).

    References
    ----------
    Harris (2001) ch. 8 (cage speed with pure rolling); Hamrock & Dowson (1981)
    eqs. (3.78)–(3.81) with beta_i = beta_o.

    Examples
    --------
    CWRU 6205 drive-end bearing geometry, inner ring at 1 rev/s (0.39831 from the
    geometry; CWRU's table prints 0.39828, inconsistent with its own BPFO/Z = 0.39831):

    >>> round(float(cage_speed(0.3126, 1.537, 0.0, 1.0)), 4)
    0.3983
    """
    D, d_m, a = _check_geometry(D, d_m, "contact_angle", contact_angle,
                                speed_inner=speed_inner, speed_outer=speed_outer)
    wi = as_array(speed_inner, "speed_inner")
    wo = as_array(speed_outer, "speed_outer")
    g = D * np.cos(a) / d_m
    return _scalar(0.5 * (wi * (1.0 - g) + wo * (1.0 + g)))


#: The ball centres orbit with the cage (no cage slip): same function.
orbital_speed = cage_speed


def ball_speed(D, d_m, contact_angle=0.0, speed_inner=1.0, speed_outer=0.0):
    r"""Ball angular speed about its own axis, relative to the cage, classical form.

    .. math:: \omega_R = \frac{d_m}{2D}\,(1-\gamma^2)\,(\omega_o - \omega_i)

    Assumes the ball axis perpendicular to the line of contact (no spin); signed as in
    Harris (2001): negative for a positive inner-ring speed.  Its magnitude in rev/s
    with the inner ring at 1 rev/s is the ball spin frequency factor (BSF).

    Parameters
    ----------
    D, d_m : float or array_like
        Ball and pitch diameters [m].
    contact_angle : float or array_like
        Contact angle alpha [rad].
    speed_inner, speed_outer : float or array_like
        Absolute ring speeds [rad/s].

    Returns
    -------
    float or ndarray
        omega_R [rad/s].

    References
    ----------
    Harris (2001) ch. 8 (ball speed about its own axis); Hamrock & Dowson (1981)
    eqs. (3.76)–(3.77) with beta_i = beta_o = xi.

    Examples
    --------
    >>> round(float(ball_speed(0.3126, 1.537, 0.0, 1.0)), 4)   # CWRU 6205: BSF 2.3567
    -2.3567
    """
    D, d_m, a = _check_geometry(D, d_m, "contact_angle", contact_angle,
                                speed_inner=speed_inner, speed_outer=speed_outer)
    wi = as_array(speed_inner, "speed_inner")
    wo = as_array(speed_outer, "speed_outer")
    g = D * np.cos(a) / d_m
    return _scalar(0.5 * d_m / D * (1.0 - g * g) * (wo - wi))


def pitch_angle(D, d_m, contact_angle_inner, contact_angle_outer=None, control="outer"):
    r"""Pitch angle beta of the ball's rotation axis for a given race control.

    .. math::
        \tan\beta = \frac{\sin\alpha_o}{\cos\alpha_o + D/d_m}\ \text{(outer control)},
        \qquad
        \tan\beta = \frac{\sin\alpha_i}{\cos\alpha_i - D/d_m}\ \text{(inner control)}

    ``control="perpendicular"`` returns the mean contact angle (ball axis
    perpendicular to the line of contact).

    Parameters
    ----------
    D, d_m : float or array_like
        Ball and pitch diameters [m].
    contact_angle_inner : float or array_like
        Inner contact angle alpha_i [rad].
    contact_angle_outer : float or array_like, optional
        Outer contact angle alpha_o [rad]; default alpha_i.
    control : {"outer", "inner", "perpendicular"}
        Race-control hypothesis.

    Returns
    -------
    float or ndarray
        beta [rad].

    References
    ----------
    Jones (1959) J. Basic Eng. 81, 1–12; Hamrock & Dowson (1981) eqs. (3.89)–(3.90);
    Harris (2001) ch. 8.

    Examples
    --------
    40 deg contact, D/d_m = 0.2, outer-race control:

    >>> round(float(np.degrees(pitch_angle(0.2, 1.0, np.radians(40.0)))), 3)
    33.639
    """
    check_choice(control, "control", CONTROLS)
    D, d_m, ai, ao = _check_angles(D, d_m, contact_angle_inner, contact_angle_outer)
    return _scalar(_pitch_angle(D / d_m, ai, ao, control))


def _pitch_angle(rho, ai, ao, control):
    """Internal: beta for validated arrays (rho = D/d_m)."""
    if control == "outer":
        return np.arctan2(np.sin(ao), np.cos(ao) + rho)
    if control == "inner":
        return np.arctan2(np.sin(ai), np.cos(ai) - rho)
    return 0.5 * (ai + ao) + 0.0 * rho


@dataclass(frozen=True)
class BallKinematics:
    """Kinematics of one ball (or an array of balls), frozen.

    Attributes
    ----------
    cage_speed : Cage = ball orbital angular speed omega_c [rad/s].
    ball_speed : Ball angular speed about its own axis relative to the cage,
        omega_R [rad/s], signed (negative for a positive inner-ring speed).
    pitch_angle : Angle beta between the ball axis and the bearing axis [rad].
    spin_inner, spin_outer : Spin angular speed of the ball relative to each race
        about the contact normal [rad/s].
    roll_inner, roll_outer : Rolling angular speed of the ball relative to each race
        (component in the axial plane perpendicular to the contact normal) [rad/s].
    control : Race-control hypothesis used.
    """

    cage_speed: np.ndarray
    ball_speed: np.ndarray
    pitch_angle: np.ndarray
    spin_inner: np.ndarray
    spin_outer: np.ndarray
    roll_inner: np.ndarray
    roll_outer: np.ndarray
    control: str

    @property
    def orbital_speed(self):
        """Ball orbital speed = cage speed [rad/s]."""
        return self.cage_speed

    @property
    def spin_to_roll_inner(self):
        """Spin-to-roll ratio at the inner contact [-]."""
        return _scalar(np.asarray(self.spin_inner) / np.asarray(self.roll_inner))

    @property
    def spin_to_roll_outer(self):
        """Spin-to-roll ratio at the outer contact [-]."""
        return _scalar(np.asarray(self.spin_outer) / np.asarray(self.roll_outer))


def _kinematics(rho, ai, ao, wi, wo, control):
    """Internal kinematics for validated, broadcastable arrays (rho = D/d_m).

    Rolling without slip at the centre of each contact (Hamrock & Dowson 1981
    eqs. 3.75-3.77; Harris 2001 ch. 8), in the cage frame:

        omega_R (D/2) cos(a_o - beta) = (omega_o - omega_c) (d_m/2) (1 + rho cos a_o)
        omega_R (D/2) cos(a_i - beta) = (omega_c - omega_i) (d_m/2) (1 - rho cos a_i)

    Eliminating omega_R gives omega_c as the weighted mean of the ring speeds.
    """
    return _kinematics_beta(rho, ai, ao, wi, wo, _pitch_angle(rho, ai, ao, control))


def _kinematics_beta(rho, ai, ao, wi, wo, beta):
    """Internal: as :func:`_kinematics` for a given pitch angle beta (arrays)."""
    go = rho * np.cos(ao)
    gi = rho * np.cos(ai)
    co = np.cos(ao - beta)
    ci = np.cos(ai - beta)
    A_o = (1.0 + go) / co
    A_i = (1.0 - gi) / ci
    wc = (wi * A_i + wo * A_o) / (A_i + A_o)
    wR = (wo - wc) * A_o / rho                       # omega_R = 2 (w_o - w_c) A_o (d_m/2) / D
    # spin about the contact normals (H&D 1981 eqs. 3.87-3.88, relative ring speeds)
    s_i = wR * np.sin(ai - beta) - (wi - wc) * np.sin(ai)
    s_o = wR * np.sin(ao - beta) - (wo - wc) * np.sin(ao)
    r_i = wR * ci - (wi - wc) * np.cos(ai)
    r_o = wR * co - (wo - wc) * np.cos(ao)
    return beta, wc, wR, s_i, s_o, r_i, r_o


def ball_kinematics(D, d_m, contact_angle_inner, contact_angle_outer=None,
                    speed_inner=1.0, speed_outer=0.0, control="outer") -> BallKinematics:
    r"""Cage speed, ball speed, pitch angle, spin and roll for given contact angles.

    Rolling without slip at both contact centres (cage frame, H&D 1981 eqs.
    3.75–3.77):

    .. math::
        \omega_R \tfrac{D}{2}\cos(\alpha_o-\beta) = (\omega_o-\omega_c)\tfrac{d_m}{2}
            (1+\gamma_o), \qquad
        \omega_R \tfrac{D}{2}\cos(\alpha_i-\beta) = (\omega_c-\omega_i)\tfrac{d_m}{2}
            (1-\gamma_i),

    so that, with :math:`A_o = (1+\gamma_o)/\cos(\alpha_o-\beta)` and
    :math:`A_i = (1-\gamma_i)/\cos(\alpha_i-\beta)`,

    .. math::
        \omega_c = \frac{\omega_i A_i + \omega_o A_o}{A_i + A_o}, \qquad
        \omega_R = \frac{d_m}{D}(\omega_o - \omega_c) A_o,

    and the spin about each contact normal (H&D eqs. 3.87–3.88)

    .. math::
        \omega_{s,j} = \omega_R \sin(\alpha_j - \beta) - (\omega_j - \omega_c)\sin\alpha_j .

    For outer-race control and inner rotation this reduces to Harris's
    :math:`\omega_c = \omega_i (1-\gamma_i)/[1+\cos(\alpha_i-\alpha_o)]`.

    Parameters
    ----------
    D, d_m : float or array_like
        Ball and pitch diameters [m].
    contact_angle_inner : float or array_like
        Inner contact angle alpha_i [rad].
    contact_angle_outer : float or array_like, optional
        Outer contact angle alpha_o [rad]; default alpha_i.
    speed_inner, speed_outer : float or array_like
        Absolute ring speeds [rad/s].
    control : {"outer", "inner", "perpendicular"}
        Race-control hypothesis fixing the pitch angle (:func:`pitch_angle`).

    Returns
    -------
    BallKinematics

    References
    ----------
    Jones (1959) J. Basic Eng. 81, 1–12; Jones (1960) J. Basic Eng. 82, 309–320;
    Hamrock & Dowson (1981) eqs. (3.75)–(3.91); Harris (2001) ch. 8.

    Examples
    --------
    Outer-race control: no spin at the outer contact.

    >>> k = ball_kinematics(0.2, 1.0, np.radians(40.0), speed_inner=1.0)
    >>> round(float(k.cage_speed), 6), round(float(k.ball_speed), 6)
    (0.423396, -2.45644)
    >>> abs(float(k.spin_outer)) < 1e-15
    True
    """
    check_choice(control, "control", CONTROLS)
    D, d_m, ai, ao = _check_angles(D, d_m, contact_angle_inner, contact_angle_outer,
                                   speed_inner=speed_inner, speed_outer=speed_outer)
    wi = as_array(speed_inner, "speed_inner")
    wo = as_array(speed_outer, "speed_outer")
    beta, wc, wR, s_i, s_o, r_i, r_o = _kinematics(D / d_m, ai, ao, wi, wo, control)
    s = _scalar
    return BallKinematics(cage_speed=s(wc), ball_speed=s(wR), pitch_angle=s(beta + 0 * wc),
                          spin_inner=s(s_i), spin_outer=s(s_o), roll_inner=s(r_i),
                          roll_outer=s(r_o), control=control)


def spin_to_roll(D, d_m, contact_angle_inner, contact_angle_outer=None, control="outer"):
    r"""Spin-to-roll ratios at the inner and outer contacts.

    Independent of the ring speeds:

    .. math::
        \left(\frac{\omega_s}{\omega_{roll}}\right)_i = (1-\gamma_i)\tan(\alpha_i-\beta)
            + \frac{D}{d_m}\sin\alpha_i, \qquad
        \left(\frac{\omega_s}{\omega_{roll}}\right)_o = (1+\gamma_o)\tan(\alpha_o-\beta)
            - \frac{D}{d_m}\sin\alpha_o,

    with beta from :func:`pitch_angle`; the controlling race has zero spin.

    Parameters
    ----------
    D, d_m : float or array_like
        Ball and pitch diameters [m].
    contact_angle_inner : float or array_like
        Inner contact angle [rad].
    contact_angle_outer : float or array_like, optional
        Outer contact angle [rad]; default the inner one.
    control : {"outer", "inner", "perpendicular"}
        Race-control hypothesis.

    Returns
    -------
    inner, outer : float or ndarray
        Spin-to-roll ratios [-].

    References
    ----------
    Jones (1959); Harris (2001) ch. 8 (spin-to-roll ratio); derived here from
    Hamrock & Dowson (1981) eqs. (3.75)–(3.88).

    Examples
    --------
    40 deg, D/d_m = 0.2, outer control: inner ratio = 2 (D/d_m) sin a / (1 + gamma):

    >>> i, o = spin_to_roll(0.2, 1.0, np.radians(40.0))
    >>> round(float(i), 5), abs(float(o)) < 1e-15
    (0.22296, True)
    """
    check_choice(control, "control", CONTROLS)
    D, d_m, ai, ao = _check_angles(D, d_m, contact_angle_inner, contact_angle_outer)
    rho = D / d_m
    beta = _pitch_angle(rho, ai, ao, control)
    inner = (1.0 - rho * np.cos(ai)) * np.tan(ai - beta) + rho * np.sin(ai)
    outer = (1.0 + rho * np.cos(ao)) * np.tan(ao - beta) - rho * np.sin(ao)
    if control == "outer":
        outer = np.zeros_like(outer)            # exact zero, not rounding noise
    elif control == "inner":
        inner = np.zeros_like(inner)
    return _scalar(inner), _scalar(outer)


@dataclass(frozen=True)
class DefectFrequencies:
    """Characteristic defect frequencies of a rolling bearing (frozen).

    Units are those of the ring speeds given (rev/s = Hz for frequencies; with ring
    speed 1 they are the usual "multiples of running speed").

    Attributes
    ----------
    ftf : Fundamental train (cage) frequency, absolute |f_c|.
    bpfo : Ball pass frequency, outer race, Z |f_c - f_o|.
    bpfi : Ball pass frequency, inner race, Z |f_i - f_c|.
    bsf : Ball spin frequency (ball rotation about its own axis), |omega_R|; a ball
        defect strikes both races, so its signature appears at 2 BSF.
    """

    ftf: np.ndarray
    bpfo: np.ndarray
    bpfi: np.ndarray
    bsf: np.ndarray


def defect_frequencies(D, d_m, n_balls, contact_angle=0.0, speed_inner=1.0,
                       speed_outer=0.0) -> DefectFrequencies:
    r"""Defect (fault) frequencies FTF, BPFO, BPFI and BSF of a ball bearing.

    .. math::
        f_c = \tfrac12[f_i(1-\gamma) + f_o(1+\gamma)],\quad
        BPFO = Z|f_c - f_o|,\quad BPFI = Z|f_i - f_c|,\quad
        BSF = \frac{d_m}{2D}(1-\gamma^2)|f_i - f_o|

    For a stationary outer ring these are the familiar
    :math:`BPFO = \tfrac{Z}{2} f_r (1-\gamma)`, :math:`BPFI = \tfrac{Z}{2} f_r (1+\gamma)`,
    :math:`FTF = \tfrac12 f_r (1-\gamma)`; for a stationary inner ring and rotating
    outer ring BPFO and BPFI are unchanged in terms of the relative speed and
    :math:`FTF = \tfrac12 f_r (1+\gamma)`.

    Parameters
    ----------
    D, d_m : float or array_like
        Ball and pitch diameters [m] (any common length unit).
    n_balls : int or array_like
        Number of balls Z [-], >= 1.
    contact_angle : float or array_like
        Contact angle [rad].
    speed_inner, speed_outer : float or array_like
        Ring rotational frequencies [Hz] (or rad/s; results in the same unit).

    Returns
    -------
    DefectFrequencies

    References
    ----------
    Harris (2001) ch. 8 (cage and ball speeds); Randall & Antoni (2011) Mech. Syst.
    Signal Process. 25, 485–520, eq. (1); Case Western Reserve University Bearing
    Data Center, "Bearing information" (6205-2RS JEM SKF factors).

    Examples
    --------
    CWRU drive-end 6205-2RS JEM SKF (D = 0.3126 in, d_m = 1.537 in, Z = 9); CWRU
    prints 3.5848, 5.4152 and, for the rolling element (2 BSF), 4.7135 (the geometry
    gives 4.71344):

    >>> f = defect_frequencies(0.3126, 1.537, 9, 0.0, speed_inner=1.0)
    >>> round(float(f.bpfo), 4), round(float(f.bpfi), 4), round(float(2 * f.bsf), 4)
    (3.5848, 5.4152, 4.7134)
    """
    D, d_m, a = _check_geometry(D, d_m, "contact_angle", contact_angle,
                                speed_inner=speed_inner, speed_outer=speed_outer)
    Z = check_integer(n_balls, "n_balls", 1)
    broadcast(D=D, n_balls=Z, speed_inner=speed_inner, speed_outer=speed_outer)
    fi = as_array(speed_inner, "speed_inner")
    fo = as_array(speed_outer, "speed_outer")
    g = D * np.cos(a) / d_m
    fc = 0.5 * (fi * (1.0 - g) + fo * (1.0 + g))
    s = _scalar
    return DefectFrequencies(ftf=s(np.abs(fc)), bpfo=s(Z * np.abs(fc - fo)),
                             bpfi=s(Z * np.abs(fi - fc)),
                             bsf=s(0.5 * d_m / D * (1.0 - g * g) * np.abs(fi - fo)))


def _bearing_numbers(bearing, contact_angle):
    try:
        D = bearing.ball_diameter
        d_m = bearing.pitch_diameter
        Z = bearing.n_balls
        a = bearing.free_contact_angle if contact_angle is None else contact_angle
    except AttributeError as exc:
        raise TypeError("bearing must be a ballrace BallBearing (needs ball_diameter, "
                        f"pitch_diameter, n_balls, free_contact_angle); {exc}") from None
    return D, d_m, Z, a


def bearing_kinematics(bearing, speed_inner=1.0, speed_outer=0.0, contact_angle=None,
                       contact_angle_outer=None, control="outer") -> BallKinematics:
    """:func:`ball_kinematics` for a :class:`ballrace.BallBearing`.

    Parameters
    ----------
    bearing : BallBearing
        Bearing geometry (``ball_diameter``, ``pitch_diameter``,
        ``free_contact_angle`` are used).
    speed_inner, speed_outer : float or array_like
        Absolute ring speeds [rad/s].
    contact_angle : float or array_like, optional
        Inner (or common) operating contact angle [rad]; default the free contact angle.
    contact_angle_outer : float or array_like, optional
        Outer contact angle [rad]; default ``contact_angle``.
    control : {"outer", "inner", "perpendicular"}
        Race-control hypothesis.

    Returns
    -------
    BallKinematics

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> b = SimpleNamespace(ball_diameter=7.94e-3, pitch_diameter=39.04e-3, n_balls=9,
    ...                     free_contact_angle=0.0)
    >>> round(float(bearing_kinematics(b, 1.0).cage_speed), 4)
    0.3983
    """
    D, d_m, _, a = _bearing_numbers(bearing, contact_angle)
    return ball_kinematics(D, d_m, a, contact_angle_outer, speed_inner, speed_outer, control)


def bearing_defect_frequencies(bearing, speed_inner=1.0, speed_outer=0.0,
                               contact_angle=None) -> DefectFrequencies:
    """:func:`defect_frequencies` for a :class:`ballrace.BallBearing`.

    Parameters
    ----------
    bearing : BallBearing
        Bearing geometry.
    speed_inner, speed_outer : float or array_like
        Ring rotational frequencies [Hz].
    contact_angle : float or array_like, optional
        Operating contact angle [rad]; default the free contact angle.

    Returns
    -------
    DefectFrequencies

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> b = SimpleNamespace(ball_diameter=0.2656, pitch_diameter=1.122, n_balls=8,
    ...                     free_contact_angle=0.0)   # CWRU fan-end 6203 (inches)
    >>> f = bearing_defect_frequencies(b, 1.0)
    >>> round(float(f.bpfo), 4), round(float(f.bpfi), 4)
    (3.0531, 4.9469)
    """
    D, d_m, Z, a = _bearing_numbers(bearing, contact_angle)
    return defect_frequencies(D, d_m, Z, a, speed_inner, speed_outer)
