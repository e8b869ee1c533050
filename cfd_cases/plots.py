"""Pictures of CFD results: torque history with the averaging window, oil distribution on a
slice through the bearing, and torque against speed beside the Liebrecht correlation."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from .forces import read_forces

__all__ = ["plot_torque_history", "plot_oil_distribution", "plot_sweep"]


def _save(fig, path: Path) -> Path:
    tmp = path.with_name(f".{path.stem}.tmp.png")
    fig.savefig(tmp, dpi=120)
    tmp.replace(path)
    return path


def plot_torque_history(case: str | Path, window: Sequence[float], path: str | Path, *,
                        steady_solver: bool) -> Path:
    """Axial torque on inner ring, outer ring and cage against time (or iteration)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    case, path = Path(case), Path(path)
    fig, ax = plt.subplots(figsize=(7.5, 4.2), constrained_layout=True)
    late = []
    for name, label in (("inner_ring", "inner ring"), ("outer_ring", "outer ring"), ("cage", "cage")):
        if not (case / "postProcessing" / f"forces_{name}").is_dir():
            continue  # a case without the cage
        f = read_forces(case, f"forces_{name}")
        m = f.moment_total[:, 2] * 1e3
        ax.plot(f.time, m, label=label, lw=1.2)
        late.append(m[f.time >= f.time[0] + 0.05 * (f.time[-1] - f.time[0])])
    # scale to the run after its first 5 % (the start-up spike would flatten everything else)
    vals = np.concatenate(late) if late else np.zeros(1)
    lo, hi = float(min(vals.min(), 0.0)), float(max(vals.max(), 0.0))
    pad = 0.1 * (hi - lo if hi > lo else 1.0)
    ax.set_ylim(lo - pad, hi + pad)
    ax.axvspan(window[0], window[1], color="0.85", label="averaging window", zorder=0)
    ax.set_xlabel("SIMPLE iteration" if steady_solver else "time (s)")
    ax.set_ylabel("torque about the bearing axis (mN m)")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.legend(loc="best", fontsize=8)
    ax.set_title(case.name, fontsize=9)
    _save(fig, path)
    plt.close(fig)
    return path


def plot_oil_distribution(case: str | Path, time_dir: str | Path, z_m: float, path: str | Path,
                          *, housing_radius_m: float, title: str = "", mesh_angle_rad: float = 0.0) -> Path:
    """Oil volume fraction in the cells near the plane ``z = z_m`` (a slice through the rollers);
    ``mesh_angle_rad``: how far a moving mesh has turned about z at that time (its cell centres
    are stored at t = 0)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .foam import read_field

    case, path = Path(case), Path(path)
    c = np.load(case / "cell_centres.npy")
    if mesh_angle_rad:
        from .run import _rotation_z

        c = c @ _rotation_z(mesh_angle_rad).T
    alpha = read_field(Path(time_dir) / "alpha.oil")
    if alpha.size == 1:
        alpha = np.full(len(c), float(alpha[0]))
    dz = 0.04 * housing_radius_m
    sel = np.abs(c[:, 2] - z_m) < dz
    fig, ax = plt.subplots(figsize=(5.6, 5.0), constrained_layout=True)
    sc = ax.scatter(c[sel, 0] * 1e3, c[sel, 1] * 1e3, c=np.clip(alpha[sel], 0, 1), s=4, cmap="YlOrBr",
                    vmin=0, vmax=1, marker="s", linewidths=0)
    fig.colorbar(sc, ax=ax, label="oil volume fraction")
    t = np.linspace(0, 2 * math.pi, 200)
    ax.plot(housing_radius_m * 1e3 * np.cos(t), housing_radius_m * 1e3 * np.sin(t), "k-", lw=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm, up)")
    ax.set_title(title or f"oil at z = {z_m * 1e3:.1f} mm, t = {Path(time_dir).name} s", fontsize=9)
    _save(fig, path)
    plt.close(fig)
    return path


def plot_sweep(rows: list[dict[str, Any]], path: str | Path, *, title: str = "") -> Path:
    """Hydraulic loss torque at the shaft against speed: CFD points and Liebrecht, per oil level."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = Path(path)
    fig, ax = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
    levels = sorted({r["oil_level"] for r in rows})
    for i, lvl in enumerate(levels):
        pts = sorted((r for r in rows if r["oil_level"] == lvl), key=lambda r: r["speed_rpm"])
        n = [p["speed_rpm"] for p in pts]
        color = f"C{i}"
        ax.plot(n, [p["cfd_loss_torque_Nm"] * 1e3 for p in pts], "o-", color=color, label=f"CFD, {lvl}")
        ax.plot(n, [p["liebrecht_total_Nm"] * 1e3 for p in pts], "s--", color=color, mfc="none",
                label=f"Liebrecht, {lvl}")
    ax.set_xlabel("shaft speed (rpm)")
    ax.set_ylabel("hydraulic loss torque (mN m)")
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=9)
    _save(fig, path)
    plt.close(fig)
    return path
