"""The plots of a run: torque against the swept quantity, its breakdown, roller loads and cage slip.

:func:`run_plots` writes ``torque.png``, ``breakdown.png`` and ``roller_loads_and_slip.png``
from the point records of :func:`kegel.run.run_scene`; :func:`build_figures` makes the same
figures without writing them (the tests inspect their axes and lines).

How a sweep is drawn
--------------------
* x axis: the first swept quantity other than the temperature (the temperature when it is the
  only one; the shaft speed for a single point, with limits around its value).
* The second swept quantity gives one line per value (the legend names the value with its
  unit); further swept quantities (the temperature when it is swept with two others) give one
  panel (facet) per value. A quantity with more than :data:`MAX_LINES` values gives panels
  instead of lines (the lines then come from the next quantity with few enough values). At most :data:`MAX_FACETS` panels are drawn (evenly chosen; the
  figure says how many of how many). Each line's points are sorted by x, so no line zig-zags.
* Breakdown: stacked bars by contact and mechanism, one panel for every line of every facet,
  with a fixed colour per (contact, mechanism) (:data:`PALETTE`), whatever the run holds.
* Hydraulic loss: labelled from its source (``hydraulic (Liebrecht)``, ``hydraulic (CFD)``);
  when it stays below :data:`SMALL_HYDRAULIC` of the friction torque it gets its own panel
  under the torque panel, with its own scale.
* Units: torque in N m, or N mm on an axis whose torques are all below 0.1 N m; tick labels
  with at most four significant figures and no offset; loads in kN, speed in rpm.
* Points that did not converge are drawn as hollow red markers (bars: hatched, red edge) and
  never joined to the lines of the converged points; points without figures are left out and
  counted in a note on the figure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Sequence, TypedDict

from ..solutions.dynamics import CONTACTS, MECHANISMS

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..model.scene import Scene

__all__ = [
    "AXES",
    "FILES",
    "MAX_FACETS",
    "MAX_LINES",
    "PALETTE",
    "PlotMeta",
    "SMALL_HYDRAULIC",
    "FIGURE_SUFFIXES",
    "build_figures",
    "check_figure_path",
    "plot_meta_from_scene",
    "run_plots",
    "save_figure",
    "x_and_series",
]


class PlotMeta(TypedDict, total=False):
    """What the plots say about a run besides its points (every key optional).

    Attributes
    ----------
    title
        The scene's title (its name; with the ``--set`` changes when there are any).
    bearing
        Bearing designation, e.g. ``"32216"``.
    lubricant
        Lubricant name, e.g. ``"FVA3"``.
    lubrication
        The lubrication as resolved, e.g. ``"oil bath, shaft_center"``, ``"minimum quantity"``.
    fidelity
        Fidelity preset and solution, e.g. ``"fast, quasi_static"``.
    swept
        The swept quantities (keys of :data:`AXES`), the x axis's first: e.g.
        ``["speed", "radial_load"]``.
    hydraulic
        Source of the hydraulic loss: ``"Liebrecht"``, ``"SKF"``, ``"CFD"`` or None (none).
    """

    title: str
    bearing: str
    lubricant: str
    lubrication: str
    fidelity: str
    swept: list[str]
    hydraulic: str | None


@dataclass(frozen=True)
class _Axis:
    """A swept quantity: record key, symbol, name, unit and the factor from the record's unit."""

    key: str
    symbol: str
    name: str
    unit: str
    scale: float

    def value(self, p: dict[str, Any]) -> float | None:
        v = p.get(self.key)
        return None if v is None else float(v) * self.scale

    def label(self, v: float) -> str:
        """``"Fr = 10 kN"``: a value (already scaled) with its symbol and unit."""
        return f"{self.symbol} = {_fmt(v)} {self.unit}"

    @property
    def axis_label(self) -> str:
        return f"{self.name} [{self.unit}]"


#: The quantities a scene sweeps, as the plots show them.
AXES: dict[str, _Axis] = {
    "speed": _Axis("speed_rpm", "n", "shaft speed", "rpm", 1.0),
    "radial_load": _Axis("radial_load_N", "Fr", "radial load", "kN", 1e-3),
    "axial_load": _Axis("axial_load_N", "Fa", "axial load", "kN", 1e-3),
    "axial_offset": _Axis("axial_offset_m", "offset", "axial offset (preload)", "um", 1e6),
    "temperature": _Axis("temperature_degC", "T", "temperature", "degC", 1.0),
}

