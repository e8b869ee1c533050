"""External validation: kegel's bearing torque against the world outside kegel (``kegel validate``).

Two kinds of check, each a comparison of kegel's friction torque with an answer that does not
come from kegel:

1. **Measured data** from independent publications (``kegel/data/validation/*.toml``, one file
   per paper with its citation, bearing, oil and conditions): Aihara 1987, Zhou and Hoeprich
   1991, Manjunath et al. 2023. None of the three prints a measured torque in its text or
   tables: every measurement is in figures, which could not be read here, so their point arrays
   are empty and the command says so (``kegel/data/validation/README.md`` lists each figure and
   its conditions, ready to be digitised). Each file also records the numbers its text states.
2. **Independent engineering models**: Aihara's running-torque formula (NSK 1987,
   :mod:`kegel.correlations.aihara`) where the load is purely axial (Table 1), and the SKF
   catalogue model's rolling + sliding moment
   (:mod:`kegel.correlations.skf`) at the test conditions of the seed paper's Tables 1-3 (the
   conditions only; the paper's measured results are not used). SKF's model is fitted to SKF's
   own measurements of many bearings; Manjunath et al. (2023, Sec. 5) found it within 5-8 % of
   their measured TRB torque above 400 rpm and 15 % low below.

Every comparison reports measured (or reference) against computed per point with the deviation,
the mean and the worst, against the targets of issue 18 (mean |deviation| <= 15 %, no point
beyond 30 %). A failing comparison is reported, never tuned away: kegel's parameters are the
literature values of its data files, one set for all.
"""

from __future__ import annotations

import math
import sys
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import KegelInputError
from .io import atomic_write_json, provenance

__all__ = ["DATASET_DIR", "TARGET_MEAN", "TARGET_WORST", "Comparison", "measured_datasets", "model_comparisons",
           "print_report", "run_validation", "skf_comparisons"]

DATASET_DIR = Path(__file__).resolve().parent / "data" / "validation"
EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
#: Targets of issue 18 for every dataset: mean |deviation| and the worst point.
TARGET_MEAN = 0.15
TARGET_WORST = 0.30
#: The seed paper's test conditions (Tables 1-3) as scenes; their measured results are not used.
SKF_SCENES = ("32216_table1.toml", "32216_table2.toml", "32216_table3.toml")


@dataclass
class Comparison:
    """One dataset: reference (measured or independent model) against kegel, point by point."""

    name: str
    reference: str                 # what the reference values are
    citation: str
    labels: list[str] = field(default_factory=list)
    reference_Nm: list[float] = field(default_factory=list)
    kegel_Nm: list[float] = field(default_factory=list)
    converged: list[bool] = field(default_factory=list)
    note: str = ""

    @property
    def deviations(self) -> list[float]:
        """kegel / reference - 1 per point."""
        return [k / r - 1.0 for k, r in zip(self.kegel_Nm, self.reference_Nm)]

    @property
    def mean_abs_deviation(self) -> float:
        d = self.deviations
        return sum(abs(x) for x in d) / len(d) if d else math.nan

    @property
    def worst_deviation(self) -> float:
        d = self.deviations
        return max(d, key=abs) if d else math.nan

    @property
    def meets_targets(self) -> bool | None:
        """None without points."""
        if not self.reference_Nm:
            return None
        return self.mean_abs_deviation <= TARGET_MEAN and abs(self.worst_deviation) <= TARGET_WORST and all(
            self.converged)

    def as_dict(self) -> dict[str, Any]:
        return {"name": self.name, "reference": self.reference, "citation": self.citation, "note": self.note,
                "points": [{"label": lab, "reference_Nm": r, "kegel_Nm": k, "deviation": d, "converged": c}
                           for lab, r, k, d, c in zip(self.labels, self.reference_Nm, self.kegel_Nm,
                                                      self.deviations, self.converged)],
                "mean_abs_deviation": self.mean_abs_deviation if self.reference_Nm else None,
                "worst_deviation": self.worst_deviation if self.reference_Nm else None,
                "meets_targets": self.meets_targets,
                "targets": {"mean_abs_deviation": TARGET_MEAN, "worst_abs_deviation": TARGET_WORST}}


