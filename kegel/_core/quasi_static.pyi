"""Quasi-static load distribution (SI units)."""

import enum
from typing import Annotated

import numpy
from numpy.typing import NDArray

import kegel._core.contact
import kegel._core.tribology


class BearingModelValues:
    def __init__(self) -> None: ...

    @property
    def roller_count(self) -> int: ...

    @roller_count.setter
    def roller_count(self, arg: int, /) -> None: ...

    @property
    def pitch_radius_m(self) -> float: ...

    @pitch_radius_m.setter
    def pitch_radius_m(self, arg: float, /) -> None: ...

    @property
    def roller_mid_z_m(self) -> float: ...

    @roller_mid_z_m.setter
    def roller_mid_z_m(self, arg: float, /) -> None: ...

    @property
    def roller_axis_angle_rad(self) -> float: ...

    @roller_axis_angle_rad.setter
    def roller_axis_angle_rad(self, arg: float, /) -> None: ...

    @property
    def apex_z_m(self) -> float: ...

    @apex_z_m.setter
    def apex_z_m(self, arg: float, /) -> None: ...

    @property
    def cup_angle_rad(self) -> float: ...

    @cup_angle_rad.setter
    def cup_angle_rad(self, arg: float, /) -> None: ...

    @property
    def cone_angle_rad(self) -> float: ...

    @cone_angle_rad.setter
    def cone_angle_rad(self, arg: float, /) -> None: ...

    @property
    def roller_mean_radius_m(self) -> float: ...

    @roller_mean_radius_m.setter
    def roller_mean_radius_m(self, arg: float, /) -> None: ...

    @property
    def roller_half_angle_rad(self) -> float: ...

    @roller_half_angle_rad.setter
    def roller_half_angle_rad(self, arg: float, /) -> None: ...

    @property
    def roller_length_m(self) -> float: ...

    @roller_length_m.setter
    def roller_length_m(self, arg: float, /) -> None: ...

    @property
    def roller_mass_kg(self) -> float: ...

    @roller_mass_kg.setter
    def roller_mass_kg(self, arg: float, /) -> None: ...

    @property
    def cage_pocket_clearance_m(self) -> float: ...

    @cage_pocket_clearance_m.setter
    def cage_pocket_clearance_m(self, arg: float, /) -> None: ...

    @property
    def E_reduced_Pa(self) -> float: ...

    @E_reduced_Pa.setter
    def E_reduced_Pa(self, arg: float, /) -> None: ...

    @property
    def rib_apex_z_m(self) -> float: ...

    @rib_apex_z_m.setter
    def rib_apex_z_m(self, arg: float, /) -> None: ...

    @property
    def rib_half_angle_rad(self) -> float: ...

    @rib_half_angle_rad.setter
    def rib_half_angle_rad(self, arg: float, /) -> None: ...

    @property
    def rib_outer_radius_m(self) -> float: ...

    @rib_outer_radius_m.setter
    def rib_outer_radius_m(self, arg: float, /) -> None: ...

    @property
    def end_sphere_radius_m(self) -> float: ...

    @end_sphere_radius_m.setter
    def end_sphere_radius_m(self, arg: float, /) -> None: ...

    @property
    def end_cap_radius_m(self) -> float: ...

    @end_cap_radius_m.setter
    def end_cap_radius_m(self, arg: float, /) -> None: ...

    @property
    def end_sphere_offset_m(self) -> float: ...

    @end_sphere_offset_m.setter
    def end_sphere_offset_m(self, arg: float, /) -> None: ...

    @property
    def slices(self) -> int: ...

    @slices.setter
    def slices(self, arg: int, /) -> None: ...

    @property
    def method(self) -> kegel._core.contact.SliceMethod: ...

    @method.setter
    def method(self, arg: kegel._core.contact.SliceMethod, /) -> None: ...

    def set_profile(self, roller_diameter_m: float, length_m: float, a_p: float, c_p_m: float, d_p_m: float, k_p_m: float, edge_radius_m: float) -> None: ...

class BearingModel:
    def __init__(self, values: BearingModelValues) -> None: ...

    @property
    def rib_Rx_m(self) -> float: ...

    @property
    def rib_Ry_m(self) -> float: ...

