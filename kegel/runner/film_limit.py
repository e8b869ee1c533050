"""The contact friction of one operating point with the contact / hydraulic boundary at a film
height: the contact half of the CFD gap study (``benchmarks/cfd_gap_study.py``).

It runs a scene, so it sits in the runner layer; the supply model it exercises is
:mod:`kegel.coupling.supply` (docs/architecture.md).
"""

from __future__ import annotations

import math
from typing import Any

from ..base.errors import KegelInputError
from ..model.scene import scene_from_dict
from .run import run_scene

__all__ = ["contact_loss_at_film_limit"]


def contact_loss_at_film_limit(film_limit_m: float, *, bearing: str = "32208", speed: str = "2000 rpm",
                               axial_load: str = "1 kN", temperature: str = "50 degC", lubricant: str = "FVA3",
                               oil_level: str = "flooded", fidelity: str = "default") -> dict[str, Any]:
    """The contact friction of one operating point with the contact / hydraulic boundary at film
    height ``film_limit_m`` (``model.contact_film_limit``): the contact half of the CFD gap study
    (contact loss + CFD loss against ``1/sqrt(g)``).

    The point is solved as ``kegel run`` solves a scene (quasi-static, oil bath at ``oil_level``
    with the supply model, no hydraulic loss); ``film_limit_m = 0`` gives the uncut contact.

    Returns
    -------
    dict
        ``friction_torque_Nm`` (the drive torque of the contacts), ``ehl_rolling_torque_Nm`` (its
        Biboulet-Houpert part), ``torque_by_mechanism_Nm``, ``torque_by_contact_Nm``,
        ``contact_film_limit_m``, ``lubricant_supply``, ``converged``.
    """

    if not (math.isfinite(film_limit_m) and film_limit_m >= 0.0):
        raise KegelInputError("<argument>", "film_limit_m", film_limit_m, "a film height >= 0 in m (0: no cut-off)")
    model: dict[str, Any] = {"fidelity": fidelity, "hydraulic": "none"}
    if film_limit_m > 0.0:
        model["contact_film_limit"] = f"{film_limit_m * 1e3!r} mm"
    raw = {"bearing": {"designation": bearing}, "lubricant": {"name": lubricant},
           "operating": {"axial_load": axial_load, "speed": speed, "temperature": temperature},
           "lubrication": {"mode": "oil_bath", "oil_level": oil_level}, "model": model}
    scene = scene_from_dict(raw)
    p = run_scene(scene, progress=False, write=False).points[0]
    return {"contact_film_limit_m": film_limit_m, "friction_torque_Nm": p["friction_torque_Nm"],
            "ehl_rolling_torque_Nm": (p.get("torque_by_mechanism_Nm") or {}).get("ehl_rolling"),
            "torque_by_mechanism_Nm": p.get("torque_by_mechanism_Nm"),
            "torque_by_contact_Nm": p.get("torque_by_contact_Nm"),
            "lubricant_supply": p.get("lubricant_supply"), "converged": p.get("converged")}