def measured_datasets() -> list[Comparison]:
    """The measured datasets of ``kegel/data/validation`` with their (possibly empty) points."""
    out = []
    for path in sorted(DATASET_DIR.glob("*.toml")):
        try:
            raw = tomllib.loads(path.read_text())
        except tomllib.TOMLDecodeError as exc:
            raise KegelInputError(str(path), "(file)", "", f"valid TOML ({exc})") from None
        cit = raw.get("citation", {})
        citation = f"{', '.join(cit.get('authors', []))}: {cit.get('title', '?')}, {cit.get('journal', '')} " \
                   f"{cit.get('volume', '')} ({cit.get('year', '')})"
        c = Comparison(name=str(raw.get("dataset", path.stem)), reference="measured", citation=citation.strip())
        n_points = int(raw.get("measured_points_in_text", 0))
        if n_points == 0:
            figs = ", ".join(s.get("figure", "?") for s in raw.get("measured_series", []))
            c.note = (f"no measured torque is printed in the paper's text or tables; the measurements are in "
                      f"figures ({figs}) that could not be read here: not validated (see {DATASET_DIR.name}/README.md)")
        else:  # solving recorded points needs the bearing's internal geometry, not yet in the files
            c.note = f"{n_points} measured points recorded but not yet runnable ({path.name}): not validated"
        out.append(c)
    return out


def skf_comparisons(progress: bool = False) -> tuple[list[Comparison], list[dict[str, Any]]]:
    """kegel's friction torque against the SKF model's rolling + sliding moment at the seed paper's
    Table 1-3 test conditions (default fidelity, the scenes in ``examples/``)."""
    comps, runs = model_comparisons(progress=progress)
    return [c for c in comps if c.name.startswith("SKF")], runs


def model_comparisons(progress: bool = False) -> tuple[list[Comparison], list[dict[str, Any]]]:
    """kegel's friction torque against two independent engineering models at the seed paper's
    Table 1-3 test conditions (default fidelity, the scenes in ``examples/``; each scene solved
    once): the SKF catalogue model's rolling + sliding moment at every point, and Aihara's
    running-torque formula (:mod:`kegel.correlations.aihara`) where the load is purely axial."""
    from . import _core
    from .correlations.aihara import CITATION as AIHARA, aihara_running_torque, vogel_viscosity_temperature_coefficient_1_K
    from .lubricant import lubricant_state
    from .run import run_scene
    from .scene import load_scene

    comps, runs = [], []
    aihara: list[Comparison] = []
    for name in SKF_SCENES:
        path = EXAMPLES / name
        if not path.is_file():
            raise KegelInputError(str(path), "(file)", "", "the example scene of the repository (kegel validate "
                                  "runs from a clone of kegel)")
        scene = load_scene(path)
        res = run_scene(scene, output_dir=None, progress=progress, write=False)
        c = Comparison(name=f"SKF model at {scene.name}", reference="SKF catalogue model, rolling + sliding",
                       citation="SKF Rolling bearings catalogue, PUB BU/P1 10000 EN, chapter Friction",
                       note="an independent engineering model, not a measurement")
        a = Comparison(name=f"Aihara 1987 formula at {scene.name}",
                       reference="Aihara's running-torque formula (Eq. 26, 27), rolling + rib",
                       citation=AIHARA,
                       note="an independent engineering model (NSK), checked by its author against the measured "
                            "torque of about 200 tapered roller bearings; pure axial load only")
        E = _core.reduced_modulus_Pa(scene.material.core, scene.material.core)
        P = scene.lubricant.parameters
        for p in res.points:
            label = (f"n {p['speed_rpm']:.0f} rpm, {p['temperature_degC']:.0f} degC, "
                     f"Fa {p['axial_force_N'] / 1e3:.1f} kN, Fr {p['radial_load_N'] / 1e3:.1f} kN")
            skf = p.get("skf_catalogue_model")
            if skf:
                c.labels.append(label)
                c.reference_Nm.append(skf["rolling_sliding_Nm"])
                c.kegel_Nm.append(p["friction_torque_Nm"])
                c.converged.append(bool(p["converged"]))
            if p["radial_load_N"] == 0.0 and p.get("friction_torque_Nm") is not None:
                T = p["temperature_K"]
                ai = aihara_running_torque(
                    scene.geometry, lubricant_state(scene.lubricant, T), speed_rad_s=p["speed_rad_s"],
                    axial_load_N=p["axial_force_N"], E_reduced_Pa=E, sigma_rib_m=scene.bearing.sigma_rib_m,
                    viscosity_temperature_coefficient_1_K=vogel_viscosity_temperature_coefficient_1_K(
                        P.vogel_B_K, P.vogel_C_degC, T))
                a.labels.append(label)
                a.reference_Nm.append(ai.total_Nm)
                a.kegel_Nm.append(p["friction_torque_Nm"])
                a.converged.append(bool(p["converged"]))
        comps.append(c)
        if a.reference_Nm:
            aihara.append(a)
        runs.append({"scene": str(path), "fidelity": scene.fidelity.as_dict()})
    return comps + aihara, runs


