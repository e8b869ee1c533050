"""Layer 5, the runner: a scene in, its solved points, tables and figures out.

:mod:`~kegel.runner.run` (``run_scene``: one record per operating point, written into the run
folder), :mod:`~kegel.runner.parallel` (worker processes and Dask), :mod:`~kegel.runner.uncertainty`
(the band of a point), :mod:`~kegel.runner.film_limit` (the contact loss at a film cut-off) and
:mod:`~kegel.runner.validation` (``kegel validate``). The CFD case runner :mod:`kegel.cfd_cases`
is the other package of this layer. See docs/architecture.md.
"""
