"""Studies: lubrications x hydraulic-loss methods at every operating point of a scene.

A scene with a ``[study]`` table (see :mod:`kegel.scene`) solves the contact friction once per
operating point and adds, for each lubrication (oil levels, minimum quantity) and each method
(Liebrecht, SKF drag, kegel CFD), the hydraulic loss and the total. :func:`study_rows` gives a
point's rows, :func:`study_csv` the long table (one row per point x lubrication x method) and
:func:`study_plot` the overlay plot (total torque against the swept quantity, a colour per
lubrication, a line style per method, the friction alone as the floor; the hydraulic losses alone
in a second panel, log scale).

CFD losses between computed speeds are interpolated (power law) with a stated error; a speed
outside the computed ones is not extrapolated: its row is ``missing`` and names the ``kegel cfd
run`` command that computes it.
"""

from __future__ import annotations

import csv
import io
import math
import shlex
from pathlib import Path
from typing import Any

from ..correlations import hydraulic_torques
from ..model.lubricant import lubricant_state
from .point_warnings import Warning_, liebrecht_warning

__all__ = ["case_name", "read_study_cfd", "study_csv", "study_plot", "study_rows", "STUDY_FILES"]

#: The summary files a study adds to a run.
STUDY_FILES = ("study.csv", "study.png")

_METHOD_LABEL = {"none": "no oil bath", "liebrecht": "Liebrecht", "skf": "SKF drag", "cfd": "CFD"}
#: The raceway contacts' inlet supply in each study row (``supply_`` + key; :mod:`kegel.supply`).
_SUPPLY_KEYS = ("inlet_gap_ratio_inner", "inlet_gap_ratio_outer", "rolling_force_factor_inner",
                "rolling_force_factor_outer")


def read_study_cfd(scene: Any) -> list[tuple[Path, dict[str, Any]]]:
    """The CFD results a study's ``cfd_results`` holds (empty when it names nothing yet)."""
    from ..coupling import cfd_result_files, read_cfd_results

    st = scene.study
    if st is None or "cfd" not in st.methods or not cfd_result_files(st.cfd_results):
        return []
    return read_cfd_results(st.cfd_results, source=scene.source, key="study.cfd_results")


def case_name(lub: Any) -> str:
    """A study lubrication's name: ``minimum_quantity`` or the oil level as written."""
    return "minimum_quantity" if lub.mode == "minimum_quantity" else lub.oil_level_as_written


_case_name = case_name


def _cfd_command(scene: Any, point: dict[str, Any], lub: Any) -> str:
    level = lub.oil_level_as_written
    out = f"{scene.study.cfd_results}/{scene.bearing.designation}_{point['speed_rpm']:.0f}rpm_{level}"
    args = ["kegel", "cfd", "run", "--bearing", scene.bearing.designation, "--lubricant", scene.lubricant.name,
            "--temperature", f"{point['temperature_degC']:g} degC", "--speed", f"{point['speed_rpm']:.0f} rpm",
            "--oil-level", level, "--output", out]
    return " ".join(shlex.quote(a) for a in args)