def run_validation(output_dir: str | Path, *, progress: bool = True) -> dict[str, Any]:
    """Run every comparison, write ``validation.json`` and one plot per comparison with points."""
    out = Path(output_dir)
    out.mkdir(parents=True, exist_ok=True)
    comps = measured_datasets()
    models, runs = model_comparisons(progress=progress)
    comps += models
    # each run records its scene's fidelity, model options (rolling_thermal, inlet_gap_ratio) included
    result = {"provenance": provenance(), "runs": runs, "comparisons": [c.as_dict() for c in comps]}
    plots = {}
    for i, c in enumerate(comps):
        if c.reference_Nm:
            plots[c.name] = str(_plot(c, out / f"validation_{i}.png"))
    result["plots"] = plots
    result["file"] = str(atomic_write_json(out / "validation.json", result))
    result["objects"] = comps
    return result


def _plot(c: Comparison, path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .plots import save_figure

    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ref, keg = c.reference_Nm, c.kegel_Nm
    top = 1.15 * max(max(ref), max(keg))
    ax.plot([0, top], [0, top], "k-", lw=0.8, label="equal")
    ax.fill_between([0, top], [0, 0.85 * top], [0, 1.15 * top], color="0.9", label="+-15 %")
    ax.plot(ref, keg, "o", color="C0", label="points")
    ax.set_xlim(0, top)
    ax.set_ylim(0, top)
    ax.set_xlabel(f"{c.reference} [N m]")
    ax.set_ylabel("kegel friction torque [N m]")
    ax.set_title(f"{c.name}\nmean |dev| {100 * c.mean_abs_deviation:.1f} %, worst {100 * c.worst_deviation:+.1f} %",
                 fontsize=9)
    ax.legend(fontsize=8)
    save_figure(fig, path)
    plt.close(fig)
    return path


def print_report(result: dict[str, Any], file=sys.stdout) -> None:
    """The validation table of :func:`run_validation`, per comparison."""
    for c in result["objects"]:
        print(f"\n{c.name}  [{c.reference}]", file=file)
        print(f"  {c.citation}", file=file)
        if c.note:
            print(f"  note: {c.note}", file=file)
        if not c.reference_Nm:
            continue
        print(f"  {'point':<44}{'reference':>11}{'kegel':>9}{'dev':>9}", file=file)
        for lab, r, k, d, ok in zip(c.labels, c.reference_Nm, c.kegel_Nm, c.deviations, c.converged):
            print(f"  {lab:<44}{r:>9.3f} N m{k:>7.3f}{100 * d:>+8.1f}%" + ("" if ok else "  FAILED"), file=file)
        verdict = {True: "meets", False: "MISSES", None: "-"}[c.meets_targets]
        print(f"  mean |dev| {100 * c.mean_abs_deviation:.1f} %, worst {100 * c.worst_deviation:+.1f} %: {verdict} "
              f"the targets ({100 * TARGET_MEAN:.0f} % mean, {100 * TARGET_WORST:.0f} % worst)", file=file)
    print(f"\nresults: {result['file']}", file=file)
