"""The settings of one identification: the data it simulates and the training (all seeded)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from jointplay.common.errors import DescriptionError

MAX_SEED = 2**32 - 1
# How the network's residual weight can be chosen on validation (IdentifyConfig.residual_by).
RESIDUAL_CRITERIA = ("free-run", "closed-loop", "closed-loop-scene")
CLOSED_LOOP_CRITERIA = RESIDUAL_CRITERIA[1:]  # the candidates run as the controller
MAX_SCENE_MOTIONS = 16  # each costs seven closed-loop runs per model
# What drives the training and validation runs' reference motions (IdentifyConfig.base_motions).
BASE_MOTIONS = ("mixed", "scene-family")


@dataclass(frozen=True)
class IdentifyConfig:
    """Everything that decides the data and the training (all seeded by ``seed``)."""

    duration: float = 2.0  # s per trajectory
    n_train: int = 12
    n_validation: int = 3
    n_test: int = 3
    output_lags: int = 2
    input_lags: int = 2
    hidden: tuple[int, ...] = (13, 14)
    seed: int = 0
    kp: tuple[float, ...] = ()  # empty: DEFAULT_KP on every moving joint
    kd: tuple[float, ...] = ()
    torque_limit: tuple[float, ...] = ()  # empty: LIMIT_FACTOR x the scene's peak torques
    base_fraction: float = 0.5  # peak of the base excitation torques, x the limit
    # The training and validation runs' base motions: "mixed" (the scene's torques, random
    # multisines and steps at base_fraction of the limit, in turn) or "scene-family" (the
    # scene's torques, then the scene's torques at other amplitudes, rates and time shifts:
    # the motions the controller is judged on, not 60x harsher ones). The test runs keep
    # their families either way.
    base_motions: str = "mixed"
    input_fraction: float = 0.03  # peak of the added-torque excitation, x the limit
    transient: float = 0.05  # s at the start of each trajectory left out (journals settling)
    linear_path: bool = True  # a linear direct path beside the hidden layers
    # The network also sees the scheduling signals (jointplay.neural.model.scheduling): the ideal
    # robot's configuration and speed and the drive torque of the motion.
    scheduling: bool = False
    # With scheduling: the network's linear part is an LPV-ARX model (its input gain affine
    # in the scheduling signals, a bilinear part) rather than an ARX model, started at the
    # least-squares LPV-ARX fit, and its residual is weighed against that model.
    lpv_base: bool = False
    # The journals' eccentricities (ex, ey) at every clearance joint are measured outputs as
    # well (a bearing displacement sensor's signals): the contact state the deviation
    # dynamics switch with, for every model identified (network, ARX twin, LPV-ARX) and every
    # controller built on them.
    contact_outputs: bool = False
    # The hidden layers do not see the added torque: the model's gain from it is its linear
    # part's (the ARX or LPV-ARX fit, trained on), and the network corrects only the
    # response to the outputs' history and the scheduling signals. The controller inverts
    # that gain; a network's input gain, identified from small excitation, varies with the
    # state where the linear model's does not.
    linear_input_gain: bool = False
    # The operating range the training and validation runs span: each run is simulated on
    # the robot with one of these radial clearances (m, every clearance joint) and payload
    # masses (kg), cycling through every pair; empty: the scene's own. The test runs stay on
    # the scene's robot.
    clearances: tuple[float, ...] = ()
    payloads: tuple[float, ...] = ()
    # How the residual weight is chosen on validation: "free-run" (the free-run loss over
    # windows) or "closed-loop" (each candidate runs as the internal-model controller on the
    # validation runs' motions: jointplay.neural.study.closed_loop_choice) or "closed-loop-scene"
    # (the same, on motions of the scene's own drive-torque family: the scene's torques at
    # other amplitudes, rates and time shifts, never the scene's run itself).
    residual_by: str = "free-run"
    # Motions of the scene's family that "closed-loop-scene" runs each candidate on.
    scene_motions: int = 2
    one_step_iterations: int = 60
    multi_step_iterations: int = 30
    window: int = 200  # samples per free-run training window
    patience: int = 8
    workers: int = 0  # 0: one per core, at most 4

    def __post_init__(self) -> None:
        # numpy and torch take seeds from 0 to 2**32 - 1; anything else failed deep inside.
        if isinstance(self.seed, bool) or not isinstance(self.seed, int) \
                or not 0 <= self.seed <= MAX_SEED:
            raise DescriptionError("seed", f"must be a whole number from 0 to {MAX_SEED} "
                                   f"(2**32 - 1), got {self.seed!r}")
        if self.linear_input_gain and not self.linear_path:
            raise DescriptionError("linear_input_gain", "needs the linear direct path (drop "
                                   "--no-linear-path): without it the model has no input "
                                   "gain")
        if self.lpv_base and not (self.scheduling and self.linear_path):
            raise DescriptionError("lpv_base", "needs the scheduling signals and the linear "
                                   "direct path (--scheduling, without --no-linear-path)")
        if self.residual_by not in RESIDUAL_CRITERIA:
            raise DescriptionError("residual_by", "must be free-run, closed-loop or "
                                   "closed-loop-scene, got "
                                   f"{self.residual_by!r}")
        if self.base_motions not in BASE_MOTIONS:
            raise DescriptionError("base_motions", "must be mixed or scene-family, got "
                                   f"{self.base_motions!r}")
        if isinstance(self.scene_motions, bool) or not isinstance(self.scene_motions, int) \
                or not 1 <= self.scene_motions <= MAX_SCENE_MOTIONS:
            raise DescriptionError("scene_motions", "must be a whole number from 1 to "
                                   f"{MAX_SCENE_MOTIONS}, got {self.scene_motions!r}")
        if self.residual_by == "closed-loop" and self.n_validation < 2:
            raise DescriptionError("residual_by", "closed-loop needs a validation run whose "
                                   "motion is not the scene's own (the first validation run "
                                   "drives the scene's torques): give --validation 2 or more")
        for name, values in (("clearances", self.clearances), ("payloads", self.payloads)):
            if not all(isinstance(v, (int, float)) and math.isfinite(v) and v >= 0
                       and (v > 0 or name == "payloads") for v in values):
                kind = "positive" if name == "clearances" else "non-negative"
                raise DescriptionError(name, f"must be {kind} finite numbers, got "
                                       f"{list(values)}")



__all__ = ["BASE_MOTIONS", "CLOSED_LOOP_CRITERIA", "MAX_SCENE_MOTIONS", "RESIDUAL_CRITERIA",
           "IdentifyConfig"]
