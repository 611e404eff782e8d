"""Registry of *calculations*: named Python functions that map SI inputs to SI outputs.

A case file names one calculation (``calculation = "hertz.point_contact"``); the
registry tells the case loader which inputs the calculation takes (and their pint
dimensionality, so unit strings are checked when the file is loaded), which outputs
it returns (so expected values are checked too), which library modules it needs
(so a missing module is reported as an ERROR at run time, never a silent pass), and
whether it is a finite-element calculation (skippable with ``--fem none``).

Calculations live in the ``calc_*`` modules of this package and register themselves
with :func:`calculation`; they import the library lazily, inside the function body,
so registering never fails because another area has not landed yet.

Examples
--------
>>> from ballrace.validation import registry
>>> calc = registry.get("hertz.point_contact")
>>> calc.area, calc.fem
('hertz', False)
>>> sorted(calc.outputs)[:3]
['E_prime', 'Rx', 'Ry']
>>> registry.get("hertz.nope")
Traceback (most recent call last):
...
KeyError: "unknown calculation 'hertz.nope'; registered in area 'hertz': hertz.approximation_error, ..."
"""
from __future__ import annotations

import importlib
import logging
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

__all__ = ["Param", "Calculation", "calculation", "get", "all_calculations", "ModuleMissing",
           "check_available"]

log = logging.getLogger(__name__)

#: Modules that define calculations (imported on first registry access).
CALC_MODULES = (
    "ballrace.validation.calc_hertz",
    "ballrace.validation.calc_subsurface",
    "ballrace.validation.calc_bearing",
    "ballrace.validation.calc_life",
    "ballrace.validation.calc_ehl",
    "ballrace.validation.calc_kinematics",
    "ballrace.validation.calc_shaft",
    "ballrace.validation.calc_roller",
    "ballrace.validation.calc_roller_published",
    "ballrace.validation.calc_fem",
    "ballrace.validation.calc_fem_roller",
)

_REQUIRED = object()


@dataclass(frozen=True)
class Param:
    """One input of a calculation (frozen).

    Attributes
    ----------
    dimension : str
        pint dimensionality (``"[length]"``, ``"[force]"``, ``"[angle]"`` ...), ``""`` for a
        dimensionless number, ``"str"`` for a text choice, ``"list"`` for a list of
        dimensionless numbers.
    default : Any
        Default SI value; omitted means the input is required.
    allow_inf : bool
        Accept ``"inf"`` (flat surfaces).
    choices : tuple
        Allowed values of a ``"str"`` input.
    """

    dimension: str
    default: Any = _REQUIRED
    allow_inf: bool = False
    choices: tuple = ()

    @property
    def required(self) -> bool:
        return self.default is _REQUIRED


@dataclass(frozen=True)
class Calculation:
    """A registered calculation (frozen).

    Attributes
    ----------
    name : str
        ``"<area>.<what>"``, the name used in case files.
    func : callable
        ``func(**si_inputs) -> dict[str, float]``.
    area : str
        Report section (hertz, subsurface, bearing, life, ehl, kinematics, highspeed, fem).
    inputs : mapping of str to Param
    outputs : mapping of str to str
        Output name -> pint dimensionality (``""`` dimensionless, ``"[angle]"`` in rad).
    requires : tuple of str
        ``"module"`` or ``"module:attribute"`` that must import for the calculation to run.
    fem : bool
        True for finite-element calculations (``--fem none`` skips them).
    distributed : bool
        Run through dask (FE solves); analytic calculations run in-process.
    doc : str
        First line of the function docstring.
    """

    name: str
    func: Callable[..., dict]
    area: str
    inputs: Mapping[str, Param]
    outputs: Mapping[str, str]
    requires: tuple = ()
    fem: bool = False
    distributed: bool = False
    doc: str = ""


class ModuleMissing(RuntimeError):
    """A library module (or attribute) a calculation needs is not available."""


_REGISTRY: dict[str, Calculation] = {}
_LOADED = False


def calculation(name: str, *, inputs: Mapping[str, Param], outputs: Mapping[str, str],
                requires=(), fem: bool = False, distributed: bool | None = None):
    """Decorator registering ``func`` as calculation ``name`` (area = text before the dot)."""
    area = name.split(".", 1)[0]

    def deco(func):
        if name in _REGISTRY and _REGISTRY[name].func is not func:
            raise ValueError(f"calculation {name!r} registered twice")
        _REGISTRY[name] = Calculation(
            name=name, func=func, area=area, inputs=dict(inputs), outputs=dict(outputs),
            requires=tuple(requires), fem=fem,
            distributed=fem if distributed is None else distributed,
            doc=(func.__doc__ or "").strip().splitlines()[0] if func.__doc__ else "")
        return func

    return deco


def _load() -> None:
    global _LOADED
    if _LOADED:
        return
    for mod in CALC_MODULES:
        importlib.import_module(mod)
    _LOADED = True


def all_calculations() -> dict[str, Calculation]:
    """All registered calculations by name."""
    _load()
    return dict(_REGISTRY)


def get(name: str) -> Calculation:
    """The calculation called ``name``; ``KeyError`` listing the close names when unknown."""
    _load()
    try:
        return _REGISTRY[name]
    except KeyError:
        area = name.split(".", 1)[0]
        same = sorted(n for n in _REGISTRY if n.startswith(area + "."))
        hint = (f"; registered in area {area!r}: {', '.join(same[:1])}, ..." if same else
                f"; known areas: {', '.join(sorted({c.area for c in _REGISTRY.values()}))}")
        raise KeyError(f"unknown calculation {name!r}{hint}") from None


def check_available(calc: Calculation) -> None:
    """Raise :class:`ModuleMissing` naming the first required module/attribute that is absent."""
    for req in calc.requires:
        mod_name, _, attr = req.partition(":")
        try:
            mod = importlib.import_module(mod_name)
        except ImportError as exc:
            raise ModuleMissing(f"{calc.name} needs {mod_name}, which is not available "
                                f"({type(exc).__name__}: {exc})") from None
        obj = mod
        for part in filter(None, attr.split(".")):
            if not hasattr(obj, part):
                raise ModuleMissing(f"{calc.name} needs {mod_name}:{attr}, which "
                                    f"{mod_name} does not define") from None
            obj = getattr(obj, part)
