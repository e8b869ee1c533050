"""Uncertainty of a point's friction torque from the inputs that set the roller's loaded length.

The EHL rolling force, the largest part of kegel's friction torque in full-film lubrication,
acts only where the roller touches its raceway (Biboulet and Houpert's force per unit length,
nearly independent of the load in the EHL regime, times the touching length). How much of the
roller touches comes from two things kegel cannot take from a measurement:

1. **The crown (profile) data.** The seed paper (Wingertszahn et al. 2023, Table 4 and A2) gives
   the logarithmic profile's parameters ``a_p, c_p, d_p, k_p`` without a tolerance, and no source
   found gives one for these rollers. The crown drop scales with ``a_p`` (``drop = a_p D_w
   ln(1/(1 - u^2))``, ``mbs_core/include/kegel/core/line_contact.hpp``), so kegel perturbs the
   drop by ``a_p (1 -+ f)`` with ``f = 0.25`` by default (:data:`CROWN_DROP_FRACTION`, an
   assumed spread: a quarter of the drop, about 2-4 um at the roller ends of the 32216, the size
   of a grinding tolerance of a crown; it is a choice, not a sourced value).
2. **The slice model.** kegel's default couples the slices through the elastic half-space
   (``alternative_slicing``); independent slices (``independent``, a model variant available
   in the code, ``model.slice_model``) put load on more slices near the loaded ends and gave
   friction torques 8-10 % higher (32216, Table 1 and 2, docs/validation.md). The point is solved
   once more with the other slice model.

The band of a point is the smallest and the largest friction torque of the nominal solution and
these variants (three extra quasi-static solves per point); the hydraulic loss is not perturbed,
so the total's band is the friction band plus the point's hydraulic loss. It is a sensitivity,
not a confidence interval: other inputs (friction parameters marked ``verify``, the contact
temperature) are not varied. The nominal solution's loaded length of the most loaded inner
raceway contact is reported beside each variant's (the line-contact solver of the slice model at
that contact's load, 100 slices).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..base.errors import KegelInputError

if TYPE_CHECKING:  # pragma: no cover
    from ..model.scene import Fidelity, Scene

__all__ = ["CROWN_DROP_FRACTION", "SLICE_MODELS", "UncertaintyOptions", "loaded_length_m", "point_uncertainty"]

#: Default relative perturbation of the crown drop (a_p), both ways: assumed (no source gives a
#: tolerance of the seed's profile data).
CROWN_DROP_FRACTION = 0.25
#: The slice models of ``model.slice_model``; the variant is the one the point was not solved with.
SLICE_MODELS = ("alternative_slicing", "independent")


@dataclass(frozen=True)
class UncertaintyOptions:
    """What :func:`point_uncertainty` perturbs.

    Attributes
    ----------
    crown_drop_fraction
        Relative change of the crown drop ``a_p``, applied as ``1 - f`` and ``1 + f``
        (0 <= f < 1; 0: the crown variants reproduce the nominal point).
    slice_model_variant
        Solve the point once more with the other slice model.
    """

    crown_drop_fraction: float = CROWN_DROP_FRACTION
    slice_model_variant: bool = True

    def __post_init__(self) -> None:
        f = self.crown_drop_fraction
        if isinstance(f, bool) or not isinstance(f, (int, float)) or not (math.isfinite(f) and 0.0 <= f < 1.0):
            raise KegelInputError("<argument>", "uncertainty.crown_drop_fraction", f, "a number in [0, 1)")
        if not isinstance(self.slice_model_variant, bool):
            raise KegelInputError("<argument>", "uncertainty.slice_model_variant", self.slice_model_variant,
                                  "true or false")

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready record of the perturbed inputs (with where each comes from)."""
        return {"crown_drop_fraction": self.crown_drop_fraction,
                "crown_drop_source": "assumed (no tolerance of the profile data found); kegel.uncertainty",
                "slice_model_variant": self.slice_model_variant}


def loaded_length_m(bearing, geometry, material, load_N: float, *, slices: int = 100,
                    method: str = "alternative_slicing") -> float:
    """Touching length of the roller on the inner raceway under ``load_N``: the line-contact
    solver of kegel's slice model (``kegel._core.contact``) with the bearing's roller profile and
    the reduced radius at the roller's mid-length; the sum of the slices that carry load.

    Parameters
    ----------
    bearing, geometry, material
        :class:`kegel.BearingData` (its profile), its derived geometry and the material.
    load_N
        Normal load of the contact (> 0).
    slices, method
        Slices of the line-contact solution and the slice model.
    """
    from .. import _core
    from ..physics.contact import roller_profile

    if not (math.isfinite(load_N) and load_N > 0.0):
        raise KegelInputError("<argument>", "load_N", load_N, "a positive contact load in N")
    C = _core.contact
    g = geometry
    L = bearing.roller_length_m
    rho = 0.5 * g.roller_mean_diameter_m
    r_ring = 0.5 * g.pitch_diameter_m - rho * math.cos(g.roller_axis_angle_rad)
    R_roller = rho / math.cos(g.roller_half_angle_rad)
    R_ring = r_ring / math.cos(g.cone_angle_rad)
    R = R_roller * R_ring / (R_roller + R_ring)
    E = _core.reduced_modulus_Pa(material.core, material.core)
    prof = roller_profile(bearing)
    xs = (np.arange(slices) + 0.5) / slices * L - 0.5 * L
    drop = [prof.drop_m(float(x)) for x in xs]
    sm = C.SliceMethod.alternative_slicing if method == "alternative_slicing" else C.SliceMethod.independent
    model = C.LineContactModel(slices, L, [R] * slices, E, sm)
    data = C.LineContactData(model)
    C.solve_line_contact_load(model, data, drop, float(load_N))
    w = np.asarray(data.line_load_N_m)
    return float(np.count_nonzero(w > 0.0) * L / slices)


