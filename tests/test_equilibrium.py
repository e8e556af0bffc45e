"""The resting start: each journal in static equilibrium in its bearing under gravity, found by
Newton's method on the compiled dynamics, checked against statics (each bearing carries the
weight of the links beyond it) and against a simulation that must not move."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from jointplay.common.errors import DescriptionError
from jointplay.scene.definition import default_scene
from jointplay.sim import Stepper, load_scene_model
from jointplay.sim.problem import _initial_state, _parameter_vector


def test_resting_journals_carry_the_weight_beyond_them() -> None:
    scene = default_scene().with_journals("resting")
    model = load_scene_model(scene)
    p = _parameter_vector(model, scene, None)
    x0 = _initial_state(model, scene, p)
    n = model.n_coordinates
    assert np.all(x0[n:] == 0.0)
    # The arm hangs straight down (q2 = -pi, q3 = 0): statics says joint j's bearing carries
    # the weight of every link from j on, straight up, with no sideways force.
    contact = model.contact(x0, p)
    robot = scene.robot
    value = dict(zip(model.parameters, p, strict=True))
    g = -value["gravity.y"]
    for i, j in enumerate(model.clearance_joints):
        # links j, j+1, ... and the payload at the tip (joint j joins link j-1 to link j)
        carried = g * (sum(value[f"link{k}.mass"] for k in range(j, len(robot.links) + 1))
                       + value.get("payload.mass", 0.0))
        assert contact["f_y"][i] == pytest.approx(carried, rel=1e-9)
        assert abs(contact["f_x"][i]) < 1e-9 * carried
        clearance = robot.joints[j - 1].bearing_radius - robot.joints[j - 1].journal_radius
        ey = x0[model.coordinates.index(f"ey{j}")]
        assert -clearance - 1e-6 < ey < -clearance  # below the centre, pressed into the wall
    # Every acceleration vanishes there (with the holding torques, here ~0: the arm hangs).
    acc = np.asarray(model.forward_dynamics(x0, np.zeros(len(model.torque_joints)), p)).ravel()
    assert np.max(np.abs(acc[n:])) < 1e-8


def test_resting_start_stays_at_rest_while_the_centred_start_falls() -> None:
    base = default_scene().with_run(t_end=0.02)
    resting = Stepper(base.with_journals("resting"))
    centred = Stepper(base)
    for _ in range(20):  # 20 ms under the scene's torques
        resting.step(np.zeros(2))
        centred.step(np.zeros(2))
    # Released at the centres, the journals fall and strike their bearings; resting, they
    # start in contact (recorded at t = 0, at zero speed) and stay in it: no impact after.
    assert [i for i in centred.impacts if i[0] > 0 and i[2] > 1e-3]
    assert [i[0] for i in resting.impacts] == [0.0, 0.0]
    assert all(i[2] == 0.0 for i in resting.impacts)


def test_resting_refuses_given_eccentricities_and_unknown_starts() -> None:
    scene = default_scene()
    with pytest.raises(DescriptionError, match=r"initial.journals.*one of centred, resting"):
        scene.with_journals("floating")
    moved = replace(scene, initial={**scene.initial, "ex2": 1e-6, "dq3": 0.1})
    with pytest.raises(DescriptionError, match=r"leave out .*dq3, ex2"):
        moved.with_journals("resting")
    assert scene.journals == "centred"  # the paper scene keeps its documented start


def test_a_sweep_tells_the_resting_start_from_the_centred() -> None:
    from jointplay.sweep.spec import _scene_fingerprint

    scene = default_scene()
    centred = _scene_fingerprint(scene)
    assert "journals" not in centred  # keys of centred starts stay as before
    assert _scene_fingerprint(scene.with_journals("resting")) == {**centred,
                                                                  "journals": "resting"}
