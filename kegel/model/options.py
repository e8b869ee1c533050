"""The names and limits of the model options a scene may choose.

The scene model (:mod:`kegel.model.scene`) checks a scene's ``[model]`` table against these; the
modules that implement the options (:mod:`kegel.solutions.quasi_static`,
:mod:`kegel.coupling.supply`, :mod:`kegel.physics.tribology`) import them from here and
re-export them, so that the scene, which sits below them, need not import them
(docs/architecture.md: no import runs back up the layers).
"""

from __future__ import annotations

__all__ = ["MAX_SLICES", "ROLLING_THERMAL_MODELS", "SUPPLY_MODELS"]

#: Most slices per roller/raceway contact: the C++ line contact's limit
#: (mbs_core/src/line_contact.cpp, LineContactModel); the scene's ``model.slices`` uses it too.
MAX_SLICES = 400

#: Supply models of a scene's ``model.lubricant_supply``: ``kinematic_replenishment``
#: (:mod:`kegel.coupling.supply`, the default) or ``flooded`` (every raceway contact fully
#: flooded: kegel before it).
SUPPLY_MODELS = ("kinematic_replenishment", "flooded")

#: Thermal reductions of the EHL rolling force (FrictionData.core's rolling_thermal).
ROLLING_THERMAL_MODELS = ("aihara", "zhu_cheng", "off")