#: More values than this on the second swept axis: one panel per value instead of one line.
MAX_LINES = 6
#: At most this many panels per figure (evenly chosen, the figure says how many of how many).
MAX_FACETS = 12
#: Hydraulic loss below this fraction of the friction torque (at its largest): its own panel.
SMALL_HYDRAULIC = 0.05
#: Torques all below this [N m] on an axis: the axis in N mm.
N_MM_BELOW = 0.1

#: File name of each plot, by the key :func:`run_plots` returns it under.
FILES = {"torque_plot": "torque.png", "breakdown_plot": "breakdown.png", "loads_plot": "roller_loads_and_slip.png"}

_BLUES = ("#08519c", "#3182bd", "#6baed6", "#9ecae1", "#c6dbef")
_ORANGES = ("#a63603", "#e6550d", "#fd8d3c", "#fdae6b", "#fdd0a2")
_GREENS = ("#006d2c", "#31a354", "#74c476", "#a1d99b", "#c7e9c0")
_SHADE = {"ehl_sliding": 0, "solid_sliding": 1, "ehl_rolling": 2, "solid_rolling": 3, "hysteresis": 4}
#: Fixed colour of each breakdown segment, (contact, mechanism): a hue per contact (outer
#: raceway blue, inner raceway orange, rib green), a shade per mechanism; the cage pockets and
#: the hydraulic loss have their own. The same in every run, whichever segments it draws.
PALETTE: dict[tuple[str, str], str] = {
    **{("outer_raceway", m): _BLUES[i] for m, i in _SHADE.items()},
    **{("inner_raceway", m): _ORANGES[i] for m, i in _SHADE.items()},
    **{("rib", m): _GREENS[i] for m, i in _SHADE.items()},
    ("cage", "solid_sliding"): "#756bb1",
    ("oil", "hydraulic"): "#969696",
}
_UNKNOWN_COLOUR = "#000000"  # a contact or mechanism added to kegel.dynamics without a colour here
_LINE_COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22",
                 "#17becf", "#ff7f0e")
_FAILED = dict(ls="none", mfc="none", mec="red", mew=1.5, ms=9)  # not-converged points
_FAILED_LABEL = "not converged (not joined)"
_HYDRAULIC_SOURCES = {"none": None, "correlation": "Liebrecht", "cfd": "CFD"}


def _fmt(v: float) -> str:
    """At most four significant figures, never an exponent for the magnitudes plotted."""
    if v == 0 or not math.isfinite(v):
        return "0" if v == 0 else str(v)
    s = f"{v:.4g}"
    if "e" in s:
        s = f"{v:.0f}" if abs(v) >= 1 else f"{v:.6f}".rstrip("0").rstrip(".")
    return s


# ------------------------------------------------------------------------------------------------
# metadata


def plot_meta_from_scene(scene: "Scene") -> PlotMeta:
    """The plots' metadata of a resolved scene.

    Parameters
    ----------
    scene
        The scene as the run solved it (after ``fidelity = "auto"`` chose its preset).

    Returns
    -------
    PlotMeta
        Title, bearing, lubricant, lubrication as resolved, fidelity, the swept quantities (the
        fastest varying first: speed, loads, temperature) and the hydraulic loss's source.
    """
    lub = scene.lubrication
    if getattr(scene, "study", None) is not None:
        lubrication = "study: contact friction alone (hydraulic losses: study.png)"
    elif lub.mode == "minimum_quantity":
        lubrication = "minimum quantity"
    else:
        lubrication = f"oil bath, {lub.oil_level_as_written}"
    fid = scene.fidelity
    hydraulic = _HYDRAULIC_SOURCES.get(fid.hydraulic, fid.hydraulic)
    if hydraulic == "Liebrecht" and lub.oil_level_m <= 0:
        hydraulic = None  # no oil bath, no hydraulic loss
    return PlotMeta(
        title=getattr(scene, "title", scene.name),
        bearing=scene.bearing.designation,
        lubricant=scene.lubricant.name,
        lubrication=lubrication,
        fidelity=f"{fid.name}, {fid.solution}",
        # the scene lists them slowest first (speed varies fastest): the plots want speed on x
        swept=[s for s in reversed(scene.swept)],
        hydraulic=hydraulic,
    )


