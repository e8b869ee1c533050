"""Layer 1, the model: one object per concept, and the loaders that build them.

:mod:`~kegel.model.data` (bearing, lubricant and material records from the shipped TOML files or
boundary dimensions; :mod:`~kegel.model.estimate` estimates the internal geometry),
:mod:`~kegel.model.geometry` (the derived bearing geometry), :mod:`~kegel.model.lubricant` (the
oil at a temperature), :mod:`~kegel.model.options` (the names and limits of the model options a
scene may choose), :mod:`~kegel.model.scene` (the scene: bearing, oil, operating points,
fidelity; loaded from a file, a dictionary or ``--set``) and :mod:`~kegel.model.inventory`
(``kegel list`` / ``kegel init``). Imports only :mod:`kegel.base` and ``kegel._core``.
See docs/architecture.md.
"""
