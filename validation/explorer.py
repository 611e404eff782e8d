"""Moved to :mod:`ballrace.teach`, split by concern: :mod:`~ballrace.teach.compute` (the
numbers), :mod:`~ballrace.teach.page` (the page and its export), :mod:`~ballrace.teach.server`
(the HTTP server and its request checks) and :mod:`~ballrace.teach.commands` (``ballrace
teach serve`` and ``export``).  This path stays importable: it re-exports their public
names (the same objects).  A name monkeypatched here is not seen by the modules that use it;
patch it in the module that defines it.
"""
# the public names of the module before the split, importable from here as they were
from ballrace.teach.commands import SMALL_GRID, register_commands  # noqa: F401
from ballrace.teach.compute import (DEFAULTS, EXPORT_GRID, FIELDS, TRACTION_MAX,  # noqa: F401
                                    InputError, case_inputs, compute, compute_safe,
                                    export_grid, export_params, unpack)
from ballrace.teach.page import export_html, page
from ballrace.teach.server import (MAX_BODY, MAX_CASE_BYTES, MAX_QUERY, MAX_TEXT,  # noqa: F401
                                   RequestError, check_request, check_text, make_server,
                                   resolve_case)

__all__ = ["FIELDS", "DEFAULTS", "compute", "case_inputs", "export_html", "export_grid",
           "make_server", "page", "register_commands", "EXPORT_GRID"]