def _hydraulic_source(points: Sequence[dict[str, Any]], meta: PlotMeta) -> str | None:
    """The hydraulic loss's source: the metadata's, else what the records say."""
    if meta.get("hydraulic"):
        return meta["hydraulic"]
    for p in points:
        h = p.get("hydraulic")
        if isinstance(h, dict):
            if h.get("source") == "cfd":
                return "CFD"
            if h.get("correlation"):
                return str(h["correlation"]).capitalize() if h["correlation"] != "skf" else "SKF"
    return None


# ------------------------------------------------------------------------------------------------
# layout: which points make which line of which panel


@dataclass
class _Line:
    label: str  # "Fr = 10 kN" ("" without a second swept quantity)
    colour: str
    points: list[dict[str, Any]]  # sorted by x


@dataclass
class _Facet:
    label: str  # "T = 50 degC" ("" for a single panel)
    lines: list[_Line] = field(default_factory=list)


@dataclass
class _Layout:
    x: _Axis
    facets: list[_Facet]
    notes: list[str]
    points: list[dict[str, Any]]  # those with figures


def _key(v: float | None) -> float | None:
    return None if v is None else float(f"{v:.9g}")


def _values(points: Sequence[dict[str, Any]], axis: _Axis) -> list[float | None]:
    vals = {_key(axis.value(p)) for p in points}
    return sorted(vals, key=lambda v: (v is None, v if v is not None else 0.0))


def _evenly(items: list[Any], n: int) -> list[Any]:
    if len(items) <= n:
        return items
    idx = sorted({round(i * (len(items) - 1) / (n - 1)) for i in range(n)})
    return [items[i] for i in idx]


def x_and_series(swept: Sequence[str]) -> tuple[str, list[str]]:
    """The x axis of a run's plots and the other swept quantities, by the rule of the module
    docstring: x is the first swept quantity other than the temperature, else the temperature,
    else (a single point) the shaft speed; the others follow in order, the temperature last.

    Parameters
    ----------
    swept
        The swept quantities (keys of :data:`AXES`; others are ignored), the fastest first.
    """
    swept = [s for s in swept if s in AXES]
    xname = next((s for s in swept if s != "temperature"), swept[0] if swept else "speed")
    series = [s for s in swept if s not in (xname, "temperature")] + [s for s in swept if s == "temperature" and s != xname]
    return xname, series


def _layout(points: Sequence[dict[str, Any]], meta: PlotMeta) -> _Layout:
    notes = []
    drawable = [p for p in points if p.get("total_torque_Nm") is not None and p.get("friction_torque_Nm") is not None]
    if len(drawable) < len(points):
        notes.append(f"{len(points) - len(drawable)} point(s) failed without figures: not drawn (see results.csv)")
    xname, series = x_and_series(meta.get("swept", []))
    x = AXES[xname]
    # lines: the first further quantity with at most MAX_LINES values; panels: the others
    line_axes = next(([s] for s in series if len(_values(drawable, AXES[s])) <= MAX_LINES), [])
    facet_axes = [s for s in series if s not in line_axes]
    line_vals = _values(drawable, AXES[line_axes[0]]) if line_axes else [None]
    colours = {v: _LINE_COLOURS[i % len(_LINE_COLOURS)] for i, v in enumerate(line_vals)}

    def combo(p: dict[str, Any], axes: list[str]) -> tuple[float | None, ...]:
        return tuple(_key(AXES[a].value(p)) for a in axes)

    facet_keys = sorted({combo(p, facet_axes) for p in drawable},
                        key=lambda t: tuple((v is None, v or 0.0) for v in t))
    if len(facet_keys) > MAX_FACETS:
        notes.append(f"{MAX_FACETS} of {len(facet_keys)} panels shown (every point: results.csv)")
        facet_keys = _evenly(facet_keys, MAX_FACETS)
    facets = []
    for fk in facet_keys:
        label = ", ".join(AXES[a].label(v) for a, v in zip(facet_axes, fk) if v is not None)
        facet = _Facet(label)
        in_facet = [p for p in drawable if combo(p, facet_axes) == fk]
        for lv in line_vals:
            ps = [p for p in in_facet if not line_axes or _key(AXES[line_axes[0]].value(p)) == lv]
            if not ps:
                continue
            ps.sort(key=lambda p: (x.value(p) is None, x.value(p) or 0.0, p.get("index", 0)))
            lab = AXES[line_axes[0]].label(lv) if line_axes and lv is not None else ""
            facet.lines.append(_Line(lab, colours[lv], ps))
        facets.append(facet)
    return _Layout(x, facets, notes, drawable)


