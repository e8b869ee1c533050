"""Layer 2, the physics of the contacts: thin wrappers over the compiled core ``kegel._core``.

:mod:`~kegel.physics.tribology` (the friction laws of the raceway and rib contacts, the friction
data files) and :mod:`~kegel.physics.contact` (the cell contact model of one raceway contact).
The hydraulic losses (:mod:`kegel.correlations`) and the oil flow couplings
(:mod:`kegel.coupling`) are the other packages of this layer. Imports only the model and base
layers. See docs/architecture.md.
"""
