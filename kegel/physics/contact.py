"""Contact models of a tapered roller bearing built from its data (seed paper, Section 2.1.1).

The models live in the C++ core (``kegel._core.contact``); this module builds them from a
bearing's derived geometry: the roller profile, the raceway cones, the rib cone and the roller's
large-end sphere, in the ring frame R (z = bearing axis, x radial through the roller, origin on
the axis at the cup back face, as ``kegel.geometry``'s frame B with x -> z).

* :class:`RacewayContact`: roller slices against the inner or outer raceway, independent slices
  (Palmgren) or the alternative slicing technique (half-space coupling).
* :class:`RibContact`: roller large end against the inner-ring rib, as a cell model (FFT + CG)
  or a closed-form elliptic Hertz contact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _core
from ..model.data import BearingData, MaterialData
from ..base.errors import KegelInputError
from ..model.geometry import BearingGeometry

C = _core.contact

__all__ = [
    "RacewayContact",
    "RibContact",
    "nominal_roller_pose",
    "roller_profile",
    "palmgren_approach_m",
]


def palmgren_approach_m(load_N: float, length_m: float) -> float:
    """Palmgren's approach of a roller/raceway line contact, 3.84e-5 Q^0.9 / l^0.8 (N, mm)."""
    return 3.84e-5 * load_N**0.9 / (length_m * 1e3) ** 0.8 * 1e-3


def roller_profile(bearing: BearingData, *, crowned: bool = True, edge: bool = True) -> "C.RollerProfile":
    """The roller profile of a bearing (``crowned=False`` or ``edge=False`` drop the crown or
    the edge radius, for studies of unprofiled rollers)."""
    return C.RollerProfile(
        roller_diameter_m=bearing.roller_mean_diameter_m,
        length_m=bearing.roller_length_m,
        a_p=bearing.profile_a_p if crowned else 0.0,
        c_p_m=bearing.profile_c_p_m,
        d_p_m=bearing.profile_d_p_m,
        k_p_m=bearing.profile_k_p_m,
        edge_radius_m=bearing.edge_radius_m if edge else 0.0,
    )


