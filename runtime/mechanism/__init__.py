"""Mechanisms: trees of bodies with cut clearance joints (the slider-crank, the four-bar).

A mechanism file (docs/reference/mechanism-file.md) is read by :func:`load_mechanism_scene`;
:func:`simulate_mechanism` runs it on its compiled model (derived and compiled on first use,
then cached) with the serial arms' integrator, contact laws and accuracy check.
"""

from __future__ import annotations

from collections.abc import Mapping

from jointplay.mechanism.description import Mechanism, MechanismScene
from jointplay.mechanism.model import MechanismModel, model_for
from jointplay.mechanism.reading import is_mechanism_file, load_mechanism_scene
from jointplay.mechanism.simulate import MechanismResult


def simulate_mechanism(scene: MechanismScene, *, parameters: Mapping[str, float] | None = None,
                       compare_ideal: bool = False, verify: bool = False,
                       model: MechanismModel | None = None) -> MechanismResult:
    """Simulate a mechanism scene and return its samples and located impacts.

    Parameters
    ----------
    scene : MechanismScene
        The mechanism and its run settings (:func:`load_mechanism_scene`).
    parameters : mapping of str to float, optional
        Numbers changed by name (``{"friction.mu": 0.02}``,
        ``{"slider_pin.journal_radius": 10.4e-3}``); never recompiles.
    compare_ideal : bool
        Also solve the ideal mechanism (every clearance joint ideal) at the same times
        (``result.ideal``).
    verify : bool
        Run the scene again at tolerances 10x tighter and state the accuracy
        (``result.accuracy``).
    model : MechanismModel, optional
        The compiled model (default: derived and compiled on first use, then cached).

    Returns
    -------
    MechanismResult
        The samples, the located impacts and the energies.

    Examples
    --------
    >>> from importlib.resources import files
    >>> import jointplay
    >>> path = files("jointplay.scenes") / "slider_crank.toml"
    >>> scene = jointplay.load_mechanism_scene(path).with_run(t_end=0.004)
    >>> result = jointplay.simulate_mechanism(scene, compare_ideal=True)
    >>> sorted(result.ideal), len(result.t) > 1
    (['acceleration', 'driving_torque', 'x'], True)
    """
    from jointplay.mechanism.accuracy import with_accuracy
    from jointplay.mechanism.simulate import simulate_mechanism as run

    if parameters:
        scene = scene.with_mechanism(scene.mechanism.with_values(dict(parameters)))
    model = model or model_for(scene.mechanism)
    result = run(scene, model=model, compare_ideal=compare_ideal)
    return with_accuracy(result, scene, model) if verify else result


__all__ = ["Mechanism", "MechanismModel", "MechanismResult", "MechanismScene",
           "is_mechanism_file", "load_mechanism_scene", "model_for", "simulate_mechanism"]
