"""What kegel ships with (``kegel list``) and a commented scene to start from (``kegel init``).

The data shipped with kegel lives in ``kegel/data/<kind>/*.toml``, one file per bearing,
lubricant, material and friction parameter set, each with its sources; the example scenes live in
``examples/`` of a source tree.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from .data import DATA_DIR, load_bearing, load_lubricant, load_material
from ..base.errors import KegelInputError
from ..base.io import atomic_write_text
from ..base._toml import read_toml

if TYPE_CHECKING:  # pragma: no cover
    from .scene_model import SceneSpec

__all__ = ["KINDS", "inventory", "scene_template", "write_scene_template"]

#: The kinds ``kegel list`` knows, with a one-line description.
KINDS = {
    "bearings": "tapered roller bearings (kegel/data/bearings)",
    "lubricants": "oils (kegel/data/lubricants)",
    "materials": "solid materials (kegel/data/materials)",
    "friction": "friction-law parameter sets (kegel/data/friction)",
    "validation": "measured-data sets of the validation (kegel/data/validation)",
    "examples": "example scenes (examples/ of a source tree)",
}

EXAMPLES_DIR = Path(__file__).resolve().parents[2] / "examples"


def _first_comment(path: Path) -> str:
    """The first sentence of a TOML file's first comment paragraph, without '#' (the paragraph's
    lines joined: a sentence that runs over several comment lines is given whole)."""
    import re

    words: list[str] = []
    for line in path.read_text(encoding="utf-8-sig").splitlines():
        s = line.strip()
        text = s.lstrip("#").strip() if s.startswith("#") else None
        if text:
            words.append(text)
        elif words:  # a blank comment line, a blank line or a statement ends the paragraph
            break
    paragraph = " ".join(words)
    # a sentence ends at . ! or ? followed by a capital letter (not "et al., Lubricants")
    return re.split(r"(?<=[.!?])\s+(?=[A-Z])", paragraph, maxsplit=1)[0]


def inventory(kind: str) -> list[dict[str, Any]]:
    """The entries of one kind of shipped data, each a dict with ``name``, ``file`` and a short
    description (bearings also with their boundary dimensions, C0r and roller count).

    Raises
    ------
    KegelInputError
        If ``kind`` is not one of :data:`KINDS`.
    """
    if kind not in KINDS:
        raise KegelInputError("command line", "kind", kind, "one of " + ", ".join(KINDS))
    if kind == "examples":
        files = sorted(EXAMPLES_DIR.glob("*.toml")) if EXAMPLES_DIR.is_dir() else []
        rows = []
        for f in files:
            scene = read_toml(f).get("scene", {})
            rows.append({"name": f.stem, "file": str(f), "title": scene.get("name", f.stem),
                         "description": scene.get("description", "")})
        return rows
    rows = []
    for f in sorted((DATA_DIR / kind).glob("*.toml")):
        row: dict[str, Any] = {"name": f.stem, "file": str(f)}
        if kind == "bearings":
            b = load_bearing(f.stem, source="command line", key="bearing")
            row.update(bore_mm=1e3 * b.bore_diameter_m, outside_mm=1e3 * b.outer_diameter_m,
                       width_mm=1e3 * b.total_width_m, C0r_kN=b.C0r_N / 1e3, rollers=b.roller_count,
                       description=f"d {1e3 * b.bore_diameter_m:g} x D {1e3 * b.outer_diameter_m:g} x "
                                   f"T {1e3 * b.total_width_m:g} mm, Z = {b.roller_count}, C0r = {b.C0r_N / 1e3:g} kN")
        elif kind == "lubricants":
            row["description"] = load_lubricant(f.stem, source="command line", key="lubricant").description
        elif kind == "materials":
            m = load_material(f.stem, source="command line", key="material")
            row["description"] = (f"E = {m.youngs_modulus_Pa / 1e9:g} GPa, nu = {m.poisson_ratio:g}, "
                                  f"rho = {m.density_kg_m3:g} kg/m3")
        else:
            row["description"] = _first_comment(f)
        rows.append(row)
    return rows


def scene_template(bearing: str = "32216", lubricant: str = "FVA3", name: str = "my scene") -> str:
    """A commented scene file that ``kegel check`` accepts: one bearing under an axial load, a speed
    sweep at one temperature in an oil bath, with every optional section shown commented out."""
    b = load_bearing(bearing, source="command line", key="--bearing")  # a clear error before writing
    lub = load_lubricant(lubricant, source="command line", key="--lubricant")
    # the values the template writes, and the description made of them (one source: the
    # description says what the file holds)
    axial, radial, speed_from, speed_to, points = "6 kN", "0 kN", "500 rpm", "4000 rpm", 8
    temperature, level = "50 degC", "half_roller"
    description = (f"{b.designation}, {lub.name}: Fa = {axial}, Fr = {radial}, {speed_from.split()[0]}-{speed_to} "
                   f"({points} speeds), {temperature}, oil bath at {level.replace('_', ' ')} height")
    return f'''# A kegel scene: one bearing, one oil, the operating points and the model fidelity.
# Check it with `kegel check FILE`, run it with `kegel run FILE`; every key is described in
# docs/scenes.md. Quantities are strings with their unit ("6 kN", "2000 rpm", "50 degC").

[scene]
name = "{name}"
description = "{description}"   # kegel run prints it: keep it in step with the values below

[bearing]
designation = "{bearing}"        # `kegel list bearings`, or a path to a bearing .toml file
# material = "bearing_steel"

[lubricant]
name = "{lubricant}"             # `kegel list lubricants`, or a path to a lubricant .toml file

[operating]
axial_load = "{axial}"              # or axial_offset = "20 um" (displacement-controlled preload)
radial_load = "{radial}"             # Fa / Fr must exceed tan(contact angle), else the ring lifts off
speed = {{ from = "{speed_from}", to = "{speed_to}", points = {points} }}   # or one speed, or a list
temperature = "{temperature}"          # bulk oil temperature; a list sweeps it
# tilt_moment = "20 N m"

[lubrication]
mode = "oil_bath"                # or "minimum_quantity" (no hydraulic loss)
oil_level = "{level}"        # none, half_roller, shaft_center, flooded or a length

[model]
fidelity = "default"             # fast, default, fine or auto (with tolerance = "1 %")
# hydraulic = "correlation"      # none, correlation (Liebrecht) or cfd (with cfd_results = "...")
# solution = "dynamic"           # then a [dynamic] table: duration, output_interval, ...

# Compare lubrications and hydraulic methods in one run (instead of [lubrication]'s level):
# [study]
# lubrication = ["flooded", "shaft_center", "minimum_quantity"]
# hydraulic = ["liebrecht", "skf"]

# [output]
# directory = "results/my_scene"
'''


def template_spec(text: str, *, source: str | Path = "kegel init") -> "SceneSpec":
    """The typed scene model (:class:`kegel.scene_model.SceneSpec`) of a template's text, checked
    by the scenes' validation layer (:func:`kegel.scene.validate_scene`), as ``kegel check``
    checks the file.

    Raises
    ------
    KegelInputError
        If the values the template writes do not pass (e.g. a bearing whose speed limit the
        template's speed sweep exceeds).
    """
    import tomllib

    from .scene import validate_scene
    from .scene_model import parse_scene

    spec = parse_scene(tomllib.loads(text), source=str(source))
    validate_scene(spec)
    return spec


def write_scene_template(path: str | Path, *, bearing: str = "32216", lubricant: str = "FVA3",
                         force: bool = False) -> Path:
    """Write :func:`scene_template` to ``path`` (atomically); refuses to replace an existing file
    unless ``force``.

    Raises
    ------
    KegelInputError
        If the file exists and ``force`` is false, or the bearing or lubricant is unknown.
    """
    p = Path(path)
    if p.exists() and not force:
        raise KegelInputError("command line", "file", str(p), "a file that does not exist yet (--force replaces it)")
    if p.suffix != ".toml":
        raise KegelInputError("command line", "file", str(p), "a .toml file name")
    text = scene_template(bearing, lubricant, name=p.stem.replace("_", " "))
    template_spec(text, source=p)  # the typed model of what it writes, validated: never a file `check` refuses
    atomic_write_text(p, text)
    return p
