"""The plots of ``kegel run`` (issue 20, item 3): right for 1-D and 2-D sweeps and single points.

The findings on the plots before ``kegel.plots`` (``kegel.run._plots`` drew them all):

A. a speed x radial-load sweep drew one zig-zag line and overlapping bars;
B. a single point got an x axis from -0.04 to 0.04 (the point's index);
C. the breakdown showed the first temperature only;
D. the CFD loss was labelled "hydraulic (Liebrecht)";
E. the colours of a contact/mechanism changed between runs;
F. the hydraulic curve sat unreadably on zero;
and, besides them: G. failed points were drawn as good ones; H. the torque was always in N m
with the axis' default formatting (offsets, too many figures); I. temporary PNGs and modes.

Each test names the finding it covers; every one of them fails on the old ``_plots`` (checked
by drawing the old code's figures through the same tests). The tests read the figures' axes,
lines and bars (``kegel.plots.build_figures``), never pixels; most build point records by hand
(the keys of ``kegel.run._quasi_static_record``), two solve real points at fidelity "fast".
"""

from __future__ import annotations

import os
import re
import stat
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import kegel.plots as plots
from kegel.dynamics import CONTACTS, MECHANISMS

# the shares of a synthetic point's friction torque by contact and by mechanism
_CONTACT_SHARE = {"outer_raceway": 0.45, "inner_raceway": 0.45, "rib": 0.10}
_MECH_SHARE = {"ehl_sliding": 0.10, "solid_sliding": 0.05, "ehl_rolling": 0.80, "solid_rolling": 0.03,
               "hysteresis": 0.02}
_Z = 17


def _point(index: int, *, speed_rpm: float = 1000.0, radial_N: float = 0.0, T: float = 50.0,
           friction: float | None = None, hydraulic: float | None = None, converged: bool = True,
           contacts: tuple[str, ...] = CONTACTS, hyd_record: Any = None) -> dict[str, Any]:
    """A point record with the keys of ``kegel.run._quasi_static_record`` that the plots read.
    Default friction grows with speed and falls with load and temperature; hydraulic 1 %."""
    if friction is None:
        friction = 1.0 + speed_rpm / 1000.0 - radial_N / 50_000.0 - (T - 50.0) / 100.0
    if hydraulic is None:
        hydraulic = 0.01 * friction
    w = speed_rpm * np.pi / 30.0
    share = sum(_CONTACT_SHARE[c] for c in contacts)
    power = {c: {k: (friction * w * _CONTACT_SHARE[c] / share * _MECH_SHARE[k] if c in contacts else 0.0)
                 for k in MECHANISMS} for c in CONTACTS}
    psi = 2 * np.pi * np.arange(_Z) / _Z
    inner = 1000.0 + radial_N / 4 * np.maximum(np.cos(psi), 0.0)
    return {
        "index": index, "speed_rpm": speed_rpm, "speed_rad_s": w, "temperature_degC": T,
        "temperature_K": T + 273.15, "axial_load_N": 6000.0, "axial_offset_m": None,
        "radial_load_N": radial_N, "friction_torque_Nm": friction, "hydraulic_torque_Nm": hydraulic,
        "total_torque_Nm": friction + hydraulic,
        "torque_by_contact_Nm": {**{c: sum(power[c].values()) / w for c in CONTACTS}, "cage": 0.0},
        "power_W": power, "cage_slip": -0.001 * (1 + index % 3),
        "roller_azimuth_rad": psi.tolist(), "roller_inner_N": inner.tolist(),
        "roller_outer_N": inner.tolist(), "roller_rib_N": (0.07 * inner).tolist(),
        "hydraulic": hyd_record, "converged": converged, "solved": True,
    }


def _grid(speeds, radials=(0.0,), temps=(50.0,), **kw) -> list[dict[str, Any]]:
    """Points in the scene's order: temperature slowest, then radial load, speed fastest."""
    pts = []
    for T in temps:
        for fr in radials:
            for n in speeds:
                pts.append(_point(len(pts), speed_rpm=n, radial_N=fr, T=T, **kw))
    return pts


def _meta(swept: list[str], hydraulic: str | None = "Liebrecht") -> dict[str, Any]:
    return {"title": "test scene", "bearing": "32216", "lubricant": "FVA3",
            "lubrication": "oil bath, half_roller", "swept": swept, "hydraulic": hydraulic}


def _ylabel_axes(fig, start: str) -> list:
    return [ax for ax in fig.axes if ax.get_ylabel().startswith(start)]


def _lines(ax, start: str) -> list:
    return [ln for ln in ax.get_lines() if ln.get_label().startswith(start)]


