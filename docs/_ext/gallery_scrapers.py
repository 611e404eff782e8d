"""Image scrapers of the gallery (importable, so Sphinx can pickle the configuration).

:class:`PyVistaScraper` is pyvista's own scraper, except that it first forgets plotters
that library code has already closed after writing its own PNG (``ballrace.fem.render``
does exactly that; the gallery shows those PNGs with matplotlib).  pyvista keeps closed
plotters registered while ``BUILDING_GALLERY`` is set and would fail to screenshot them.
"""
from __future__ import annotations


class PyVistaScraper:
    """pyvista's sphinx-gallery scraper, skipping plotters closed without an image."""

    def __call__(self, block, block_vars, gallery_conf):
        import pyvista as pv
        from pyvista.plotting import plotter as _plotter

        for key, p in list(_plotter._ALL_PLOTTERS.items()):
            if getattr(p, "render_window", None) is None and getattr(p, "last_image", None) is None:
                _plotter._ALL_PLOTTERS.pop(key, None)
        return pv.Scraper()(block, block_vars, gallery_conf)

    def __repr__(self) -> str:          # stable, so a rebuild does not see a changed config
        return "PyVistaScraper"