class BearingLoads:
    def __init__(self) -> None: ...

    @property
    def axial_N(self) -> float: ...

    @axial_N.setter
    def axial_N(self, arg: float, /) -> None: ...

    @property
    def radial_N(self) -> float: ...

    @radial_N.setter
    def radial_N(self, arg: float, /) -> None: ...

    @property
    def tilt_moment_Nm(self) -> float: ...

    @tilt_moment_Nm.setter
    def tilt_moment_Nm(self, arg: float, /) -> None: ...

    @property
    def misalignment_x_rad(self) -> float: ...

    @misalignment_x_rad.setter
    def misalignment_x_rad(self, arg: float, /) -> None: ...

    @property
    def misalignment_y_rad(self) -> float: ...

    @misalignment_y_rad.setter
    def misalignment_y_rad(self, arg: float, /) -> None: ...

    @property
    def tilt_free(self) -> bool: ...

    @tilt_free.setter
    def tilt_free(self, arg: bool, /) -> None: ...

    @property
    def axial_offset_controlled(self) -> bool: ...

    @axial_offset_controlled.setter
    def axial_offset_controlled(self, arg: bool, /) -> None: ...

    @property
    def axial_offset_m(self) -> float: ...

    @axial_offset_m.setter
    def axial_offset_m(self, arg: float, /) -> None: ...

    @property
    def cage_speed_rad_s(self) -> float: ...

    @cage_speed_rad_s.setter
    def cage_speed_rad_s(self, arg: float, /) -> None: ...

class RollerState:
    @property
    def u_m(self) -> float: ...

    @property
    def w_m(self) -> float: ...

    @property
    def tilt_rad(self) -> float: ...

    @property
    def outer_N(self) -> float: ...

    @property
    def inner_N(self) -> float: ...

    @property
    def rib_N(self) -> float: ...

    @property
    def residual(self) -> float: ...

class BearingData:
    def __init__(self, model: BearingModel) -> None: ...

    @property
    def ring(self) -> Annotated[NDArray[numpy.float64], dict(shape=(None,), order='C')]: ...

    @property
    def rollers(self) -> list[RollerState]: ...

    @property
    def residual(self) -> float: ...

    @property
    def reaction_moment_Nm(self) -> Annotated[NDArray[numpy.float64], dict(shape=(2), order='C')]: ...

    @property
    def axial_force_N(self) -> float: ...

    @property
    def iterations(self) -> int: ...

def loaded_lengths_m(model: BearingModel, data: BearingData) -> Annotated[NDArray[numpy.float64], dict(shape=(None, None), order='F')]:
    """
    Loaded length [m] of each roller's line contacts at a solved load distribution: the widths of the slices that carry load, one row per roller, columns (inner, outer).
    """

def solve_load_distribution(model: BearingModel, data: BearingData, loads: BearingLoads) -> int:
    """Solve the load distribution; 0 = converged."""

class CageModel(enum.Enum):
    off = 0

    pocket = 1

    free_rollers = 2

    walls = 3

class RibPressure(enum.Enum):
    hertz = 0

    solved = 1

def evaluate_bearing_friction(model: BearingModel, data: BearingData, loads: BearingLoads, inner_speed_rad_s: float, lubricant_state: kegel._core.tribology.ContactLubricantState, friction: kegel._core.tribology.FrictionParameters, raceway: kegel._core.tribology.SurfacePair, rib: kegel._core.tribology.SurfacePair, rib_cells: int = 0, cage: CageModel = CageModel.free_rollers, outer_lubricant_state: kegel._core.tribology.ContactLubricantState | None = None, inner_lubricant_state: kegel._core.tribology.ContactLubricantState | None = None, rib_pressure: RibPressure = RibPressure.hertz) -> dict:
    """
    Friction of the whole bearing at the solved load distribution (rib_cells > 0: rib cell model, its pressure field as rib_pressure says: Hertz's ellipse unless an edge cuts it, or solved for every roller). outer_lubricant_state / inner_lubricant_state (default: lubricant_state): the lubricant state of the outer ring's contacts and of the inner ring's (its raceway and the rib), for a contact temperature per ring.
    """
