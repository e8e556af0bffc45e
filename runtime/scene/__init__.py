"""Scenes: a robot, the effects it calls for, drive torques, an initial state and run settings.

:mod:`.definition` reads and validates scene files, :mod:`.initial` their initial state,
:mod:`.run_settings` their ``[run]`` table;
:mod:`.expressions` and :mod:`.tables` hold the drive torques
(restricted expressions and CSV tables, never executed as code).
"""

from jointplay.scene.definition import (
    RunSettings,
    Scene,
    default_scene,
    ideal_counterpart,
    load_scene,
    scene_from_dict,
)

__all__ = ["RunSettings", "Scene", "default_scene", "ideal_counterpart", "load_scene",
           "scene_from_dict"]
