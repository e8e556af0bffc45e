"""The calibration benchmark's cases: robot, excitation, truth, what is measured and what is free.

Each case is a problem a user could bring: a scene at the robot's catalogue values (what
``jointplay calibrate`` starts from), measured motion made by the independent reference
(reference.py) at the case's true values, and the parameters to free. The truths lie within
+-50 % of the catalogue values (drawn with the case's seed where not given). ``noise`` is
the standard deviation the benchmark adds to each measured column; ``noise_stated`` says
whether the calibration is told it (``--noise``) or must estimate it.

Excitations of the paper arm: the paper scene's (4 and 2 N m at 1 Hz, "default"), a slow one
(0.6 Hz), a fast one (1.7 Hz, other amplitudes), and two multi-sines (three and two tones
per joint; five and three).
"""

from __future__ import annotations

import math
import os
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from reference import SineTerm, resolved_robot, torque_expression

HERE = Path(__file__).resolve().parent
REPOSITORY = HERE.parents[1]
DATA = HERE / "data"
PAPER_ROBOT = REPOSITORY / "runtime" / "robots" / "paper_4dof.toml"
THREE_LINK_ROBOT = HERE / "robots" / "three_link.toml"
ONE_CLEARANCE_ROBOT = HERE / "robots" / "paper_one_clearance.toml"
TIP = ("tip_x", "tip_y")
TIP_NOISE = 1e-6  # m
ANGLE_NOISE = 5e-6  # rad
# The paper scene's integration settings (scenes/paper_4dof.toml): the calibration fits at
# these, tightened by its own factor.
RUN = {"integrator": "bdf", "rtol": 2.0e-6, "atol": 3.0e-7}

Torques = dict[int, tuple[SineTerm, ...]]
DEFAULT: Torques = {2: (SineTerm(4.0, 1.0),), 3: (SineTerm(2.0, 1.0),)}
SLOW: Torques = {2: (SineTerm(3.0, 0.6),), 3: (SineTerm(1.5, 0.6, 0.8),)}
FAST: Torques = {2: (SineTerm(5.0, 1.7),), 3: (SineTerm(2.5, 1.7, 1.2),)}
MULTISINE: Torques = {2: (SineTerm(3.0, 0.8), SineTerm(1.2, 2.3, 0.4), SineTerm(0.6, 4.1, 1.0)),
             3: (SineTerm(1.5, 1.1, 0.3), SineTerm(0.8, 2.9, 2.0))}
MULTISINE_B: Torques = {2: (SineTerm(2.5, 0.5, 1.5), SineTerm(1.5, 1.9), SineTerm(0.8, 3.3, 0.7)),
               3: (SineTerm(1.8, 0.7), SineTerm(0.6, 2.6, 2.5), SineTerm(0.3, 5.2))}
# Moderate swings (q2 +-0.4, q3 +-0.7, q4 +-0.9 rad about the start): larger torques flip the
# hand over and the driven triple pendulum turns chaotic, not an experiment one would run.
THREE_LINK_TORQUES: Torques = {2: (SineTerm(2.0, 0.9), SineTerm(0.6, 2.1, 0.5)),
                               3: (SineTerm(0.8, 1.3, 0.9),),
                               4: (SineTerm(0.25, 1.7, 2.1), SineTerm(0.1, 3.1))}
HANGING = {"q2": -math.pi}  # the paper arm's start: links 2-4 hanging straight down
PAPER_FREE = ("joint2.clearance", "joint3.clearance", "friction.mu")


@dataclass(frozen=True)
class Case:
    name: str
    why: str
    robot_file: Path
    torques: Torques
    free: tuple[str, ...]
    columns: tuple[str, ...]
    noise_stated: bool
    truth: dict[str, float] = field(default_factory=dict)  # given truths
    draw_seed: int | None = None  # the free parameters not in ``truth`` are drawn with it
    initial: dict[str, float] = field(default_factory=lambda: dict(HANGING))
    t_end: float = 1.5
    output_step: float = 2e-3

    def robot_table(self) -> dict[str, Any]:
        with open(self.robot_file, "rb") as fh:
            return tomllib.load(fh)

    def noise(self) -> dict[str, float]:
        return {c: TIP_NOISE if c in TIP else ANGLE_NOISE for c in self.columns}

    def true_values(self) -> dict[str, float]:
        """Every free parameter's true value: given, or drawn uniformly within +-50 % of the
        robot's catalogue value with the case's seed (in the order of ``free``)."""
        nominal = catalogue_values(self.robot_table(), self.free)
        rng = np.random.default_rng(self.draw_seed)
        values = {}
        for name in self.free:
            draw = nominal[name] * (1.0 + rng.uniform(-0.5, 0.5))
            values[name] = self.truth.get(name, draw) if self.draw_seed is not None \
                else self.truth[name]
        return values

    def scene_text(self, scene_folder: Path) -> str:
        """The case's scene file: the robot at its catalogue values, the case's torques,
        start and run (the calibration starts from this scene's values)."""
        robot = Path(_relative(self.robot_file, scene_folder)).as_posix()
        lines = [f'# Calibration benchmark case "{self.name}"; written by '
                 "benchmarks/calibration_cases/generate.py, do not edit.",
                 f'name = "{self.name.replace("-", "_")}"',
                 f'description = "{self.why.splitlines()[0][:200]}"',
                 f'robot = "{robot}"', "", "[torques]"]
        lines += [f'joint{j} = "{torque_expression(terms)}"' for j, terms in
                  sorted(self.torques.items())]
        lines += ["", "[initial]"] + [f"{k} = {v!r}" for k, v in self.initial.items()]
        lines += ["", "[run]", f"t_end = {self.t_end!r}", f"output_step = {self.output_step!r}",
                  f'integrator = "{RUN["integrator"]}"', f"rtol = {RUN['rtol']!r}",
                  f"atol = {RUN['atol']!r}", ""]
        return "\n".join(lines)


