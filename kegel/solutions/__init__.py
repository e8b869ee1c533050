"""Layer 3, the solutions of one operating point: the equations solved, not the bookkeeping.

:mod:`~kegel.solutions.quasi_static` (the load distribution and the friction torque of a
bearing in equilibrium), :mod:`~kegel.solutions.dynamics` (the time integration of the rollers
and cage) and :mod:`~kegel.solutions.steady` (when a signal has settled). A solution takes model
objects and SI numbers and returns a result object; it does not know scenes files, folders or
tables. See docs/architecture.md.
"""
