"""Renamed public names: old keywords, properties and functions that keep working.

A name that changed stays usable for a while as an alias that gives the same result and
emits a ``DeprecationWarning`` naming its replacement (the decided names and the aliases are
listed in docs/naming.md).  Giving both the old and the new keyword is a ``TypeError``.
"""
import functools
import inspect
import warnings

__all__ = ["renamed_keywords", "warn_renamed"]


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


def warn_renamed(old: str, new: str, stacklevel: int = 3) -> None:
    """DeprecationWarning: ``old`` is now ``new``; attributed to the caller of the function
    (or property getter) that calls this (``stacklevel=3``)."""
    warnings.warn(_message(old, new, ""), DeprecationWarning, stacklevel=stacklevel)