# ------------------------------------------------------------------------------------------------
# helpers


def _failed(p: dict[str, Any]) -> bool:
    return p.get("converged") is False


def _torque_unit(values: Sequence[float]) -> tuple[str, float]:
    """``("N mm", 1e3)`` when every torque is below 0.1 N m, else ``("N m", 1)``."""
    top = max((abs(v) for v in values if v is not None and math.isfinite(v)), default=0.0)
    return ("N mm", 1e3) if top < N_MM_BELOW else ("N m", 1.0)


def _style_y(ax: "Axes", data: Sequence[float]) -> None:
    """Tick labels with <= 4 significant figures, no offset; the range from zero when the data
    keep one sign (a torque's size reads against zero)."""
    from matplotlib.ticker import FuncFormatter

    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _pos: _fmt(v)))
    vals = [v for v in data if v is not None and math.isfinite(v)]
    if vals:
        lo, hi = min(vals), max(vals)
        if lo >= 0 and hi > 0:
            ax.set_ylim(0.0, 1.08 * hi)
        elif hi <= 0 and lo < 0:
            ax.set_ylim(1.08 * lo, 0.0)


def _style_x(ax: "Axes", xs: Sequence[float]) -> None:
    """Plain tick labels; a single x value gets limits around it (not +-0.04 around nothing)."""
    from matplotlib.ticker import FuncFormatter

    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _pos: _fmt(v)))
    vals = sorted({v for v in xs if v is not None})
    if len(vals) == 1:
        v = vals[0]
        pad = 0.1 * abs(v) if v else 1.0
        ax.set_xlim(v - pad, v + pad)


def _annotate(ax: "Axes", unit: str) -> None:
    """A panel with a single x value: the figures of its labelled lines in a box."""
    rows = [f"{ln.get_label()}: {_fmt(float(y))} {unit}" for ln in ax.get_lines()
            if not ln.get_label().startswith("_") for y in ln.get_ydata()]
    if rows:
        ax.text(0.02, 0.04, "\n".join(rows), transform=ax.transAxes, fontsize=7, va="bottom", ha="left",
                bbox=dict(boxstyle="round", fc="white", ec="0.8"))


def _header(meta: PlotMeta, what: str) -> str:
    title = meta.get("title") or "kegel run"
    details = ", ".join(str(meta[k]) for k in ("bearing", "lubricant", "lubrication") if meta.get(k))
    fid = meta.get("fidelity")
    return f"{title}: {what}\n{details}" + (f" (fidelity {fid})" if fid else "")


def _finish(fig: "Figure", meta: PlotMeta, what: str, notes: list[str]) -> None:
    text = _header(meta, what) + ("\nnote: " + "; ".join(notes) if notes else "")
    fig.suptitle(text, fontsize=9)


def _grid(n: int) -> tuple[int, int]:
    ncols = 1 if n == 1 else 2 if n in (2, 4) else 3
    return math.ceil(n / ncols), ncols


def _new_figure(width: float, height: float) -> "Figure":
    from matplotlib.figure import Figure

    return Figure(figsize=(width, height), layout="constrained")


# ------------------------------------------------------------------------------------------------
# figures


