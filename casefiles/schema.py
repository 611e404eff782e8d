"""The sections every case file shares: one definition of their keys and their reading.

The bearing (:mod:`ballrace.casefiles.bearing`), shaft (:mod:`ballrace.casefiles.shaft`)
and FE (:mod:`ballrace.fem.cli`) case files describe a bearing, its materials, its fits
and its operation with the same keys; this module defines those keys once (pydantic v2
models, strict: an unknown key is an error) and reads them into SI once.  A case file
that takes only some keys of a section builds its model with :func:`subset`, so that a
constraint (``n_balls >= 3``, ``0.5 < f_inner``) or a default is written in one place.

The keys, their units and an example of each::

    [bearing]                          # bearing_keys(); a shaft's [bearings.NAME]
    type = "deep-groove"               # or "angular-contact"
    name = "6208"                      # optional
    ball_diameter = "12.7 mm"          # [length]
    n_balls = 9                        # >= 3
    pitch_diameter = "65 mm"           # [length]
    f_inner = 0.52                     # groove radius / ball diameter, > 0.5
    f_outer = 0.52
    diametral_clearance = "15 um"      # [length]; or free_contact_angle = "40 deg"
    nominal_contact_angle = "0 deg"    # [angle], rating angle (see rating_angle)

    [bearing]                          # roller_bearing_keys(): a roller bearing
    type = "cylindrical-roller"        # or "tapered-roller"
    roller_diameter = "13 mm"          # [length]; tapered: at the middle of the roller
    roller_length = "11.8 mm"          # effective length L_we [length]
    n_rollers = 14                     # >= 3
    pitch_diameter = "70.65 mm"        # [length]
    contact_angle = "15 deg"           # tapered only: the cup angle [angle]
    diametral_clearance = "45 um"      # [length]; default 0
    profile = "iso"                    # or "straight", "lundberg", "johns-gohar", a table
                                       # { x = ["0 mm", ...], drop = ["0 um", ...] } or a
                                       # crown { flat_length = "8 mm", crown_radius = "2 m" }
    n_slices = 31                      # odd, >= 5 (lamina model)

    [materials]                        # material_keys(): ball, ring
    ball = { E = "200 GPa", nu = 0.3, density = "7800 kg/m^3", name = "52100" }

    [fits]                             # fits_keys(); a shaft's [seat.fits]
    bore = "25 mm"                     # [length]
    outside_diameter = "62 mm"
    shaft_interference = "12 um"       # diametral; negative = loose
    housing_interference = "0 um"
    shaft_bore = "0 mm"                # hollow shaft (bearing case files)
    housing_diameter = "inf mm"        # outer diameter of the housing wall
    inner_temperature = "50 degC"      # absolute temperatures (parse_temperature)
    outer_temperature = "40 degC"
    reference_temperature = "20 degC"  # where the fits are made
    shaft_expansion = "11.5e-6 1/K"    # [1/temperature]
    housing_expansion = "23e-6 1/K"
    shaft = { E = "210 GPa", nu = 0.3 }     # (bearing case files)
    housing = { E = "70 GPa", nu = 0.33 }

    [oil]                              # oil_keys()
    nu40 = "68 mm^2/s"                 # [length]^2/[time]; "cSt" also accepted
    nu100 = "8.7 mm^2/s"
    temperature = "70 degC"            # or viscosity = "20 mm^2/s" at the operating one
    ep_additives = false

    [operation]                        # operation_keys()
    speed = "4000 rpm"                 # rpm, rev/s or rad/s (parse_speed)
    rotating_ring = "inner"            # or "outer"

pydantic is imported on first use (the models are built by cached functions).
"""
from __future__ import annotations

import functools
from typing import Literal, Optional

__all__ = ["strict", "subset", "bearing_keys", "roller_bearing_keys", "ROLLER_TYPES",
           "material_keys", "materials_keys",
           "fits_keys", "oil_keys", "operation_keys", "read_material", "read_materials",
           "read_operating_clearance", "DENSITY", "EXPANSION"]

