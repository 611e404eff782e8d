"""Elastic materials and the effective contact modulus.

Two moduli appear in the contact literature and differ by a factor of two:

* Hamrock & Dowson's **E'** (``E_prime``), used throughout this package,
  ``E' = 2 / [(1 - nu1**2)/E1 + (1 - nu2**2)/E2]``;
* Johnson's **E*** (``E_star``), ``1/E* = (1 - nu1**2)/E1 + (1 - nu2**2)/E2``,
  so ``E* = E'/2``.

The functions are named for their symbols so nobody confuses them.
"""
from __future__ import annotations

from dataclasses import dataclass


from ._checks import check_instance, check_positive, check_range

__all__ = ["Material", "effective_modulus", "johnson_modulus", "BEARING_STEEL", "SILICON_NITRIDE"]


@dataclass(frozen=True)
class Material:
    """Isotropic linear-elastic material (frozen).

    Parameters
    ----------
    E : float
        Young's modulus [Pa], > 0.
    nu : float
        Poisson's ratio [-], in (-1, 0.5).
    density : float, optional
        Mass density [kg/m^3], > 0; used for ball centrifugal force and gyroscopic
        moment at high speed.  Default 7850 (bearing steel).
    name : str, optional
        Label for tables and reports.

    Examples
    --------
    >>> steel = Material(E=200e9, nu=0.3)
    >>> round(steel.reduced_modulus / 1e9, 2)    # E / (1 - nu^2)  [GPa]
    219.78
    >>> Material(E=200e9, nu=0.5)
    Traceback (most recent call last):
    ...
    ValueError: nu must be in (-1, 0.5) [-]; got 0.5
    """

    E: float
    nu: float
    density: float = 7850.0
    name: str = ""

    def __post_init__(self) -> None:
        checked = (check_positive(self.E, "E", "Pa", bounded=True),
                   check_range(self.nu, "nu", -1.0, 0.5, unit="-"),
                   check_positive(self.density, "density", "kg/m^3", bounded=True))
        for name, arr in zip(("E", "nu", "density"), checked):
            if arr.ndim:
                raise TypeError(f"{name} must be a single real number, not an array; "
                                f"got shape {arr.shape}")
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a string; got {type(self.name).__name__}")
        from .plausible import modulus

        modulus(self.E, "E", stacklevel=4)           # Material(E=200): GPa typed as Pa

    @property
    def reduced_modulus(self) -> float:
        """Plane-strain modulus E/(1 - nu^2) [Pa] of this material alone."""
        return self.E / (1.0 - self.nu**2)


def effective_modulus(material1: Material, material2: Material | None = None):
    r"""Hamrock–Dowson effective modulus E' of two bodies in contact [Pa].

    .. math:: E' = \frac{2}{(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2}

    This is **twice** Johnson's contact modulus E* (see :func:`johnson_modulus`).

    Parameters
    ----------
    material1 : Material
        Body 1.
    material2 : Material, optional
        Body 2; the same as body 1 when omitted.

    Returns
    -------
    float
        E' [Pa].

    References
    ----------
    Hamrock, B.J. & Dowson, D. (1981) *Ball Bearing Lubrication*, ch. 3, eq. (3.4)
    (NASA TM-81691); Ricci (2009) eq. (13).

    Examples
    --------
    >>> steel = Material(E=200e9, nu=0.3)
    >>> round(effective_modulus(steel) / 1e9, 3)   # = E/(1-nu^2) for like materials
    219.78
    """
    check_instance(material1, "material1", Material, "ballrace.Material")
    if material2 is not None:
        check_instance(material2, "material2", Material, "ballrace.Material")
    m2 = material1 if material2 is None else material2
    return 2.0 / ((1.0 - material1.nu**2) / material1.E + (1.0 - m2.nu**2) / m2.E)


def johnson_modulus(material1: Material, material2: Material | None = None):
    r"""Johnson's contact modulus E* = E'/2 [Pa].

    .. math:: \frac{1}{E^*} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2}

    References
    ----------
    Johnson, K.L. (1985) *Contact Mechanics*, Cambridge, eq. (4.22).

    Examples
    --------
    >>> steel = Material(E=200e9, nu=0.3)
    >>> round(johnson_modulus(steel) / 1e9, 3)
    109.89
    """
    return 0.5 * effective_modulus(material1, material2)


#: AISI 52100 through-hardened bearing steel (E and nu as used by Ricci 2009).
BEARING_STEEL = Material(E=200e9, nu=0.3, density=7850.0, name="bearing steel (AISI 52100)")
#: Hot-isostatically-pressed silicon nitride for hybrid-bearing balls (typical values).
SILICON_NITRIDE = Material(E=310e9, nu=0.27, density=3200.0, name="silicon nitride (Si3N4)")