def _torque_figure(lay: _Layout, meta: PlotMeta, source: str | None) -> "Figure":
    pts = lay.points
    hyd_all = [abs(p.get("hydraulic_torque_Nm") or 0.0) for p in pts]
    fric_all = [abs(p["friction_torque_Nm"]) for p in pts]
    has_hyd = max(hyd_all, default=0.0) > 0.0
    separate = has_hyd and max(hyd_all) < SMALL_HYDRAULIC * max(fric_all, default=0.0)
    unit, us = _torque_unit([p["total_torque_Nm"] for p in pts] + [p["friction_torque_Nm"] for p in pts]
                            + ([] if separate else hyd_all))
    hunit, hs = _torque_unit(hyd_all) if separate else (unit, us)
    hlabel = f"hydraulic ({source})" if source else "hydraulic"
    nrows, ncols = _grid(len(lay.facets))
    per = 2 if separate else 1
    fig = _new_figure(4.0 + 3.4 * ncols, (4.3 if separate else 3.6) * nrows + 0.8)
    gs = fig.add_gridspec(nrows * per, ncols, height_ratios=([3, 1.4] if separate else [1]) * nrows)
    for i, facet in enumerate(lay.facets):
        r, c = divmod(i, ncols)
        ax = fig.add_subplot(gs[r * per, c])
        ax.set_label("torque")
        hax = fig.add_subplot(gs[r * per + 1, c], sharex=ax) if separate else ax
        if separate:
            hax.set_label("hydraulic")
        ys, hys, xs = [], [], []
        failed_shown = False
        for line in facet.lines:
            suffix = f", {line.label}" if line.label else ""
            good = [p for p in line.points if not _failed(p)]
            bad = [p for p in line.points if _failed(p)]
            gx = [lay.x.value(p) for p in good]
            tot = [p["total_torque_Nm"] * us for p in good]
            fr = [p["friction_torque_Nm"] * us for p in good]
            ax.plot(gx, tot, ls="-", marker="o", color=line.colour, label=f"total{suffix}")
            ax.plot(gx, fr, ls="--", marker="s", ms=4, color=line.colour, label=f"friction{suffix}")
            ys += tot + fr
            ys += _band(ax, gx, good, us, line.colour, suffix, with_total=has_hyd)
            xs += gx
            if has_hyd:
                hy = [(p.get("hydraulic_torque_Nm") or 0.0) * hs for p in good]
                hax.plot(gx, hy, ls=":", marker="^", color=line.colour, label=f"{hlabel}{suffix}")
                hys += hy
            if bad:
                bx = [lay.x.value(p) for p in bad]
                btot = [p["total_torque_Nm"] * us for p in bad]
                bfr = [p["friction_torque_Nm"] * us for p in bad]
                ax.plot(bx, btot, marker="o", label="_nolegend_" if failed_shown else _FAILED_LABEL, **_FAILED)
                ax.plot(bx, bfr, marker="s", label="_nolegend_", **_FAILED)
                failed_shown = True
                ys += btot + bfr
                xs += bx
                if has_hyd:
                    bh = [(p.get("hydraulic_torque_Nm") or 0.0) * hs for p in bad]
                    hax.plot(bx, bh, marker="^", label="_nolegend_", **_FAILED)
                    hys += bh
        if not separate:
            ys += hys
        if len({v for v in xs if v is not None}) == 1:
            _annotate(ax, unit)  # a single point: its figures written beside the markers
            if separate:
                _annotate(hax, hunit)
        ax.set_ylabel(f"torque [{unit}]")
        _style_y(ax, ys)
        _style_x(ax, xs)
        if facet.label:
            ax.set_title(facet.label, fontsize=9)
        if separate:
            hax.set_ylabel(f"{hlabel} [{hunit}]", fontsize=8)
            _style_y(hax, hys)
            ax.tick_params(labelbottom=False)
        hax.set_xlabel(lay.x.axis_label)
        ax.legend(fontsize=7)
        if separate:
            hax.legend(fontsize=7)
    notes = list(lay.notes)
    if separate:
        notes.append(f"{hlabel} < {SMALL_HYDRAULIC:.0%} of the friction torque: own panel, own scale")
    _finish(fig, meta, "torque at the shaft", notes)
    return fig