def _bars(ax) -> dict[str, Any]:
    """The bar containers of a breakdown panel by their label."""
    return {c.get_label(): c for c in ax.containers}


def _xlabels(fig) -> str:
    """The x labels of a figure (a panel under another shares the lower one's)."""
    return " ".join(ax.get_xlabel() for ax in fig.axes)


def _stack_tops(ax) -> list[float]:
    """The top of each stack of bars of a breakdown panel, left to right."""
    stacks: dict[float, float] = {}
    for c in ax.containers:
        for patch in c.patches:
            assert patch.get_width() > 0
            x = round(patch.get_x() + patch.get_width() / 2, 9)
            stacks[x] = max(stacks.get(x, -np.inf), patch.get_y() + patch.get_height())
    return [stacks[k] for k in sorted(stacks)]


def _all_text(fig) -> str:
    """Every label, title, legend entry and note of a figure."""
    out = []
    for ax in fig.axes:
        out += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
        out += [ln.get_label() for ln in ax.get_lines()] + [c.get_label() for c in ax.containers]
        leg = ax.get_legend()
        if leg is not None:
            out += [t.get_text() for t in leg.get_texts()]
        out += [t.get_text() for t in ax.texts]
    out += [t.get_text() for t in fig.texts]
    if fig._suptitle is not None:
        out.append(fig._suptitle.get_text())
    return "\n".join(out)


# ------------------------------------------------------------------------------------------------


def test_2d_sweep_draws_one_line_per_radial_load_with_monotone_speed():
    """Finding A: 3 speeds x 2 radial loads drew one zig-zag line (radial load on x, both speeds'
    points joined). Now: speed on x, one line per radial load and quantity, each monotone."""
    pts = _grid([500.0, 1000.0, 2000.0], radials=(0.0, 10_000.0))
    figs = plots.build_figures(pts, _meta(["speed", "radial_load"]))
    (ax,) = _ylabel_axes(figs["torque_plot"], "torque")
    assert "rpm" in _xlabels(figs["torque_plot"])
    for quantity in ("total", "friction"):
        lines = _lines(ax, quantity)
        assert len(lines) == 2, [ln.get_label() for ln in ax.get_lines()]
        for ln in lines:
            x = np.asarray(ln.get_xdata(), float)
            assert x.tolist() == [500.0, 1000.0, 2000.0]  # monotone, every speed once
        assert sorted(ln.get_label() for ln in lines) == [f"{quantity}, Fr = 0 kN", f"{quantity}, Fr = 10 kN"]
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("Fr = 10 kN" in t for t in legend) and any("Fr = 0 kN" in t for t in legend)
    # the line at 10 kN holds the points at 10 kN (not a mix)
    (hi,) = [ln for ln in _lines(ax, "total") if "10 kN" in ln.get_label()]
    assert np.allclose(hi.get_ydata(), [p["total_torque_Nm"] for p in pts if p["radial_load_N"] == 10_000.0])


def test_2d_sweep_breakdown_has_a_panel_per_radial_load_without_overlapping_bars():
    """Finding A (bars): the breakdown's bars of both radial loads stood at the same x and
    overlapped. Now one panel per radial load, one stack per speed, the stack's top the total."""
    pts = _grid([500.0, 1000.0, 2000.0], radials=(0.0, 10_000.0))
    fig = plots.build_figures(pts, _meta(["speed", "radial_load"]))["breakdown_plot"]
    panels = _ylabel_axes(fig, "torque")
    assert sorted(ax.get_title() for ax in panels) == ["Fr = 0 kN", "Fr = 10 kN"]
    for ax in panels:
        fr = 10_000.0 if "10 kN" in ax.get_title() else 0.0
        totals = [p["total_torque_Nm"] for p in pts if p["radial_load_N"] == fr]
        tops = _stack_tops(ax)
        assert len(tops) == 3  # one stack per speed, none overlapping another
        assert np.allclose(tops, totals, rtol=1e-9)


def test_single_point_gets_a_sensible_x_axis():
    """Finding B: a single operating point was drawn at x = its index with limits -0.04..0.04.
    Now at its speed in rpm, with limits around it, and its figures written on the panel."""
    pts = [_point(0, speed_rpm=1500.0)]
    figs = plots.build_figures(pts, _meta([]))
    (ax,) = _ylabel_axes(figs["torque_plot"], "torque")
    lo, hi = ax.get_xlim()
    assert "rpm" in _xlabels(figs["torque_plot"])
    assert lo < 1500.0 < hi and hi - lo > 10.0, (lo, hi)
    assert not (abs(lo) < 1 and abs(hi) < 1)
    (slip,) = _ylabel_axes(figs["loads_plot"], "cage slip")
    lo, hi = slip.get_xlim()
    assert lo < 1500.0 < hi and hi - lo > 10.0


