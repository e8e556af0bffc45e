"""Robot descriptions: the typed description a user writes (:mod:`.description`), reading it
from TOML, dictionaries and flags (:mod:`.reading`), its validation (:mod:`.validation`), and
its split into the compile-time :class:`~jointplay.robot.structure.Structure` and the run-time
parameters (:mod:`.structure`), and those parameters by name (:mod:`.parameters`)."""

from jointplay.robot.description import (
    CONTACT_LAWS,
    CONTACT_STIFFNESSES,
    FRICTION_LAWS,
    FRICTION_RAMPS,
    LUBRICATION_MODELS,
    MAX_LINKS,
    WEAR_MODELS,
    Contact,
    Friction,
    Gravity,
    Joint,
    Link,
    Lubrication,
    Robot,
    Wear,
    canonical_json,
    uniform_chain,
    with_parameters,
)
from jointplay.robot.reading import (
    load_robot,
    parse_index_list,
    robot_from_dict,
    robot_from_flags,
)
from jointplay.robot.structure import (
    JOINT_KINDS,
    Coordinate,
    JointKind,
    Parameter,
    Structure,
    coordinate_layout,
    parameter_layout,
)
from jointplay.robot.validation import validate

__all__ = [
    "CONTACT_LAWS",
    "CONTACT_STIFFNESSES",
    "FRICTION_LAWS",
    "FRICTION_RAMPS",
    "JOINT_KINDS",
    "LUBRICATION_MODELS",
    "MAX_LINKS",
    "WEAR_MODELS",
    "Contact",
    "Coordinate",
    "Friction",
    "Gravity",
    "Joint",
    "JointKind",
    "Link",
    "Lubrication",
    "Parameter",
    "Robot",
    "Structure",
    "Wear",
    "canonical_json",
    "coordinate_layout",
    "load_robot",
    "parameter_layout",
    "parse_index_list",
    "robot_from_dict",
    "robot_from_flags",
    "uniform_chain",
    "validate",
    "with_parameters",
]