#: pint dimensions of the keys read here.
DENSITY = "[mass] / [length] ** 3"
EXPANSION = "1 / [temperature]"
#: The absolute temperatures of a ``[fits]`` table, read with :func:`parse_temperature`.
FIT_TEMPERATURES = ("inner_temperature", "outer_temperature", "reference_temperature")
#: Its thermal expansion coefficients [1/K].
FIT_EXPANSIONS = ("shaft_expansion", "housing_expansion")


@functools.cache
def strict():
    """The base of every case-file model: unknown keys are errors, values frozen."""
    from pydantic import BaseModel, ConfigDict

    class Strict(BaseModel):
        model_config = ConfigDict(extra="forbid", frozen=True)

    return Strict


def subset(model, name: str, keys, base=None):
    """A strict model of ``model``'s fields named in ``keys``, in that order (a case file
    that takes only some keys of a shared section: the others are unknown keys there)."""
    from pydantic import create_model

    fields = {k: (model.model_fields[k].annotation, model.model_fields[k]) for k in keys}
    return create_model(name, __base__=base or strict(), **fields)


@functools.cache
def bearing_keys():
    """Pydantic model of the bearing keys every case file shares (the ``[bearing]`` table
    of a bearing case file, each ``[bearings.NAME]`` table of a shaft case file; the FE
    case file's ``[bearing]`` takes the geometry keys, see :func:`subset`)."""
    from pydantic import Field

    class BearingKeys(strict()):
        type: Literal["deep-groove", "angular-contact"] = "deep-groove"
        name: str = ""
        ball_diameter: str
        n_balls: int = Field(ge=3)
        pitch_diameter: str
        f_inner: float = Field(gt=0.5)
        f_outer: float = Field(gt=0.5)
        diametral_clearance: Optional[str] = None
        free_contact_angle: Optional[str] = None
        nominal_contact_angle: Optional[str] = None

    return BearingKeys


#: The ``[bearing].type`` values of a roller bearing.
ROLLER_TYPES = ("cylindrical-roller", "tapered-roller")


@functools.cache
def roller_bearing_keys():
    """Pydantic model of the ``[bearing]`` table of a roller bearing (``type`` one of
    :data:`ROLLER_TYPES`).  ``profile`` is a name or a table (a profile table or a circular
    crown), read by :func:`ballrace.casefiles.bearing.read_profile`."""
    from typing import Union

    from pydantic import Field

    class RollerBearingKeys(strict()):
        type: Literal["cylindrical-roller", "tapered-roller"]
        name: str = ""
        roller_diameter: str
        roller_length: str
        n_rollers: int = Field(ge=3)
        pitch_diameter: str
        contact_angle: Optional[str] = None
        diametral_clearance: str = "0 m"
        profile: Union[str, dict] = "iso"
        n_slices: Optional[int] = None

    return RollerBearingKeys


@functools.cache
def material_keys():
    """Pydantic model of a material: ``{ E = "200 GPa", nu = 0.3, density, name }``."""
    from pydantic import Field

    class MaterialKeys(strict()):
        E: str
        nu: float = Field(gt=-1.0, lt=0.5)
        density: Optional[str] = None
        name: str = ""

    return MaterialKeys


@functools.cache
def materials_keys(material=None):
    """Pydantic model of a ``[materials]`` table: ``ball`` and ``ring``, each optional
    (``material``: the model of one, default :func:`material_keys`)."""
    M = material or material_keys()

    class MaterialsKeys(strict()):
        ball: Optional[M] = None
        ring: Optional[M] = None

    return MaterialsKeys


@functools.cache
def fits_keys():
    """Pydantic model of a ``[fits]`` table (a shaft seat's takes the keys of
    :data:`SEAT_FITS`: its bore and materials are the shaft's)."""
    M = material_keys()

    class FitsKeys(strict()):
        bore: str
        outside_diameter: str
        shaft_interference: str = "0 m"
        housing_interference: str = "0 m"
        shaft_bore: str = "0 m"
        housing_diameter: str = "inf m"
        inner_temperature: str = "20 degC"
        outer_temperature: str = "20 degC"
        reference_temperature: str = "20 degC"
        shaft_expansion: Optional[str] = None
        housing_expansion: Optional[str] = None
        shaft: Optional[M] = None
        housing: Optional[M] = None

    return FitsKeys


