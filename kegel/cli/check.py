"""``kegel check SCENE [--set KEY=VALUE ...]``: validate a scene file (what ``kegel run`` checks
before its first point)."""

from __future__ import annotations

import argparse
from typing import Any, Callable

from ..model.lubricant import lubricant_state
from ..model.scene import Scene, load_scene
from .common import _json_out, printable

__all__ = ["add_parser", "command"]


def _scene_summary(scene: Scene) -> dict[str, Any]:
    g = scene.geometry
    states = {}
    for p in scene.operating_points:
        if p.temperature_K not in states:
            states[p.temperature_K] = lubricant_state(scene.lubricant, p.temperature_K, source=scene.source,
                                                      key="operating.temperature")
    return {
        "scene": {"name": scene.name, "description": scene.description, "file": scene.source,
                  "resolved": scene.resolved},
        "bearing": scene.bearing.designation,
        "material": scene.material.name,
        "lubricant": scene.lubricant.name,
        "lubrication": {"mode": scene.lubrication.mode, "oil_level_m": scene.lubrication.oil_level_m,
                        "oil_level_as_written": scene.lubrication.oil_level_as_written},
        "fidelity": scene.fidelity.as_dict(),
        "swept": list(scene.swept),
        "geometry": g.as_dict(),
        "operating_points": [
            {**p.as_dict(), "lubricant_state": states[p.temperature_K].as_dict()} for p in scene.operating_points
        ],
    }


def command(args: argparse.Namespace) -> int:
    from ..runner.run import preflight

    scene = load_scene(args.scene, args.set or ())
    preflight(scene)  # what kegel run checks before its first point (each point's CFD result)
    summary = _scene_summary(scene)  # evaluates the lubricant at every temperature, too
    if args.format == "json":
        _json_out({"valid": True, "file": str(args.scene), "name": scene.name,
                   "operating_point_count": len(scene.operating_points), "swept": list(scene.swept),
                   "fidelity": summary["fidelity"]})
        return 0
    print(f"{printable(args.scene)}: valid scene '{printable(scene.name)}': bearing {scene.bearing.designation}, "
          f"lubricant {scene.lubricant.name}, {len(scene.operating_points)} operating point(s)"
          + (f" sweeping {', '.join(scene.swept)}" if scene.swept else "")
          + f", fidelity {scene.fidelity.name}")
    return 0


def add_parser(sub: Any, common: Callable[[argparse.ArgumentParser], None]) -> None:
    """The ``check`` sub-command on ``sub`` (``common`` adds ``--format``)."""
    sp = sub.add_parser("check", help="validate a scene file")
    sp.add_argument("scene", help="scene .toml file")
    sp.add_argument("--set", action="append", metavar="KEY=VALUE",
                    help='override a scene value, e.g. --set operating.axial_load="6.5 kN" (repeatable)')
    common(sp)
    sp.set_defaults(func=command)
