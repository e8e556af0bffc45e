"""jointplay: dynamics and control of planar serial robots with revolute-joint clearance.

The flat public API. This package is the runtime: it loads and evaluates generated models and
never imports sympy. Deriving new models lives in :mod:`jointplay.derive`.
"""

from jointplay import _moved

# Imported first (after _moved, which imports nothing heavy): in the `jointplay` program,
# Ctrl-C while the rest imports is one line and exit 130 (see interrupts.guard_imports).
from jointplay.common import interrupts as _interrupts  # noqa: F401

# isort: split
# Then, in `jointplay simulate ... --plot` only, the process that draws the figures starts,
# so that it imports matplotlib while this one imports the rest (figure_process.start_early).
from jointplay.common import figure_process as _figure_process  # noqa: F401

# isort: split
from jointplay.common.errors import (
    BuildError,
    DescriptionError,
    DescriptionErrors,
    GeneratedCodeError,
    JointplayError,
    SimulationError,
)
from jointplay.mechanism import (
    MechanismResult,
    MechanismScene,
    load_mechanism_scene,
    simulate_mechanism,
)
from jointplay.results.accuracy import Accuracy
from jointplay.results.records import Impacts, SimulationResult
from jointplay.results.solution import DenseSolution
from jointplay.results.write import read
from jointplay.robot import (
    Contact,
    Friction,
    Gravity,
    Joint,
    Link,
    Robot,
    load_robot,
    robot_from_dict,
    robot_from_flags,
    uniform_chain,
    with_parameters,
)
from jointplay.robot.robotio import robot_to_toml
from jointplay.robot.structure import Coordinate, Parameter, Structure
from jointplay.scene.definition import (
    RunSettings,
    Scene,
    default_scene,
    ideal_counterpart,
    load_scene,
    scene_from_dict,
)
from jointplay.sim import Stepper, load_scene_model, simulate
from jointplay.store.build import cache_root, compile_source
from jointplay.store.lookup import generated_folder, model_for
from jointplay.store.model import FastFunction, Model, load_model

# isort: split
# After the interrupt guard, as every other import here.
from jointplay.calibration import CalibrationOptions, CalibrationResult, calibrate

__version__ = "0.1.0"

_moved.install()

__all__ = [
    "Accuracy",
    "BuildError",
    "CalibrationOptions",
    "CalibrationResult",
    "Contact",
    "Coordinate",
    "DenseSolution",
    "DescriptionError",
    "DescriptionErrors",
    "FastFunction",
    "Friction",
    "GeneratedCodeError",
    "Gravity",
    "Impacts",
    "Joint",
    "JointplayError",
    "Link",
    "MechanismResult",
    "MechanismScene",
    "Model",
    "Parameter",
    "Robot",
    "RunSettings",
    "Scene",
    "SimulationError",
    "SimulationResult",
    "Stepper",
    "Structure",
    "__version__",
    "cache_root",
    "calibrate",
    "compile_source",
    "default_robot",
    "default_scene",
    "generated_folder",
    "ideal_counterpart",
    "load_mechanism_scene",
    "load_model",
    "load_robot",
    "load_scene",
    "load_scene_model",
    "model_for",
    "read",
    "robot_from_dict",
    "robot_from_flags",
    "robot_to_toml",
    "scene_from_dict",
    "simulate",
    "simulate_mechanism",
    "uniform_chain",
    "with_parameters",
]


def default_robot() -> Robot:
    """The built-in default robot: the paper's 4-link arm with clearance at joints 2 and 3.

    Returns
    -------
    Robot
        The robot of ``robots/paper_4dof.toml`` (shipped with the package), as
        :func:`load_robot` reads it.
    """
    from importlib.resources import files

    return load_robot(str(files("jointplay") / "robots" / "paper_4dof.toml"))