#: The ``[fits]`` keys of a shaft seat (no shaft_bore, shaft or housing material).
SEAT_FITS = ("bore", "outside_diameter", "shaft_interference", "housing_interference",
             "housing_diameter", "inner_temperature", "outer_temperature",
             "reference_temperature", "shaft_expansion", "housing_expansion")


@functools.cache
def oil_keys():
    """Pydantic model of an ``[oil]`` table (ISO 281 viscosity ratio)."""

    class OilKeys(strict()):
        nu40: Optional[str] = None
        nu100: Optional[str] = None
        temperature: Optional[str] = None
        viscosity: Optional[str] = None
        ep_additives: bool = False

    return OilKeys


@functools.cache
def operation_keys():
    """Pydantic model of an ``[operation]`` table: the speed (required) and which ring
    rotates; a shaft case file's adds its temperature changes."""

    class OperationKeys(strict()):
        speed: str
        rotating_ring: Literal["inner", "outer"] = "inner"

    return OperationKeys


def read_material(m, q, where: str, name: str, density: bool = True) -> dict:
    """The :class:`ballrace.Material` keywords of a material table ``m``
    (:func:`material_keys`) at ``where`` (``"[materials.ball]"``), read with the file's
    quantity reader ``q``; ``density`` False leaves a given density unread."""
    kw = dict(E=q(m.E, "[pressure]", f"{where}.E"), nu=m.nu, name=name)
    given = getattr(m, "density", None)          # (a material model without the key)
    if density and given is not None:
        kw["density"] = q(given, DENSITY, f"{where}.density")
    return kw


def read_materials(spec, q, source: str, make, parts=("ball", "ring")) -> dict:
    """``{"ball": Material, "ring": Material}`` of a ``[materials]`` table ``spec``
    (:func:`materials_keys`; a material not given is left out), each built by ``make``
    from its keywords (:func:`read_material`); an error names ``[materials.ball]``.
    ``parts`` are the table's keys (``("roller", "ring")`` for a roller bearing)."""
    from ballrace.errors import CaseFileError

    mats = {}
    for which in parts:
        m = getattr(spec, which)
        if m is not None:
            kw = read_material(m, q, f"[materials.{which}]", m.name or which)
            try:
                mats[which] = make(**kw)
            except (ValueError, TypeError) as exc:
                raise CaseFileError(f"{source}: [materials.{which}]: {exc}") from None
    return mats


def read_operating_clearance(f, brg, q, source: str, where: str, *, shaft_bore,
                             shaft_material=None, housing_material=None,
                             shaft_expansion=None):
    """The :class:`~ballrace.analytic.clearance.OperatingClearance` of a fits table ``f``
    (:func:`fits_keys`) at ``where`` (``"[fits]"``) for the bearing ``brg``.

    ``shaft_bore`` [m], the materials and a default ``shaft_expansion`` [1/K] are the
    caller's (a bearing case file's own keys, a shaft seat's shaft).  Every error is a
    :class:`CaseFileError` naming ``source`` and the key.
    """
    from ballrace.analytic import clearance
    from ballrace.casefiles.bearing import parse_inf, parse_temperature
    from ballrace.errors import CaseFileError

    exp = {k: q(getattr(f, k), EXPANSION, f"{where}.{k}") for k in FIT_EXPANSIONS}
    if exp["shaft_expansion"] is None and shaft_expansion:
        exp["shaft_expansion"] = shaft_expansion
    T = {k: parse_temperature(getattr(f, k), f"{source}: {where}.{k}")
         for k in FIT_TEMPERATURES}
    try:
        return clearance.operating_clearance(
            brg, bore=q(f.bore, "[length]", f"{where}.bore"),
            outside_diameter=q(f.outside_diameter, "[length]", f"{where}.outside_diameter"),
            shaft_interference=q(f.shaft_interference, "[length]",
                                 f"{where}.shaft_interference"),
            housing_interference=q(f.housing_interference, "[length]",
                                   f"{where}.housing_interference"),
            shaft_bore=shaft_bore,
            housing_diameter=parse_inf(q, f.housing_diameter, f"{where}.housing_diameter"),
            shaft_material=shaft_material, housing_material=housing_material, **T, **exp)
    except CaseFileError:
        raise
    except ValueError as exc:
        raise CaseFileError(f"{source}: {where}: {exc}") from None
