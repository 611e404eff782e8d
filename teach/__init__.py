"""ballrace.teach — teaching: figures and the subsurface-stress explorer, drawn from the library.

* :mod:`~ballrace.teach.figures` — ``ballrace teach subsurface``: the stress fields under a
  contact as a PNG (with ``--traction``: with and without a tangential traction);
* :mod:`~ballrace.teach.compute` — the explorer's numbers: what its page plots, sampled from
  :mod:`ballrace.analytic` (no HTML), for a ball and for a profiled roller (roller mode,
  ``ballrace teach roller``);
* :mod:`~ballrace.teach.page` — the explorer's page and its self-contained export;
* :mod:`~ballrace.teach.server` — the local HTTP server and its request checks;
* :mod:`~ballrace.teach.commands` — the ``ballrace teach`` commands.

See ``docs/explorer.md``.
"""