def point_uncertainty(scene: "Scene", fid: "Fidelity", op, friction, *, nominal_friction_Nm: float,
                      hydraulic_Nm: float = 0.0, inner_load_N: float | None = None,
                      options: UncertaintyOptions | None = None) -> dict[str, Any]:
    """The friction torque of one quasi-static point at the perturbed inputs, and its band.

    Parameters
    ----------
    scene, fid, op, friction
        The scene, its fidelity, the operating point and the point's friction parameters (with
        its lubricant supply), as :mod:`kegel.run` solved the nominal point.
    nominal_friction_Nm
        The nominal point's friction torque.
    hydraulic_Nm
        The point's hydraulic loss (not perturbed; added to the total's band).
    inner_load_N
        Load of the most loaded inner raceway contact (for the loaded lengths); None: not reported.
    options
        :class:`UncertaintyOptions` (default: crown drop +-25 %, the other slice model).

    Returns
    -------
    dict
        ``friction_torque_low_Nm``, ``friction_torque_high_Nm``, ``total_torque_low_Nm``,
        ``total_torque_high_Nm``, ``band_relative`` (low and high over the nominal, minus 1),
        ``variants`` (per variant: what changed, its friction torque, converged, loaded length),
        ``inputs`` (:meth:`UncertaintyOptions.as_dict`) and ``nominal_loaded_length_m``. A variant
        that does not converge is reported and left out of the band (``note`` says so).
    """
    from .run import _quasi_static_point

    opts = options or UncertaintyOptions()
    b0 = scene.bearing
    variants: list[tuple[str, str, Any, Any]] = []
    f = opts.crown_drop_fraction
    for name, factor in (("crown_drop_low", 1.0 - f), ("crown_drop_high", 1.0 + f)):
        variants.append((name, f"crown drop a_p x {factor:g} ({b0.profile_a_p:g} -> {b0.profile_a_p * factor:g})",
                         dataclasses.replace(b0, profile_a_p=b0.profile_a_p * factor), fid))
    if opts.slice_model_variant:
        other = next(m for m in SLICE_MODELS if m != fid.slice_model)
        variants.append(("slice_model", f"slice model {other} (nominal {fid.slice_model})", b0,
                         dataclasses.replace(fid, slice_model=other)))
    rows: dict[str, dict[str, Any]] = {}
    good = [nominal_friction_Nm]
    for name, what, bearing, vfid in variants:
        vscene = dataclasses.replace(scene, bearing=bearing)
        _, fr = _quasi_static_point(vscene, vfid, op, friction)
        row: dict[str, Any] = {"changed": what, "friction_torque_Nm": fr.drive_torque_Nm,
                               "converged": bool(fr.converged)}
        if inner_load_N is not None:
            row["loaded_length_m"] = loaded_length_m(bearing, scene.geometry, scene.material, inner_load_N,
                                                     method=vfid.slice_model)
        rows[name] = row
        if fr.converged and math.isfinite(fr.drive_torque_Nm):
            good.append(fr.drive_torque_Nm)
    lo, hi = min(good), max(good)
    failed = [n for n, r in rows.items() if not r["converged"]]
    out: dict[str, Any] = {
        "friction_torque_low_Nm": lo, "friction_torque_high_Nm": hi,
        "total_torque_low_Nm": lo + hydraulic_Nm, "total_torque_high_Nm": hi + hydraulic_Nm,
        "band_relative": [lo / nominal_friction_Nm - 1.0, hi / nominal_friction_Nm - 1.0]
        if nominal_friction_Nm else [0.0, 0.0],
        "inputs": opts.as_dict(), "variants": rows,
        "note": ("variants not converged, left out of the band: " + ", ".join(failed)) if failed else "",
    }
    if inner_load_N is not None:
        out["nominal_loaded_length_m"] = loaded_length_m(b0, scene.geometry, scene.material, inner_load_N,
                                                         method=fid.slice_model)
        out["roller_length_m"] = b0.roller_length_m
    return out