def test_breakdown_covers_every_temperature():
    """Finding C: the breakdown showed the first temperature only. Now one panel per
    temperature, each holding that temperature's points."""
    pts = _grid([500.0, 1000.0, 2000.0], temps=(40.0, 50.0, 60.0))
    figs = plots.build_figures(pts, _meta(["speed", "temperature"]))
    panels = _ylabel_axes(figs["breakdown_plot"], "torque")
    assert sorted(ax.get_title() for ax in panels) == ["T = 40 degC", "T = 50 degC", "T = 60 degC"]
    for ax in panels:
        T = float(re.search(r"T = (\d+) degC", ax.get_title()).group(1))
        expect = [p["total_torque_Nm"] for p in pts if p["temperature_degC"] == T]
        assert np.allclose(_stack_tops(ax), expect, rtol=1e-9)
    # and the torque plot: one line per temperature
    (ax,) = _ylabel_axes(figs["torque_plot"], "torque")
    assert sorted(ln.get_label() for ln in _lines(ax, "total")) == [
        "total, T = 40 degC", "total, T = 50 degC", "total, T = 60 degC"]


def test_cfd_hydraulic_loss_is_labelled_cfd():
    """Finding D: the CFD loss was labelled "hydraulic (Liebrecht)". Now the label comes from the
    run's metadata (and the records): "hydraulic (CFD)", never Liebrecht."""
    cfd = {"source": "cfd", "file": "cfd/results.json", "loss_torque_at_shaft_Nm": 0.5}
    pts = [_point(i, speed_rpm=n, friction=1.0, hydraulic=0.5, hyd_record=cfd) for i, n in enumerate((500.0, 1000.0))]
    figs = plots.build_figures(pts, _meta(["speed"], hydraulic="CFD"))
    (ax,) = _ylabel_axes(figs["torque_plot"], "torque")
    assert [ln.get_label() for ln in _lines(ax, "hydraulic")] == ["hydraulic (CFD)"]
    assert "hydraulic (CFD)" in _bars(_ylabel_axes(figs["breakdown_plot"], "torque")[0])
    for fig in figs.values():
        assert "Liebrecht" not in _all_text(fig)
    # without the metadata's word the records' source says CFD as well
    figs = plots.build_figures(pts, _meta(["speed"], hydraulic=None))
    (ax,) = _ylabel_axes(figs["torque_plot"], "torque")
    assert [ln.get_label() for ln in _lines(ax, "hydraulic")] == ["hydraulic (CFD)"]


def _bar_colour(fig, label: str) -> tuple[float, ...]:
    (ax,) = _ylabel_axes(fig, "torque")
    return tuple(_bars(ax)[label].patches[0].get_facecolor())


def test_breakdown_colours_are_fixed_per_contact_and_mechanism():
    """Finding E: the breakdown's colours followed the order of the segments present, so the
    inner raceway's EHL rolling changed colour between runs. Now a fixed palette."""
    from matplotlib.colors import to_rgba

    full = [_point(0, speed_rpm=1000.0)]
    inner_only = [_point(0, speed_rpm=1000.0, contacts=("inner_raceway",))]
    a = plots.build_figures(full, _meta([]))["breakdown_plot"]
    b = plots.build_figures(inner_only, _meta([]))["breakdown_plot"]
    label = "inner raceway: ehl rolling"
    assert label in _bars(_ylabel_axes(b, "torque")[0]) and "outer raceway: ehl rolling" not in _bars(_ylabel_axes(b, "torque")[0])
    assert _bar_colour(a, label) == _bar_colour(b, label)
    assert _bar_colour(a, label) == to_rgba(plots.PALETTE[("inner_raceway", "ehl_rolling")])
    # every contact x mechanism has its own colour
    keys = [(c, k) for c in CONTACTS for k in MECHANISMS]
    assert all(k in plots.PALETTE for k in keys)
    assert len({plots.PALETTE[k] for k in keys}) == len(keys)


