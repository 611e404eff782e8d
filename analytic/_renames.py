"""Renamed public names: old keywords, properties and functions that keep working.

A name that changed stays usable for a while as an alias that gives the same result and
emits a ``DeprecationWarning`` naming its replacement (the decided names and the aliases are
listed in docs/naming.md).  Giving both the old and the new keyword is a ``TypeError``.
"""
import functools
import inspect
import warnings

__all__ = ["renamed_keywords", "deprecated_property", "deprecated_function"]


def _message(old: str, new: str, where: str) -> str:
    return (f"{where}{old} is deprecated and will be removed in a future release; "
            f"use {new} instead (same value)")


def renamed_keywords(**renames):
    """Decorator: keywords ``old=new`` of the wrapped function keep working under their old
    names, with a DeprecationWarning naming the new keyword; both given is a TypeError.

    The wrapped function's signature (``inspect.signature``) is the new one.
    """
    def wrap(func):
        sig = inspect.signature(func)
        for new in renames.values():
            if new not in sig.parameters:
                raise AssertionError(f"{func.__qualname__} has no parameter {new!r}")

        @functools.wraps(func)
        def wrapper(*args, **kwargs):
            if kwargs.keys() & renames.keys():
                bound = None
                for old, new in renames.items():
                    if old not in kwargs:
                        continue
                    if new in kwargs:
                        raise TypeError(f"{func.__name__}() got both {old!r} (deprecated) and "
                                        f"{new!r}; give only {new!r}")
                    if bound is None:
                        bound = sig.bind_partial(*args).arguments
                    if new in bound:
                        raise TypeError(f"{func.__name__}() got {new!r} as a positional "
                                        f"argument and {old!r} (deprecated) as a keyword; "
                                        f"give only {new!r}")
                    warnings.warn(_message(f"keyword {old!r}", f"{new!r}",
                                           f"{func.__name__}(): "),
                                  DeprecationWarning, stacklevel=2)
                    kwargs[new] = kwargs.pop(old)
            return func(*args, **kwargs)

        return wrapper
    return wrap


def deprecated_property(old: str, new: str, owner: str) -> property:
    """A read-only property ``owner.old`` giving ``getattr(self, new)`` with a
    DeprecationWarning naming ``owner.new``."""
    def get(self):
        warnings.warn(_message(f"{owner}.{old}", f"{owner}.{new}", ""),
                      DeprecationWarning, stacklevel=2)
        return getattr(self, new)
    get.__name__ = old
    get.__doc__ = f"Deprecated alias of :attr:`{new}` (same value; DeprecationWarning)."
    return property(get)


def deprecated_function(func, old: str, where: str):
    """``func`` under its old name ``old`` (in ``where``), with a DeprecationWarning."""
    @functools.wraps(func)
    def alias(*args, **kwargs):
        warnings.warn(_message(f"{where}.{old}", f"{where}.{func.__name__}", ""),
                      DeprecationWarning, stacklevel=2)
        return func(*args, **kwargs)
    alias.__name__ = alias.__qualname__ = old
    alias.__doc__ = (f"Deprecated alias of :func:`{func.__name__}` (same arguments and "
                     "result; DeprecationWarning).")
    return alias