def study_rows(scene: Any, point: dict[str, Any], cfd_runs: list[tuple[Path, dict[str, Any]]]) -> list[dict[str, Any]]:
    """The study rows of one operating point's record (``friction_torque_Nm``, speeds,
    temperature, ``cage_speed_rpm``; per lubrication its contact friction and inlet supply in
    ``study_friction`` when the run solved them): per lubrication and method the contact friction,
    the raceway contacts' supply, the hydraulic loss at the shaft and the total, with the method's
    warnings.

    The minimum-quantity case has no oil bath: one row, method ``none``, hydraulic loss 0.
    """
    from ..coupling import cfd_loss_at
    from ..coupling.cfd_results import is_unbalanced, unbalanced_reason

    st = scene.study
    g = scene.geometry
    friction = float(point["friction_torque_Nm"])
    w = float(point["speed_rad_s"])
    T = float(point["temperature_K"])
    state = lubricant_state(scene.lubricant, T, source=scene.source, key="operating.temperature")
    wc = float(point.get("cage_speed_rpm", 0.0)) * math.pi / 30 or None
    D = scene.bearing.outer_diameter_m
    rows: list[dict[str, Any]] = []
    per_case = point.get("study_friction") or {}
    for lub in st.cases:
        case = per_case.get(_case_name(lub)) or {}
        sup = case.get("lubricant_supply") or {}
        friction = float(case.get("friction_torque_Nm", point["friction_torque_Nm"]))
        base = {"lubrication": _case_name(lub), "mode": lub.mode,
                "oil_level_m": lub.oil_level_m if lub.mode == "oil_bath" else None,
                "friction_torque_Nm": friction,
                **{f"supply_{k}": sup.get(k) for k in _SUPPLY_KEYS}}
        if lub.mode == "minimum_quantity":
            rows.append({**base, "method": "none", "status": "no oil bath", "hydraulic_torque_Nm": 0.0,
                         "total_torque_Nm": friction, "error_rel": None, "note": "", "warnings": []})
            continue
        flooded = lub.oil_level_m >= D
        for m in st.methods:
            warns: list[Warning_] = []
            cut_failed = False  # the CFD row's contact, cut at the gap, did not converge
            row: dict[str, Any] = {**base, "method": m, "error_rel": None, "note": ""}
            if m in ("liebrecht", "skf"):
                h = hydraulic_torques(m, g, state, shaft_speed_rad_s=w, oil_level_m=lub.oil_level_m,
                                      cage_speed_rad_s=wc if m == "liebrecht" else None)
                row.update(status="correlation", hydraulic_torque_Nm=h.total_Nm, components=h.as_dict())
                if m == "liebrecht":
                    lw = liebrecht_warning(scene.bearing.designation, flooded)
                    if lw:
                        warns.append(lw)
                else:
                    warns.append(Warning_("skf_constants_to_verify", "the SKF drag moment uses the V_M diagram "
                                          "digitisation and constants marked verify (kegel.correlations.skf)"))
            else:
                c = cfd_loss_at(cfd_runs, bearing=scene.bearing.designation, lubricant=scene.lubricant.name,
                                speed_rad_s=w, temperature_K=T, oil_level_m=lub.oil_level_m, flooded=flooded)
                loss = c["hydraulic_Nm"]
                row.update(status=c["status"], note=c["note"], error_rel=c["error_rel"], files=c["files"],
                           meshes=c["meshes"], cfd_wall_time_s=c["wall_time_s"], gap_ratio=c["gap_ratio"],
                           cfd_Nm=c["loss_torque_at_shaft_Nm"], thin_films_Nm=c["thin_films_Nm"],
                           hydraulic_torque_Nm=None if loss is None else math.copysign(loss, w))
                if c["gap_ratio"] is not None and c["status"] != "missing":
                    # real rollers: the contact owns the oil within the CFD's gap g, so this row's
                    # contact friction is the one cut there (solved by the run), the hydraulic loss
                    # the CFD beyond g plus the analytic thin films
                    if case.get("friction_cut_at_g_Nm") is not None:
                        row.update(friction_torque_Nm=float(case["friction_cut_at_g_Nm"]),
                                   contact_film_limit_m=case.get("contact_film_limit_m"))
                        # less the CFD's far field on the unloaded stretch of the lines, which
                        # the contact convention does not count (kegel.coupling.split)
                        wedge = float(case.get("unloaded_line_wedge_Nm") or 0.0)
                        if loss is not None and wedge:
                            loss -= wedge
                            row.update(unloaded_line_wedge_Nm=wedge, hydraulic_torque_Nm=math.copysign(loss, w))
                        if case.get("friction_cut_at_g_converged") is False:
                            cut_failed = True
                            warns.append(Warning_("not_converged", f"the contact friction cut at the CFD's gap for "
                                                  f"{row['lubrication']} did not converge: the CFD row has no total"))
                    else:
                        warns.append(Warning_("cfd_contact_uncut", f"the CFD row of {row['lubrication']} adds the "
                                              "CFD beyond its gap g to a contact friction that was not cut at g "
                                              "(a dynamic study): it counts the oil within g twice"))
                elif c["status"] != "missing":
                    warns.append(Warning_("cfd_old_geometry", f"the CFD result(s) for {row['lubrication']} are of "
                                          "the old geometry (rollers shrunk by 0.08 D_w): no contact / CFD boundary, "
                                          "their level is set by that gap (docs/cfd.md)"))
                if c["status"] == "missing":
                    row["command"] = _cfd_command(scene, point, lub)
                    warns.append(Warning_("cfd_missing", f"no CFD loss for {row['lubrication']} at "
                                          f"{point['speed_rpm']:.0f} rpm (computed: "
                                          f"{', '.join(f'{s:.0f}' for s in c['computed_speeds_rpm']) or 'none'} rpm); "
                                          f"compute it with: {row['command']}"))
                elif c["status"] == "interpolated":
                    warns.append(Warning_("cfd_interpolated", f"CFD loss for {row['lubrication']} at "
                                          f"{point['speed_rpm']:.0f} rpm {c['note']}"))
                if c["steady"] is False:
                    warns.append(Warning_("cfd_not_steady", f"a CFD result used for {row['lubrication']} did not "
                                          "reach a steady loss torque"))
                if is_unbalanced(c["balance"]):
                    warns.append(Warning_("cfd_unbalanced", f"a CFD result used for {row['lubrication']} at "
                                          f"{point['speed_rpm']:.0f} rpm: {unbalanced_reason(c['balance'])}"))
            hyd = row.get("hydraulic_torque_Nm")
            row["total_torque_Nm"] = None if hyd is None or cut_failed else row["friction_torque_Nm"] + hyd
            row["warnings"] = [x.as_dict() for x in warns]
            rows.append(row)
    return rows