def test_failed_points_are_drawn_distinctly_and_not_joined():
    """Finding G: a point that did not converge was drawn (and joined) like a good one. Now it
    is a hollow red marker off the lines, and its breakdown stack is hatched."""
    from matplotlib.colors import to_rgb

    pts = _grid([500.0, 1000.0, 2000.0])
    pts[1]["converged"] = False
    figs = plots.build_figures(pts, _meta(["speed"]))
    (ax,) = _ylabel_axes(figs["torque_plot"], "torque")
    (total,) = _lines(ax, "total")
    assert list(total.get_xdata()) == [500.0, 2000.0]
    failed = [ln for ln in ax.get_lines() if 1000.0 in list(ln.get_xdata())]
    assert failed and all(ln.get_markerfacecolor() == "none" and ln.get_linestyle() == "None" for ln in failed)
    assert all(np.allclose(to_rgb(ln.get_markeredgecolor()), (1, 0, 0)) for ln in failed)
    assert any("not converged" in t.get_text() for t in ax.get_legend().get_texts())
    (bax,) = _ylabel_axes(figs["breakdown_plot"], "torque")
    assert any("not converged" in label for label in _bars(bax))


def test_small_hydraulic_loss_gets_its_own_axis():
    """Finding F: a hydraulic loss of ~1 % of the friction lay on zero in the torque axis. Now it
    has its own panel whose scale shows it."""
    pts = _grid([500.0, 1000.0, 2000.0])  # hydraulic 1 % of friction
    fig = plots.build_figures(pts, _meta(["speed"]))["torque_plot"]
    (tax,) = _ylabel_axes(fig, "torque")
    (hax,) = _ylabel_axes(fig, "hydraulic")
    assert hax is not tax and not _lines(tax, "hydraulic")
    (h,) = _lines(hax, "hydraulic (Liebrecht)")
    assert "N mm" in hax.get_ylabel()  # all below 0.1 N m
    hmax = max(p["hydraulic_torque_Nm"] for p in pts) * 1e3
    assert np.allclose(h.get_ydata(), [p["hydraulic_torque_Nm"] * 1e3 for p in pts])
    assert hax.get_ylim()[1] < 2 * hmax  # fills its panel
    # a hydraulic loss of the friction's size stays with the friction
    big = _grid([500.0, 1000.0], hydraulic=0.8)
    fig = plots.build_figures(big, _meta(["speed"]))["torque_plot"]
    assert not _ylabel_axes(fig, "hydraulic") and _lines(_ylabel_axes(fig, "torque")[0], "hydraulic")


def _sig_figs(label: str) -> int:
    digits = re.sub(r"[^0-9]", "", label).lstrip("0")
    return len(digits)


def test_torque_units_n_mm_below_a_tenth_and_four_figures():
    """Finding H: torques of a few N mm were plotted in N m with the axis' default formatting.
    Now N mm when every torque is below 0.1 N m, N m otherwise; tick labels with at most four
    significant figures and no offset; loads in kN."""
    small = _grid([500.0, 1000.0, 2000.0], friction=0.0123)
    figs = plots.build_figures(small, _meta(["speed"]))
    (ax,) = _ylabel_axes(figs["torque_plot"], "torque")
    assert ax.get_ylabel() == "torque [N mm]"
    assert np.allclose(_lines(ax, "friction")[0].get_ydata(), 12.3)
    assert _ylabel_axes(figs["breakdown_plot"], "torque")[0].get_ylabel() == "torque [N mm]"
    big = _grid([500.0, 1000.0, 2000.0], friction=1234.5678)
    (ax,) = _ylabel_axes(plots.build_figures(big, _meta(["speed"]))["torque_plot"], "torque")
    assert ax.get_ylabel() == "torque [N m]"
    for axis in (ax.yaxis, ax.xaxis):
        fmt = axis.get_major_formatter()
        labels = fmt.format_ticks(axis.get_majorticklocs())
        assert all("e" not in t and _sig_figs(t) <= 4 for t in labels), labels
        assert getattr(fmt, "get_offset", lambda: "")() == ""
    (loads,) = _ylabel_axes(figs["loads_plot"], "roller load")
    assert "kN" in loads.get_ylabel()


def test_many_values_of_the_second_axis_become_panels():
    """Finding A, continued: with more than MAX_LINES radial loads one panel per load (a line
    each, monotone), not a tangle of lines."""
    radials = [1000.0 * i for i in range(plots.MAX_LINES + 2)]
    pts = _grid([500.0, 1000.0, 2000.0], radials=radials)
    fig = plots.build_figures(pts, _meta(["speed", "radial_load"]))["torque_plot"]
    panels = _ylabel_axes(fig, "torque")
    assert len(panels) == len(radials)
    for ax in panels:
        (total,) = _lines(ax, "total")
        assert list(total.get_xdata()) == [500.0, 1000.0, 2000.0]
        assert ax.get_title().startswith("Fr = ")