def _band(ax: "Axes", gx: list[float | None], pts: Sequence[dict[str, Any]], us: float, colour: str, suffix: str,
          *, with_total: bool) -> list[float]:
    """The uncertainty band of a line (``kegel run --uncertainty``, :mod:`kegel.uncertainty`): a
    shaded band from the smallest to the largest friction torque of each point (and of the total,
    with a hydraulic loss), an error bar for a single point. Returns the values drawn (for the
    axis limits); nothing when a point of the line has no band."""
    bands = [p.get("uncertainty") or {} for p in pts]
    if not pts or not all("friction_torque_low_Nm" in u for u in bands):
        return []
    drawn: list[float] = []
    keys = [("friction", "friction_torque")] + ([("total", "total_torque")] if with_total else [])
    for i, (name, key) in enumerate(keys):
        lo = [u[f"{key}_low_Nm"] * us for u in bands]
        hi = [u[f"{key}_high_Nm"] * us for u in bands]
        label = f"{name} band (crown, slice model){suffix}"
        if len(gx) > 1:
            ax.fill_between(gx, lo, hi, color=colour, alpha=0.18 if i == 0 else 0.10, lw=0, label=label)
        else:
            mid = [p[f"{key}_Nm"] * us for p in pts]
            ax.errorbar(gx, mid, yerr=[[m - a for m, a in zip(mid, lo)], [b - m for m, b in zip(mid, hi)]],
                        fmt="none", ecolor=colour, capsize=4, label=label)
        drawn += lo + hi
    return drawn


def _segments(pts: Sequence[dict[str, Any]], source: str | None) -> list[tuple[tuple[str, str], str, Callable]]:
    """The breakdown's segments drawn (fixed order; negligible ones everywhere left out): key in
    :data:`PALETTE`, label, torque [N m] of a point."""

    def contact_mech(c: str, k: str) -> Callable[[dict[str, Any]], float]:
        def f(p: dict[str, Any]) -> float:
            power = p.get("power_W") or {}
            w = p.get("speed_rad_s") or 0.0
            return float(power.get(c, {}).get(k, 0.0)) / w if w else 0.0
        return f

    candidates: list[tuple[tuple[str, str], str, Callable]] = [
        ((c, k), f"{c.replace('_', ' ')}: {k.replace('_', ' ')}", contact_mech(c, k)) for c in CONTACTS for k in MECHANISMS]
    candidates.append((("cage", "solid_sliding"), "cage pockets: solid sliding",
                       lambda p: float((p.get("torque_by_contact_Nm") or {}).get("cage", 0.0) or 0.0)))
    candidates.append((("oil", "hydraulic"), f"hydraulic ({source})" if source else "hydraulic",
                       lambda p: float(p.get("hydraulic_torque_Nm") or 0.0)))
    scale = max((abs(p["friction_torque_Nm"]) for p in pts), default=0.0)
    return [s for s in candidates if any(abs(s[2](p)) > 1e-6 * max(scale, 1e-12) for p in pts)]