_CSV_COLUMNS = ("index", "speed_rpm", "temperature_degC", "axial_load_N", "axial_offset_m", "radial_load_N",
                "lubrication", "oil_level_m", "method", "status", "friction_torque_Nm",
                *(f"supply_{k}" for k in _SUPPLY_KEYS), "contact_film_limit_m", "hydraulic_torque_Nm", "cfd_Nm",
                "thin_films_Nm", "unloaded_line_wedge_Nm", "total_torque_Nm", "error_rel", "converged", "note",
                "command", "warnings")


def study_csv(points: list[dict[str, Any]]) -> str:
    """The long table: one row per operating point x lubrication x method (empty cells: no value)."""
    buf = io.StringIO()
    w = csv.writer(buf)
    w.writerow(_CSV_COLUMNS)
    for p in points:
        for r in p.get("study") or ():
            merged = {**p, **r, "converged": p.get("converged"),
                      "warnings": "; ".join(x["code"] for x in r.get("warnings", ()))}
            w.writerow(["" if merged.get(c) is None else merged.get(c) for c in _CSV_COLUMNS])
    return buf.getvalue()


_LINESTYLE = {"none": "-", "liebrecht": "-", "skf": "--", "cfd": ":"}
_MARKER = {"none": "s", "liebrecht": "o", "skf": "^", "cfd": "D"}


def _study_x_and_series(meta: dict[str, Any]) -> tuple[Any, list[Any]]:
    """The study plot's x axis and the other swept quantities (one line per value of each), by
    the run plots' rule: x is the first swept quantity other than the temperature, else the
    temperature, else (a single point) the shaft speed."""
    from .plots import AXES, x_and_series

    xname, series = x_and_series(meta.get("swept", []))
    return AXES[xname], [AXES[s] for s in series]


def _shade(colour: Any, i: int, n: int) -> Any:
    """The ``i``-th of ``n`` shades of a colour (the darkest first): one per value of the
    quantities a study sweeps besides its x axis."""
    if n <= 1:
        return colour
    f = 0.55 * i / (n - 1)
    return tuple(c + (1.0 - c) * f for c in colour[:3])