def nominal_roller_pose(g: BearingGeometry, azimuth_rad: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Mid-point ``p_RM`` and axis ``a_R`` (small -> large end) of the roller at an azimuth, in
    the apex-matched nominal position where it touches both raceways."""
    c, s = math.cos(azimuth_rad), math.sin(azimuth_rad)
    r = 0.5 * g.pitch_diameter_m
    p = np.array([r * c, r * s, g.roller_mid_x_m])
    b = g.roller_axis_angle_rad
    a = np.array([math.sin(b) * c, math.sin(b) * s, math.cos(b)])
    return p, a


@dataclass
class RacewayContact:
    """Slices of one roller/raceway contact.

    Parameters
    ----------
    geometry, bearing, material
        The bearing's derived geometry and data.
    side
        ``"inner"`` (cone) or ``"outer"`` (cup).
    slices
        Number of slices over the roller's effective length.
    method
        ``"alternative_slicing"`` (AST, default) or ``"independent"``.
    crowned, edge
        Use the roller's crown and edge radius (``False`` for unprofiled studies).
    reference
        What the AST approach is measured against: ``"palmgren"`` (default; a finite-body
        reference depth set so that a flat roller follows Palmgren's approach at 1000 N/mm, the
        level of the independent slices) or ``"half_space"`` (points at infinite depth).
    """

    geometry: BearingGeometry
    bearing: BearingData
    material: MaterialData
    side: str = "inner"
    slices: int = 30
    method: str = "alternative_slicing"
    crowned: bool = True
    edge: bool = True
    reference: str = "palmgren"

    def __post_init__(self) -> None:
        if self.side not in ("inner", "outer"):
            raise KegelInputError("<argument>", "side", self.side, "'inner' or 'outer'")
        if self.method not in ("alternative_slicing", "independent"):
            raise KegelInputError("<argument>", "method", self.method, "'alternative_slicing' or 'independent'")
        if self.reference not in ("palmgren", "half_space"):
            raise KegelInputError("<argument>", "reference", self.reference, "'palmgren' or 'half_space'")
        if not (isinstance(self.slices, int) and 1 <= self.slices <= 400):
            raise KegelInputError("<argument>", "slices", self.slices, "an integer in [1, 400]")
        g = self.geometry
        self.profile = roller_profile(self.bearing, crowned=self.crowned, edge=self.edge)
        self.E_reduced_Pa = _core.reduced_modulus_Pa(self.material.core, self.material.core)
        self._side = C.RacewaySide.inner if self.side == "inner" else C.RacewaySide.outer
        self._cone = (g.apex_x_m, g.cone_angle_rad if self.side == "inner" else g.cup_angle_rad)
        # slices over the whole roller length: the edge radius and the crown decide where the
        # contact ends; the nominal reduced radii come from the nominal pose
        length = g.roller_length_m
        x = (np.arange(self.slices) + 0.5) / self.slices * length - 0.5 * length
        self.xi_m = x
        nominal = self.slice_geometry(*nominal_roller_pose(g))
        method = C.SliceMethod.alternative_slicing if self.method == "alternative_slicing" else C.SliceMethod.independent
        self.model = C.LineContactModel(self.slices, length, list(nominal["reduced_radius_m"]), self.E_reduced_Pa,
                                        method, getattr(C.ApproachReference, self.reference))
        self.data = C.LineContactData(self.model)

    def slice_geometry(self, p_RM: np.ndarray, a_R: np.ndarray) -> dict[str, np.ndarray]:
        """Contact point, normal, tangents, interference and reduced radius of every slice for a
        roller pose in the ring frame."""
        g = self.geometry
        d = C.raceway_slice_geometry(
            0.5 * g.roller_mean_diameter_m, g.roller_half_angle_rad, g.roller_length_m, self.profile,
            np.asarray(p_RM, float), np.asarray(a_R, float), self._cone[0], self._cone[1], self._side,
            list(self.xi_m),
        )
        return {k: np.asarray(v) for k, v in d.items()}

    def solve_pose(self, p_RM: np.ndarray, a_R: np.ndarray) -> dict[str, np.ndarray | float]:
        """Slice loads for a roller pose (displacement control)."""
        geo = self.slice_geometry(p_RM, a_R)
        status = C.solve_line_contact(self.model, self.data, list(geo["interference_m"]))
        if status != 0:
            raise RuntimeError(f"{self.side} raceway contact: the slice solver did not converge (status {status})")
        return {**geo, **self._result()}

    def solve_load(self, force_N: float, tilt_rad: float = 0.0) -> dict[str, np.ndarray | float]:
        """Slice loads and approach for a contact force, with the roller tilted in its axial
        plane by ``tilt_rad`` relative to the raceway (load control)."""
        p, a = nominal_roller_pose(self.geometry)
        e_theta = np.array([0.0, 1.0, 0.0])
        a_t = _rotate(a, e_theta, tilt_rad)
        geo = self.slice_geometry(p, a_t)
        gap = -geo["interference_m"]
        approach = C.solve_line_contact_load(self.model, self.data, list(gap), force_N)
        return {**geo, **self._result(), "approach_m": approach}

    def _result(self) -> dict[str, np.ndarray | float]:
        d = self.data
        return {
            "xi_m": self.xi_m,
            "line_load_N_m": np.asarray(d.line_load_N_m),
            "max_pressure_Pa": np.asarray(d.max_pressure_Pa),
            "half_width_m": np.asarray(d.half_width_m),
            "force_N": d.force_N,
            "moment_Nm": d.moment_Nm,
        }


def _rotate(v: np.ndarray, axis: np.ndarray, angle: float) -> np.ndarray:
    axis = axis / np.linalg.norm(axis)
    return (v * math.cos(angle) + np.cross(axis, v) * math.sin(angle)
            + axis * np.dot(axis, v) * (1 - math.cos(angle)))


@dataclass
class RibContact:
    """Roller large end against the inner-ring rib.

    Parameters
    ----------
    geometry, bearing, material
        The bearing's derived geometry and data.
    cells
        Cells per side of the contact window (cell model).
    window_over_hertz
        Window size as a multiple of the Hertz contact's semi-axes at the reference load.
    reference_load_N
        Load that sizes the window (the rib load of the operating point, roughly).
    """

    geometry: BearingGeometry
    bearing: BearingData
    material: MaterialData
    cells: int = 32
    window_over_hertz: float = 3.0
    reference_load_N: float = 100.0

    def __post_init__(self) -> None:
        g = self.geometry
        if not (isinstance(self.cells, int) and 4 <= self.cells <= 512):
            raise KegelInputError("<argument>", "cells", self.cells, "an integer in [4, 512]")
        if not (self.reference_load_N > 0 and math.isfinite(self.reference_load_N)):
            raise KegelInputError("<argument>", "reference_load_N", self.reference_load_N, "a positive load in N")
        self.E_reduced_Pa = _core.reduced_modulus_Pa(self.material.core, self.material.core)
        phi = g.rib_face_angle_to_radial_plane_rad  # rib normal (roller -> rib) to the bearing axis
        x_p, r_p = g.rib_contact_point_m
        self.cone_half_angle_rad = 0.5 * math.pi + phi  # the rib cone opens towards the small end
        self.apex_z_m = x_p + r_p * math.tan(phi)
        self.cap_radius_m = 0.5 * g.roller_large_end_diameter_m - self.bearing.edge_radius_m
        self.rib_outer_radius_m = g.rib_top_point_m[1]
        # principal relative radii from the gap on a small stencil at the nominal pose
        d = 1e-4
        _, st, _, _ = self._gap(*self.nominal_end(), 3, 3, d, d)
        st = np.asarray(st).reshape(3, 3)
        self.Rx_m = d * d / (st[0, 1] + st[2, 1] - 2 * st[1, 1])  # along the rib generator
        self.Ry_m = d * d / (st[1, 0] + st[1, 2] - 2 * st[1, 1])  # circumferential
        hz = C.hertz_point_contact_load(self.Rx_m, self.Ry_m, self.E_reduced_Pa, self.reference_load_N)
        semi_x = hz["semi_minor_m"] if self.Rx_m <= self.Ry_m else hz["semi_major_m"]
        semi_y = hz["semi_major_m"] if self.Rx_m <= self.Ry_m else hz["semi_minor_m"]
        self.dx_m = 2 * self.window_over_hertz * semi_x / self.cells
        self.dy_m = 2 * self.window_over_hertz * semi_y / self.cells
        self.model = C.CellContactModel(self.cells, self.cells, self.dx_m, self.dy_m, self.E_reduced_Pa)
        self.data = C.CellContactData(self.model)

    def nominal_end(self) -> tuple[np.ndarray, np.ndarray]:
        """Sphere centre and roller axis of the nominal roller at azimuth 0 (frame R)."""
        g = self.geometry
        p, a = nominal_roller_pose(g)
        return p + (0.5 * g.roller_length_m - g.roller_end_radius_m) * a, a

    def _gap(self, p_RE, a_R, nx, ny, dx, dy):
        return C.rib_gap(np.asarray(p_RE, float), np.asarray(a_R, float), self.geometry.roller_end_radius_m,
                         self.cap_radius_m, self.apex_z_m, self.cone_half_angle_rad, self.rib_outer_radius_m,
                         nx, ny, dx, dy)

    def solve_load(self, load_N: float, model: str = "cell") -> dict[str, float | np.ndarray]:
        """Contact for a rib load at the nominal pose: ``model="cell"`` (FFT + CG on the exact
        gap) or ``"hertz"`` (closed-form ellipse from the principal relative radii)."""
        if model == "hertz":
            return C.hertz_point_contact_load(self.Rx_m, self.Ry_m, self.E_reduced_Pa, load_N)
        if model != "cell":
            raise KegelInputError("<argument>", "model", model, "'cell' or 'hertz'")
        _, h0, _, _ = self._gap(*self.nominal_end(), self.cells, self.cells, self.dx_m, self.dy_m)
        status = C.solve_cell_contact(self.model, self.data, h0, load_N)
        if status != 0:
            raise RuntimeError(f"rib cell contact did not converge (status {status})")
        p = np.asarray(self.data.pressure_Pa).reshape(self.cells, self.cells)
        return {
            "load_N": load_N,
            "approach_m": self.data.approach_m,
            "max_pressure_Pa": float(p.max()),
            "contact_area_m2": float((p > 0).sum() * self.dx_m * self.dy_m),
            "pressure_Pa": p,
            "iterations": self.data.iterations,
        }
