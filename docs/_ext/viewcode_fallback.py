"""Source-code pages for modules that Sphinx's own parser cannot tag.

``sphinx.ext.viewcode`` tags the functions and classes of a module with
``sphinx.pycode.ModuleAnalyzer``; for a few modules that parser fails (Sphinx 9:
"zip() argument 2 is longer than argument 1"), viewcode then leaves the module out but
still lists it in ``_modules/index.html`` — a broken link.  This handler of
``viewcode-find-source`` answers for exactly those modules with tags from the standard
``ast`` module (top-level functions and classes and their methods), so every listed
module gets its page.  Modules Sphinx can parse are left to Sphinx.
"""
from __future__ import annotations

import ast


def _tags(source: str) -> dict[str, tuple[str, int, int]]:
    tags = {}
    for node in ast.parse(source).body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            tags[node.name] = ("def", node.lineno, node.end_lineno)
        elif isinstance(node, ast.ClassDef):
            tags[node.name] = ("class", node.lineno, node.end_lineno)
            for sub in node.body:
                if isinstance(sub, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    tags[f"{node.name}.{sub.name}"] = ("def", sub.lineno, sub.end_lineno)
    return tags


def find_source(app, modname: str):
    from sphinx.pycode import ModuleAnalyzer

    try:
        ModuleAnalyzer.for_module(modname).find_tags()
        return None                      # Sphinx handles it
    except Exception:  # noqa: BLE001 - any parser failure: fall back to ast
        pass
    try:
        _filename, source = ModuleAnalyzer.get_module_source(modname)
        return source, _tags(source)
    except Exception:  # noqa: BLE001 - no source at all: let viewcode skip it
        return None


def setup(app):
    app.connect("viewcode-find-source", find_source)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
