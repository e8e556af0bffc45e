"""Draw the documentation's gallery: run each command that draws figures, with the settings the
gallery page shows, and copy its figures into docs/img/gallery/ at thumbnail size.

    python docs/gallery/draw.py            # every command (about 10 minutes on 2 cores)
    python docs/gallery/draw.py simulate   # one group: simulate compare control study sweep
                                           #            calibrate mechanism bench

tests/test_docs_gallery.py checks that the page lists exactly the figure files the commands
write and that each listed figure is here.
"""

from __future__ import annotations

import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
GALLERY = ROOT / "docs" / "img" / "gallery"
WIDTH = 900  # pixels: readable in the page, small in the repository

IDEAL_ARM = """
text = open("scenes/paper_4dof.toml").read().replace('kind = "clearance"', 'kind = "ideal"')
lines = [ln for ln in text.splitlines() if not ln.startswith(("ex2", "ey2", "ex3", "ey3"))]
open("ideal_arm.toml", "w").write("\\n".join(lines).replace("t_end = 2.0 ", "t_end = 0.2 "))
import numpy as np, jointplay as jp
scene = jp.default_scene()
arm = scene.with_robot(jp.ideal_counterpart(scene.robot)).with_run(t_end=0.2)
exact = jp.simulate(arm.with_run(rtol=1e-11, atol=1e-11),
                    parameters={"payload.mass": 2.3, "link2.com": 0.19})
tip = exact.tip_position + 1e-6 * np.random.default_rng(0).standard_normal((exact.t.size, 2))
np.savetxt("tip.csv", np.column_stack([exact.t, tip]), delimiter=",",
           header="time,tip_x,tip_y", comments="", fmt="%.17g")
"""

# Each group: shell commands run in a scratch folder holding scenes/, and the folder (in it)
# whose PNGs the group draws. The gallery page shows the same commands.
GROUPS: dict[str, tuple[list[str], list[str]]] = {
    "simulate": (["jointplay simulate --compare-ideal --t-end 0.5 --plot simulate --quiet",
                  "jointplay simulate scenes/paper_4dof_lubricated.toml --t-end 0.5 "
                  "--plot lubricated --quiet",
                  "jointplay simulate scenes/paper_4dof_wear.toml --t-end 0.5 --plot wear "
                  "--quiet"],
                 ["simulate", "lubricated", "wear"]),
    "compare": (["jointplay simulate --t-end 0.5 --out run.h5 --quiet",
                 "jointplay simulate --t-end 0.5 --set friction.mu=0.2 --out run_mu.h5 --quiet",
                 "jointplay compare run.h5 run_mu.h5 --out compared"],
                ["compared"]),
    "control": (["jointplay identify --preset paper --train 4 --validation 2 --test 2 "
                 "--duration 1.0 --iterations 20,5 --out model",
                 "jointplay control --model model --plot control_plots"],
                ["control_plots"]),
    "study": (["jointplay control-study --out study --seeds 2 --train 2 --validation 2 "
               "--test 1 --duration 0.6 --identify-iterations 20,5 --cases scene"],
              ["study"]),
    "sweep": (["jointplay sweep scenes/sweep_clearance.toml --out sweep --workers 2"],
              ["sweep/plots"]),
    "calibrate": ([f"python - <<'EOF'\n{IDEAL_ARM}\nEOF",
                   "jointplay calibrate ideal_arm.toml --measured tip.csv "
                   "--free payload.mass,link2.com --noise tip_x=1e-6,tip_y=1e-6 "
                   "--out calibration --profile-points 5"],
                  ["calibration"]),
    "mechanism": (["jointplay simulate scenes/slider_crank.toml --compare-ideal --plot mechanism "
                   "--quiet",
                   "jointplay sweep scenes/sweep_slider_crank.toml --out mechanism_sweep"],
                  ["mechanism", "mechanism_sweep"]),
    "bench": (["jointplay bench work-precision --out bench --t-end 0.1 --repeats 1 "
               "--methods bdf,rk4 --rtols 1e-4,1e-6,1e-8 --steps 4e-5,1e-5 --quiet",
               "jointplay bench fidelity --out bench --t-end 0.2 --quiet",
               "jointplay bench scaling --out bench --links 1-4 --structures clearance"],
              ["bench"]),
}


def _thumbnail(source: Path, target: Path) -> None:
    from PIL import Image

    with Image.open(source) as opened:
        image = opened.convert("RGB")
    if image.width > WIDTH:
        image = image.resize((WIDTH, round(image.height * WIDTH / image.width)),
                             Image.Resampling.LANCZOS)
    # 256 colours hold a line figure's anti-aliasing; the file is a third of the size
    image.quantize(colors=256, method=Image.Quantize.MEDIANCUT).save(target, optimize=True)


def draw(group: str) -> list[Path]:
    commands, folders = GROUPS[group]
    written = []
    with tempfile.TemporaryDirectory() as scratch:
        (Path(scratch) / "scenes").symlink_to(ROOT / "scenes")
        for command in commands:
            print(f"[{group}] {command.splitlines()[0]}", flush=True)
            subprocess.run(["bash", "-e", "-c", command], cwd=scratch, check=True)
        for folder in folders:
            for png in sorted((Path(scratch) / folder).glob("*.png")):
                if re.search(r"_joint(?!2\.)\d+\.png$", png.name):
                    continue  # one joint's figure stands for every joint's
                target = GALLERY / png.name
                if folder in ("lubricated", "wear") and (GALLERY / png.name).exists() \
                        and png.name not in ("film_force.png", "wear.png"):
                    continue  # the dry run's figures of the same name stand for these
                if folder == "mechanism" and png.name == "contact_force.png":
                    continue  # the arm's figure of the same name stands for the mechanism's
                _thumbnail(png, target)
                written.append(target)
    return written


def main(argv: list[str]) -> int:
    groups = argv or list(GROUPS)
    unknown = [g for g in groups if g not in GROUPS]
    if unknown:
        print(f"unknown group {unknown}; choose from {', '.join(GROUPS)}", file=sys.stderr)
        return 2
    GALLERY.mkdir(parents=True, exist_ok=True)
    for group in groups:
        for path in draw(group):
            print(f"  {path.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