def _relative(path: Path, start: Path) -> str:
    return os.path.relpath(path, start)


def catalogue_values(robot: dict[str, Any], names: tuple[str, ...]) -> dict[str, float]:
    """The robot file's value of each parameter name (``jointN.clearance``: Rb - Rj)."""
    values = {}
    for name in names:
        group, key = name.split(".", 1)
        if group.startswith("joint"):
            joint = robot["joints"][int(group[5:]) - 1]
            values[name] = float(joint["bearing_radius"]) - float(joint["journal_radius"]) \
                if key == "clearance" else float(joint[key])
        elif group.startswith("link"):
            values[name] = float(robot["links"][int(group[4:]) - 1][key])
        else:
            values[name] = float(robot[group][key])
    return values


def true_robot(case: Case) -> dict[str, Any]:
    return resolved_robot(case.robot_table(), case.true_values())


CASES = (
    Case("paper-default-tip", "The paper scene's excitation, truths drawn within +-50 %, tip "
         "measured, noise stated.", PAPER_ROBOT, DEFAULT, PAPER_FREE, TIP, True, draw_seed=101),
    Case("paper-exchange-trap", "The paper scene's excitation, 2 s at 1 ms, unequal clearances "
         "(joint 3's 1.7 times joint 2's) and a higher friction, tip measured, noise not stated: "
         "a fit from the scene's values can land on the exchanged clearances.", PAPER_ROBOT,
         DEFAULT, PAPER_FREE, TIP, False,
         truth={"joint2.clearance": 21.5e-6, "joint3.clearance": 36.5e-6, "friction.mu": 0.07},
         t_end=2.0, output_step=1e-3),
    Case("paper-slow-angles", "A slow excitation (0.6 Hz), truths drawn, joint angles q2, q3 "
         "measured, noise not stated.", PAPER_ROBOT, SLOW, PAPER_FREE, ("q2", "q3"), False,
         draw_seed=103),
    Case("paper-fast-tip", "A fast excitation (5 and 2.5 N m at 1.7 Hz), unequal clearances "
         "and a lower friction, tip measured, noise not stated.", PAPER_ROBOT, FAST,
         PAPER_FREE, TIP, False,
         truth={"joint2.clearance": 38.0e-6, "joint3.clearance": 24.0e-6, "friction.mu": 0.032}),
    Case("paper-fast-angles", "The fast excitation and truths of paper-fast-tip, joint angles "
         "measured, noise not stated.", PAPER_ROBOT, FAST, PAPER_FREE, ("q2", "q3"), False,
         truth={"joint2.clearance": 38.0e-6, "joint3.clearance": 24.0e-6, "friction.mu": 0.032}),
    Case("paper-multisine-both", "A multi-sine excitation (three and two tones), truths drawn, "
         "tip and joint angles measured, noise stated.", PAPER_ROBOT, MULTISINE, PAPER_FREE,
         (*TIP, "q2", "q3"), True, draw_seed=105),
    Case("paper-multisine-b-tip", "Another multi-sine (three tones per joint), truths drawn, "
         "tip measured, noise not stated.", PAPER_ROBOT, MULTISINE_B, PAPER_FREE, TIP, False,
         draw_seed=106),
    Case("paper-one-clearance", "The paper arm with joint 3 ideal: one clearance joint, the "
         "slow excitation, truths drawn, tip measured, noise stated.", ONE_CLEARANCE_ROBOT,
         SLOW, ("joint2.clearance", "friction.mu"), TIP, True, draw_seed=107),
    Case("three-link-tip", "A second arm (three moving links, clearance at the shoulder and "
         "the wrist, other lengths, masses and materials), truths drawn, tip measured, noise "
         "not stated.", THREE_LINK_ROBOT, THREE_LINK_TORQUES,
         ("joint2.clearance", "joint4.clearance", "friction.mu"), TIP, False, draw_seed=108,
         initial={"q2": -math.pi, "q3": 0.4, "q4": -0.3}),
    Case("three-link-both", "The second arm, other truths drawn, tip and the three joint angles "
         "measured, noise stated.", THREE_LINK_ROBOT, THREE_LINK_TORQUES,
         ("joint2.clearance", "joint4.clearance", "friction.mu"), (*TIP, "q2", "q3", "q4"),
         True, draw_seed=109, initial={"q2": -math.pi, "q3": 0.4, "q4": -0.3}),
    Case("paper-stiffness-inseparable", "Not separable: joint 2's bearing and journal Young's "
         "moduli enter the motion only through the contact stiffness K = 4 / (3 (sigma_b + "
         "sigma_j)) sqrt(Rb Rj / c), i.e. through the sum of the two compliances sigma = "
         "(1 - nu^2) / E, so the data determine that sum and not the two moduli (an honest "
         "calibration reports them not determined). Default excitation, tip and angles, noise "
         "stated.", PAPER_ROBOT, DEFAULT,
         ("joint2.bearing_E", "joint2.journal_E", "friction.mu"), (*TIP, "q2", "q3"), True,
         draw_seed=110),
)
INSEPARABLE = {"paper-stiffness-inseparable": ("joint2.bearing_E", "joint2.journal_E")}


def by_name(names: list[str] | None) -> list[Case]:
    if not names:
        return list(CASES)
    known = {c.name: c for c in CASES}
    unknown = [n for n in names if n not in known]
    if unknown:
        raise SystemExit(f"unknown case {unknown[0]!r}; cases: {', '.join(known)}")
    return [known[n] for n in names]
