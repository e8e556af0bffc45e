"""How far the built-in scenes stay from the run-time stops (docs/reference/
limits-and-errors.md): the largest penetration as a fraction of the journal radius, and the largest
energy
balance residual as a fraction of the run's largest energy, per scene and integrator, beside
the bounds (``jointplay.common.limits.MAX_PENETRATION_FRACTION``, ``MAX_ENERGY_RESIDUAL``).

    python benchmarks/plausibility_margins.py

Prints a Markdown table; writes nothing.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from jointplay import load_scene, simulate
from jointplay.common.limits import MAX_ENERGY_RESIDUAL, MAX_PENETRATION_FRACTION

SCENES = Path(__file__).resolve().parent.parent / "scenes"
CASES = (("paper_4dof", ("bdf", "cvodes", "idas", "rk4", "radau")),
         ("paper_4dof_lubricated", ("bdf",)), ("paper_4dof_wear", ("bdf",)))


def margins(scene_name: str, integrator: str) -> tuple[float, float]:
    """(largest penetration / journal radius, largest |balance| / largest energy)."""
    scene = load_scene(SCENES / f"{scene_name}.toml").with_run(integrator=integrator)
    result = simulate(scene)
    radius = np.array([scene.robot.joints[j - 1].journal_radius
                       for j in result.clearance_joints])
    penetration = float(np.max(result.penetration / radius))
    energy = result.energy
    largest = max(float(np.max(np.abs(energy[key])))
                  for key in ("kinetic", "drive_work", "dissipated"))
    largest = max(largest, float(np.max(np.abs(energy["total"] - energy["total"][0]))))
    return penetration, float(np.max(np.abs(energy["balance"]))) / largest


def main() -> None:
    print("| scene | integrator | max penetration / journal radius | max energy residual / "
          "largest energy |")
    print("|---|---|---|---|")
    for scene_name, integrators in CASES:
        for integrator in integrators:
            penetration, residual = margins(scene_name, integrator)
            print(f"| {scene_name} | {integrator} | {penetration:.2g} | {residual:.2g} |")
    print(f"| bound (a run stops beyond it) | | {MAX_PENETRATION_FRACTION:g} | "
          f"{MAX_ENERGY_RESIDUAL:g} |")


if __name__ == "__main__":
    main()