def _breakdown_figure(lay: _Layout, meta: PlotMeta, source: str | None) -> "Figure":
    import numpy as np

    segs = _segments(lay.points, source)
    unit, us = _torque_unit([p["total_torque_Nm"] for p in lay.points])
    panels = [(facet, line) for facet in lay.facets for line in facet.lines]
    notes = list(lay.notes)
    if len(panels) > MAX_FACETS:
        notes.append(f"breakdown: {MAX_FACETS} of {len(panels)} panels shown")
        panels = _evenly(panels, MAX_FACETS)
    nrows, ncols = _grid(len(panels))
    fig = _new_figure(2.8 + 3.6 * ncols, 3.4 * nrows + 0.8)
    gs = fig.add_gridspec(nrows, ncols + 1, width_ratios=[1] * ncols + [0.9])
    handles: dict[str, Any] = {}
    for i, (facet, line) in enumerate(panels):
        r, c = divmod(i, ncols)
        ax = fig.add_subplot(gs[r, c])
        ax.set_label("breakdown")
        ps = line.points
        pos = np.arange(len(ps), dtype=float)
        bottom = np.zeros(len(ps))
        tops = [0.0]
        for key, label, f in segs:
            vals = np.array([f(p) * us for p in ps])
            bars = ax.bar(pos, vals, bottom=bottom, width=0.6, color=PALETTE.get(key, _UNKNOWN_COLOUR),
                          label=label, edgecolor="white", linewidth=0.3)
            handles.setdefault(label, bars)
            bottom += vals
        tops += bottom.tolist()
        bad = [j for j, p in enumerate(ps) if _failed(p)]
        if bad:
            bars = ax.bar(pos[bad], bottom[bad], width=0.6, fill=False, edgecolor="red", hatch="xx",
                          linewidth=1.2, label=_FAILED_LABEL)
            handles.setdefault(_FAILED_LABEL, bars)
        ax.set_xticks(pos)
        ax.set_xticklabels([_fmt(lay.x.value(p)) + ("\nnot conv." if _failed(p) else "") for p in ps],
                           fontsize=7, rotation=0 if len(ps) <= 8 else 60)
        for j in bad:
            ax.get_xticklabels()[j].set_color("red")
        ax.set_xlim(-0.75, len(ps) - 0.25)
        ax.set_xlabel(lay.x.axis_label)
        ax.set_ylabel(f"torque [{unit}]")
        _style_y(ax, tops)
        title = ", ".join(t for t in (facet.label, line.label) if t)
        if title:
            ax.set_title(title, fontsize=9)
    lax = fig.add_subplot(gs[:, ncols])
    lax.set_label("legend")
    lax.axis("off")
    lax.legend(list(handles.values()), list(handles.keys()), loc="upper left", fontsize=7, frameon=False,
               title="contact: mechanism", title_fontsize=7)
    _finish(fig, meta, "torque at the shaft by contact and mechanism", notes)
    return fig


def _loads_figure(lay: _Layout, meta: PlotMeta) -> "Figure":
    import numpy as np

    n = len(lay.facets)
    fig = _new_figure(11.0, 3.8 * n + 0.8)
    axes = fig.subplots(n, 2, squeeze=False)
    for facet, (a1, a2) in zip(lay.facets, axes):
        a1.set_label("roller_loads")
        a2.set_label("cage_slip")
        loads: list[float] = [0.0]
        slips, xs = [], []
        failed_shown = False
        for line in facet.lines:
            ends = [line.points[0]] + ([line.points[-1]] if len(line.points) > 1 else [])
            for j, p in enumerate(ends):
                if not p.get("roller_azimuth_rad"):
                    continue
                psi = np.degrees(p["roller_azimuth_rad"])
                what = ", ".join(t for t in (lay.x.label(lay.x.value(p)), line.label) if t)
                what += " (not converged)" if _failed(p) else ""
                ls = "-" if j == 0 else "--"
                inner = [v * 1e-3 for v in p.get("roller_inner_N", [])]
                rib = [v * 1e-3 for v in p.get("roller_rib_N", [])]
                if inner:
                    a1.plot(psi, inner, ls=ls, marker="o", ms=4, color=line.colour, label=f"inner, {what}")
                if rib:
                    a1.plot(psi, rib, ls=ls, marker="x", ms=4, lw=0.8, color=line.colour, alpha=0.7,
                            label=f"rib, {what}")
                loads += inner + rib
            good = [p for p in line.points if not _failed(p) and p.get("cage_slip") is not None]
            bad = [p for p in line.points if _failed(p) and p.get("cage_slip") is not None]
            gx = [lay.x.value(p) for p in good]
            gy = [100 * p["cage_slip"] for p in good]
            a2.plot(gx, gy, marker="o", color=line.colour, label=line.label or "cage slip")
            slips += gy
            xs += gx
            if bad:
                bx = [lay.x.value(p) for p in bad]
                by = [100 * p["cage_slip"] for p in bad]
                a2.plot(bx, by, marker="o", label="_nolegend_" if failed_shown else _FAILED_LABEL, **_FAILED)
                failed_shown = True
                slips += by
                xs += bx
        a1.set_xlabel("roller azimuth from the radial load [deg]")
        a1.set_ylabel("roller load [kN]")
        _style_y(a1, loads)
        a1.legend(fontsize=6)
        a2.set_xlabel(lay.x.axis_label)
        a2.set_ylabel("cage slip [%]")
        _style_y(a2, slips)
        _style_x(a2, xs)
        if len({v for v in xs if v is not None}) == 1:
            _annotate(a2, "%")
        a2.legend(fontsize=7)
        if facet.label:
            a1.set_title(facet.label, fontsize=9)
            a2.set_title(facet.label, fontsize=9)
    _finish(fig, meta, "roller loads (first and last point of each line) and cage slip", list(lay.notes))
    return fig