def test_run_plots_writes_files_with_the_umask_mode_and_leaves_no_temporary(tmp_path, monkeypatch):
    """Finding I: the files keep their names and keys, get the umask's mode (mkstemp made them
    0o600) and a failed write leaves no hidden temporary PNG."""
    pts = _grid([500.0, 1000.0], radials=(0.0, 5000.0))
    old = os.umask(0o027)
    try:
        files = plots.run_plots(pts, _meta(["speed", "radial_load"]), tmp_path)
    finally:
        os.umask(old)
    assert files == {"torque_plot": str(tmp_path / "torque.png"), "breakdown_plot": str(tmp_path / "breakdown.png"),
                     "loads_plot": str(tmp_path / "roller_loads_and_slip.png")}
    for f in files.values():
        assert Path(f).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert stat.S_IMODE(os.stat(f).st_mode) == 0o640
    from matplotlib.figure import Figure

    def boom(self, *a, **k):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Figure, "savefig", boom)
    with pytest.raises(OSError):
        plots.run_plots(pts, _meta(["speed", "radial_load"]), tmp_path / "new")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["breakdown.png", "new", "roller_loads_and_slip.png",
                                                          "torque.png"]
    assert list((tmp_path / "new").iterdir()) == []


# ------------------------------------------------------------------------------------------------
# real points (fidelity fast, ~50 ms each)

_SCENE = {
    "scene": {"name": "plots test"},
    "bearing": {"designation": "32216"},
    "lubricant": {"name": "FVA3"},
    "operating": {"axial_load": "6 kN", "radial_load": ["0 kN", "10 kN"],
                  "speed": ["500 rpm", "1000 rpm", "2000 rpm"], "temperature": "50 degC"},
    "lubrication": {"mode": "oil_bath", "oil_level": "half_roller"},
    "model": {"fidelity": "fast"},
}


def test_real_speed_by_radial_load_sweep(tmp_path):
    """Findings A and F on real points: the metadata from the scene, one line per radial load,
    the Liebrecht loss (~1-2 % of the friction) on its own axis; ``kegel.run`` writes the plots
    through ``kegel.plots`` and leaves no temporary file."""
    from kegel.run import run_scene
    from kegel.scene import scene_from_dict

    scene = scene_from_dict(_SCENE)
    meta = plots.plot_meta_from_scene(scene)
    assert meta["swept"] == ["speed", "radial_load"]
    assert meta["lubrication"] == "oil bath, half_roller" and meta["hydraulic"] == "Liebrecht"
    assert (meta["title"], meta["bearing"], meta["lubricant"]) == ("plots test", "32216", "FVA3")
    res = run_scene(scene, tmp_path / "out", progress=False)
    figs = plots.build_figures(res.points, meta)
    (ax,) = _ylabel_axes(figs["torque_plot"], "torque")
    totals = _lines(ax, "total")
    assert sorted(ln.get_label() for ln in totals) == ["total, Fr = 0 kN", "total, Fr = 10 kN"]
    assert all(list(ln.get_xdata()) == [500.0, 1000.0, 2000.0] for ln in totals)
    assert _lines(_ylabel_axes(figs["torque_plot"], "hydraulic")[0], "hydraulic (Liebrecht)")
    for key, name in plots.FILES.items():
        assert res.files[key] == str(tmp_path / "out" / name)
    assert not [p.name for p in (tmp_path / "out").iterdir() if p.name.startswith(".") and p.suffix == ".png"]


def test_labels_come_from_the_resolved_scene():
    """Labels from the result's metadata (the old titles named neither the lubrication nor the
    fidelity): a minimum-quantity scene swept in temperature only, no hydraulic loss drawn."""
    from kegel.scene import scene_from_dict

    raw = {**_SCENE, "lubrication": {"mode": "minimum_quantity"},
           "operating": {"axial_load": "6 kN", "speed": "1500 rpm", "temperature": ["40 degC", "50 degC"]}}
    meta = plots.plot_meta_from_scene(scene_from_dict(raw))
    assert meta["lubrication"] == "minimum quantity" and meta["hydraulic"] is None
    assert meta["swept"] == ["temperature"] and meta["fidelity"] == "fast, quasi_static"
    pts = [_point(i, speed_rpm=1500.0, T=T, hydraulic=0.0) for i, T in enumerate((40.0, 50.0))]
    figs = plots.build_figures(pts, meta)
    for fig in figs.values():
        text = _all_text(fig)
        assert all(w in text for w in ("plots test", "32216", "FVA3", "minimum quantity", "fast")), text
        assert "hydraulic" not in text
    (ax,) = _ylabel_axes(figs["torque_plot"], "torque")
    assert ax.get_xlabel() == "temperature [degC]"
    assert list(_lines(ax, "total")[0].get_xdata()) == [40.0, 50.0]
