"""Contact models of the roller (SI units)."""

from collections.abc import Sequence
import enum
from typing import Annotated

import numpy
from numpy.typing import NDArray


class RollerProfile:
    """Logarithmic roller crowning plus edge radius."""

    def __init__(self, roller_diameter_m: float, length_m: float, a_p: float, c_p_m: float, d_p_m: float, k_p_m: float, edge_radius_m: float) -> None: ...

    def drop_m(self, x_m: float) -> float:
        """Profile drop at x from the roller middle [m]."""

class SliceMethod(enum.Enum):
    independent = 0

    alternative_slicing = 1

def strip_influence_H(a: float) -> float: ...

class ApproachReference(enum.Enum):
    palmgren = 0

    half_space = 1

REFERENCE_LINE_LOAD_N_M: float = 1000000.0

def depth_displacement(x1_m: float, x2_m: float, depth_m: float, E_reduced_Pa: float, poisson: float = 0.3) -> float:
    """
    Boussinesq displacement at a depth below a slice from a unit line load on [x1, x2] (both bodies).
    """

class LineContactModel:
    """Slices of a roller/raceway line contact."""

    def __init__(self, slices: int, length_m: float, reduced_radius_m: Sequence[float], E_reduced_Pa: float, method: SliceMethod, reference: ApproachReference = ApproachReference.palmgren) -> None: ...

    @property
    def reference_depth_m(self) -> float: ...

    def set_reference_depth(self, depth_m: float) -> None: ...

    @property
    def slices(self) -> int: ...

    @property
    def width_m(self) -> float: ...

    @property
    def length_m(self) -> float: ...

    @property
    def positions_m(self) -> list[float]: ...

class LineContactData:
    """State of a line contact (warm start)."""

    def __init__(self, model: LineContactModel) -> None: ...

    @property
    def line_load_N_m(self) -> list[float]: ...

    @property
    def half_width_m(self) -> list[float]: ...

    @property
    def max_pressure_Pa(self) -> list[float]: ...

    @property
    def force_N(self) -> float: ...

    @property
    def moment_Nm(self) -> float: ...

    @property
    def iterations(self) -> int: ...

def solve_line_contact(model: LineContactModel, data: LineContactData, interference_m: Sequence[float]) -> int:
    """Slice loads for given interferences; 0 = converged."""

def solve_line_contact_load(model: LineContactModel, data: LineContactData, gap_m: Sequence[float], force_N: float) -> float:
    """Approach [m] that carries the force."""

class CellContactModel:
    """Cell grid and influence coefficients."""

    def __init__(self, nx: int, ny: int, dx_m: float, dy_m: float, E_reduced_Pa: float) -> None: ...

    @property
    def nx(self) -> int: ...

    @property
    def ny(self) -> int: ...

class CellContactData:
    """Pressure field (warm start) and workspace."""

    def __init__(self, model: CellContactModel) -> None: ...

    @property
    def pressure_Pa(self) -> list[float]: ...

    @property
    def displacement_m(self) -> list[float]: ...

    @property
    def approach_m(self) -> float: ...

    @property
    def iterations(self) -> int: ...

    @property
    def residual(self) -> float: ...

def solve_cell_contact(model: CellContactModel, data: CellContactData, h0_m: Sequence[float], load_N: float, tolerance: float = 1e-09, max_iterations: int = 2000, warm_start: bool = True) -> int:
    """
    Solve the cell contact in load control; 0 = converged, 1 = iteration limit.
    """

def hertz_point_contact_load(Rx_m: float, Ry_m: float, E_reduced_Pa: float, load_N: float) -> dict: ...

def hertz_point_contact_approach(Rx_m: float, Ry_m: float, E_reduced_Pa: float, approach_m: float) -> dict: ...

class RacewaySide(enum.Enum):
    inner = 0

    outer = 1

def raceway_slice_geometry(mean_radius_m: float, half_angle_rad: float, length_m: float, profile: RollerProfile, p_RM: Annotated[NDArray[numpy.float64], dict(shape=(3), order='C')], a_R: Annotated[NDArray[numpy.float64], dict(shape=(3), order='C')], apex_z_m: float, cone_half_angle_rad: float, side: RacewaySide, xi_m: Sequence[float]) -> dict:
    """Slice contact geometry of a roller against a raceway cone."""

def rib_gap(p_RE: Annotated[NDArray[numpy.float64], dict(shape=(3), order='C')], a_R: Annotated[NDArray[numpy.float64], dict(shape=(3), order='C')], sphere_radius_m: float, cap_radius_m: float, apex_z_m: float, cone_half_angle_rad: float, rib_outer_radius_m: float, nx: int, ny: int, dx_m: float, dy_m: float) -> tuple[float, list[float], Annotated[NDArray[numpy.float64], dict(shape=(3), order='C')], Annotated[NDArray[numpy.float64], dict(shape=(3), order='C')]]:
    """
    Gap between roller end and rib on a cell grid: (min gap, h0, p_RC, n_R).
    """