def build_figures(points: Sequence[dict[str, Any]], meta: PlotMeta | None = None) -> dict[str, "Figure"]:
    """The run's figures, not written (see the module docstring for what they show).

    Parameters
    ----------
    points
        Point records of :func:`kegel.run.run_scene` (records without figures are left out
        and counted in a note).
    meta
        See :class:`PlotMeta` (:func:`plot_meta_from_scene`); None: no title, x axis the speed.

    Returns
    -------
    dict[str, matplotlib.figure.Figure]
        By the keys of :data:`FILES`: ``torque_plot``, ``breakdown_plot``, ``loads_plot``.
        Each axes carries a label (``Axes.get_label()``): ``torque``, ``hydraulic``,
        ``breakdown``, ``legend``, ``roller_loads``, ``cage_slip``.

    Raises
    ------
    ValueError
        No point has figures.
    """
    meta = PlotMeta(**(meta or {}))
    lay = _layout(points, meta)
    if not lay.points:
        raise ValueError("no point with figures to plot")
    source = _hydraulic_source(lay.points, meta)
    return {
        "torque_plot": _torque_figure(lay, meta, source),
        "breakdown_plot": _breakdown_figure(lay, meta, source),
        "loads_plot": _loads_figure(lay, meta),
    }


#: File name suffixes a figure can be written to (matplotlib's formats that every installation has).
FIGURE_SUFFIXES = (".png", ".pdf", ".svg", ".jpg", ".jpeg", ".eps", ".ps", ".tif", ".tiff", ".webp")


def check_figure_path(path: str | Path, *, source: str = "command line", key: str = "--plot") -> Path:
    """The figure file ``path`` if a figure can be written there.

    Parameters
    ----------
    path
        File to write (its suffix chooses the format).
    source, key
        Where the path came from, for the error (e.g. ``"command line"``, ``"--plot"``).

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    KegelInputError
        ``path`` is an existing folder, its suffix is not one of :data:`FIGURE_SUFFIXES`, or its
        folder does not exist.
    """
    from ..base.errors import KegelInputError

    p = Path(path)
    names = ", ".join(FIGURE_SUFFIXES)
    if p.is_dir():
        raise KegelInputError(source, key, str(path), f"a figure file name ending in {names}, not a folder "
                              f"(e.g. {p / 'losses.png'})")
    if p.suffix.lower() not in FIGURE_SUFFIXES:
        raise KegelInputError(source, key, str(path), f"a figure file name ending in {names} "
                              f"(e.g. {p.with_suffix('.png') if p.name else 'losses.png'})")
    if not p.parent.is_dir():
        raise KegelInputError(source, key, str(path), f"a file in an existing folder ({p.parent} does not exist)")
    return p


def save_figure(fig: "Figure", path: str | Path, dpi: int = 110) -> str:
    """Write a figure atomically: a hidden temporary file beside ``path`` with the umask's mode,
    then a rename; the temporary file is removed on any failure or interrupt.

    Returns
    -------
    str
        The path written.
    """
    from ..base.io import atomic_save

    return str(atomic_save(path, lambda tmp: fig.savefig(tmp, dpi=dpi)))


def run_plots(points: Sequence[dict[str, Any]], meta: PlotMeta | None, out: str | Path) -> dict[str, str]:
    """Write the plots of a run into ``out``.

    Parameters
    ----------
    points
        Point records of :func:`kegel.run.run_scene`.
    meta
        See :class:`PlotMeta`.
    out
        Output folder.

    Returns
    -------
    dict[str, str]
        The files written, by the keys of :data:`FILES`.
    """
    figs = build_figures(points, meta)
    try:
        return {key: save_figure(fig, Path(out) / FILES[key]) for key, fig in figs.items()}
    finally:
        figs.clear()  # Figure objects without pyplot: nothing global to close