def study_plot(points: list[dict[str, Any]], meta: dict[str, Any], path: Path) -> str:
    """The study's overlay plot (see the module docstring), written atomically; returns its path.

    ``meta``: ``title``, ``swept`` (the swept quantities, keys of :data:`kegel.plots.AXES`, the
    x axis's first) and ``cases`` (the lubrication names in the scene's order). Each line is one
    lubrication x method at one value of every swept quantity besides x (its label names them),
    sorted by x; a single operating point stands at its value with limits around it.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..base.io import atomic_save
    from .plots import _style_x

    xaxis, series = _study_x_and_series(meta)

    def combo(p: dict[str, Any]) -> tuple[float | None, ...]:
        return tuple(None if a.value(p) is None else float(f"{a.value(p):.9g}") for a in series)

    pts = sorted(points, key=lambda p: (combo(p), xaxis.value(p) or 0.0))
    combos = sorted({combo(p) for p in pts}, key=lambda t: tuple((v is None, v or 0.0) for v in t))
    cases = list(meta["cases"])
    colours = {c: plt.get_cmap("tab10")(i % 10) for i, c in enumerate(cases)}
    fig, (ax, ax2, ax3) = plt.subplots(1, 3, figsize=(17, 4.8), gridspec_kw={"width_ratios": (1.0, 1.0, 0.7)})
    all_x = [xaxis.value(p) for p in pts]

    for ci, k in enumerate(combos):
        in_combo = [p for p in pts if combo(p) == k]
        # the values of the other swept quantities, named in each label of this combination
        suffix = "".join(f", {a.label(v)}" for a, v in zip(series, k) if v is not None)
        if "minimum_quantity" not in cases:  # else its line is the friction alone
            lab = "contact friction (kegel)" + suffix
            ax.plot([xaxis.value(p) for p in in_combo], [p["friction_torque_Nm"] for p in in_combo],
                    color=_shade((0.0, 0.0, 0.0), ci, len(combos)), lw=2.5, alpha=0.35, label=lab)
        keys: list[tuple[str, str]] = []
        for p in in_combo:
            for r in p.get("study") or ():
                if (r["lubrication"], r["method"]) not in keys:
                    keys.append((r["lubrication"], r["method"]))
        for case in dict.fromkeys(c for c, _ in keys):
            # the raceway contacts' inlet supply of this lubrication: Biboulet-Houpert's rolling
            # force factor of the inner (solid) and outer (dashed) raceway (kegel.supply)
            sx, fi, fo = [], [], []
            for p in in_combo:
                r = next((r for r in p.get("study") or () if r["lubrication"] == case), None)
                if r is None or r.get("supply_rolling_force_factor_inner") is None:
                    continue
                sx.append(xaxis.value(p))
                fi.append(r["supply_rolling_force_factor_inner"])
                fo.append(r["supply_rolling_force_factor_outer"])
            if sx:
                colour = _shade(colours[case], ci, len(combos))
                ax3.plot(sx, fi, ls="-", marker="o", ms=4, color=colour, label=f"{case.replace('_', ' ')}: inner" + suffix)
                ax3.plot(sx, fo, ls="--", marker="s", ms=4, color=colour, label=f"{case.replace('_', ' ')}: outer" + suffix)
        for case, m in keys:
            xs_, tot, hyd, err, interp = [], [], [], [], []
            for p in in_combo:
                r = next((r for r in p.get("study") or () if r["lubrication"] == case and r["method"] == m), None)
                if r is None or r.get("total_torque_Nm") is None:
                    continue
                xs_.append(xaxis.value(p))
                tot.append(r["total_torque_Nm"])
                hyd.append(abs(r["hydraulic_torque_Nm"]))
                err.append((r.get("error_rel") or 0.0) * abs(r["hydraulic_torque_Nm"]))
                interp.append(r.get("status") == "interpolated")
            if not xs_:
                continue
            label = f"{case.replace('_', ' ')}: {_METHOD_LABEL[m]}" + suffix
            colour = _shade(colours[case], ci, len(combos))
            ax.plot(xs_, tot, ls=_LINESTYLE[m], marker=_MARKER[m], color=colour, label=label, ms=5)
            if m != "none":
                ax2.errorbar(xs_, [h * 1e3 for h in hyd], yerr=[e * 1e3 for e in err], ls=_LINESTYLE[m],
                             marker=_MARKER[m], color=colour, label=label, ms=5, capsize=3)
                if any(interp):
                    ax2.plot([a for a, i in zip(xs_, interp) if i], [h * 1e3 for h, i in zip(hyd, interp) if i],
                             ls="none", marker=_MARKER[m], mfc="white", mec=colour, ms=7)
    for a in (ax, ax2, ax3):
        _style_x(a, all_x)
    ax3.set_xlabel(xaxis.axis_label)
    ax3.set_ylabel("rolling-force factor of the oil supply [-]")
    ax3.set_ylim(0.0, 1.05)
    ax3.set_title("raceway contacts' oil supply (1: flooded; kegel.supply)", fontsize=9)
    if ax3.lines:
        ax3.legend(fontsize=7)
    ax.set_xlabel(xaxis.axis_label)
    ax.set_ylabel("total torque at the shaft [N m]")
    ax.set_title("friction + hydraulic loss", fontsize=9)
    ax.legend(fontsize=7)
    ax2.set_xlabel(xaxis.axis_label)
    ax2.set_ylabel("hydraulic loss torque [N mm]")
    if ax2.lines:
        from matplotlib.ticker import LogFormatter

        ax2.set_yscale("log")
        ax2.yaxis.set_major_formatter(LogFormatter(labelOnlyBase=False))
        ax2.yaxis.set_minor_formatter(LogFormatter(labelOnlyBase=False, minor_thresholds=(2, 0.5)))
        ax2.legend(fontsize=7)
    missing = sorted({f"{r['lubrication'].replace('_', ' ')} {p['speed_rpm']:.0f}" for p in pts
                      for r in p.get("study") or () if r.get("status") == "missing"})
    if missing:
        ax2.text(0.01, 0.01, "CFD not computed (rpm): " + ", ".join(missing[:8]) + (" ..." if len(missing) > 8 else "")
                 + "\nstudy.csv names the command for each", transform=ax2.transAxes, fontsize=6, va="bottom")
    ax2.set_title("hydraulic losses alone (hollow: CFD interpolated, bars: its stated error)", fontsize=9)
    fig.suptitle(meta["title"], fontsize=9)
    fig.tight_layout()
    try:
        atomic_save(path, lambda tmp: fig.savefig(tmp, dpi=110))
    finally:
        plt.close(fig)
    return str(path)
