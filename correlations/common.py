"""The common interface of the hydraulic-loss correlations."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

__all__ = ["HydraulicTorques", "immersed_fraction"]


@dataclass(frozen=True)
class HydraulicTorques:
    """Hydraulic (drag and churning) torques of a bearing, by body and component [N m].

    Attributes
    ----------
    correlation
        Name of the correlation.
    inner_ring_Nm
        Torque resisting the inner ring's rotation.
    outer_ring_Nm
        Torque the oil exerts on the (fixed) outer ring.
    cage_Nm
        Torque resisting the cage and roller set's rotation.
    components
        The correlation's own components, by name.
    """

    correlation: str
    inner_ring_Nm: float
    outer_ring_Nm: float
    cage_Nm: float
    components: dict[str, float] = field(default_factory=dict)

    @property
    def total_Nm(self) -> float:
        """Sum of the components: the hydraulic share of the measured bearing torque."""
        return float(sum(self.components.values()))

    def as_dict(self) -> dict[str, object]:
        """JSON-ready dictionary (field names carry units)."""
        return {**asdict(self), "total_Nm": self.total_Nm}


def immersed_fraction(level_above_centre_m: float, radius_m: float) -> float:
    """Fraction of a horizontal-axis circle's circumference below an oil surface.

    Parameters
    ----------
    level_above_centre_m
        Height of the oil surface above the circle's centre (negative: below it).
    radius_m
        Radius of the circle.

    Returns
    -------
    float
        0 when the surface lies below the circle, 1 when above it, arccos(-h/r)/pi between.
    """
    if radius_m <= 0.0:
        raise ValueError(f"radius_m = {radius_m}: expected a value > 0")
    c = -level_above_centre_m / radius_m
    if c >= 1.0:
        return 0.0
    if c <= -1.0:
        return 1.0
    return math.acos(c) / math.pi
