"""The journals' eccentricities as measured outputs (identify --contact-outputs): they are the
clearance robot's own ex, ey coordinates, measuring them changes nothing else a run records,
the ideal robot's are 0, the noise case covers their sensors, and the controllers run on a
model that has them."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np
import pytest

from jointplay.common.errors import DescriptionError
from jointplay.neural.identify.pipeline import (
    IdentifyConfig,
    contact_joints,
    default_limits,
    inner_loop_for,
    output_names,
)
from jointplay.scene.definition import default_scene

DURATION = 0.3  # s: long enough for both journals to fall into contact (about 20 ms)


def test_contact_output_names_follow_the_others() -> None:
    names, units = output_names((2, 3), (2, 3))
    plain, plain_units = output_names((2, 3))
    assert names[: len(plain)] == plain and units[: len(plain)] == plain_units
    assert names[len(plain):] == ("ex2", "ey2", "ex3", "ey3")
    assert units[len(plain):] == ("m",) * 4
    assert contact_joints(names) == (2, 3) and contact_joints(plain) == ()


def _trajectories(contact: bool) -> list[Any]:
    from jointplay.neural.identify.trajectories import _plan, run_task

    scene = default_scene()
    config = IdentifyConfig(n_train=1, n_validation=0, n_test=0, duration=DURATION,
                            contact_outputs=contact, seed=5)
    tasks = _plan(scene, config, inner_loop_for(scene, (), ()), default_limits(scene))
    return [run_task(t) for t in tasks]


def test_eccentricities_are_measured_without_changing_the_run() -> None:
    """The same excitation with and without the eccentricity outputs: the other outputs are
    equal to the bit (measuring is reading the state), the reference's eccentricities are 0,
    and the measured ones start at the bearing's centre (where the scene releases the
    journals), reach contact, and stay within the clearance plus a Hertz penetration of under
    2 µm (30 µm radial clearance, 2 kg payload: 1.6 µm at the first impacts' peak, 0.4 µm
    resting, whereas a wrong coordinate would be off by the link's own motion, metres)."""
    plain, = _trajectories(False)
    measured, = _trajectories(True)
    n = plain.y.shape[1]
    assert measured.y.shape[1] == n + 4
    np.testing.assert_array_equal(measured.y[:, :n], plain.y)
    np.testing.assert_array_equal(measured.r[:, :n], plain.r)
    assert not np.any(measured.r[:, n:])
    clearance = 30e-6
    for j in range(2):
        ex, ey = measured.y[:, n + 2 * j], measured.y[:, n + 2 * j + 1]
        radius = np.hypot(ex, ey)
        assert radius[0] == 0.0
        assert clearance < radius.max() < clearance + 2e-6
        assert np.all(np.abs(radius[-50:] - clearance) < 1e-6)


def test_a_model_measuring_a_joint_without_play_is_refused() -> None:
    """A model that measures joint 3's journal, run on a robot whose joint 3 has no play:
    refused by name before any step, not an index error deep in the loop."""
    from types import SimpleNamespace

    from jointplay.neural.identify.pipeline import contact_index

    with_play = SimpleNamespace(coordinates=["q2", "q3", "ex2", "ey2", "ex3", "ey3"])
    assert contact_index(with_play, (3, 2)) == [4, 5, 2, 3]
    without = SimpleNamespace(coordinates=["q2", "q3", "ex2", "ey2"])
    with pytest.raises(DescriptionError, match=r"joint\(s\) \[3\], which have no clearance"):
        contact_index(without, (2, 3))


def test_contact_outputs_need_a_clearance_joint() -> None:
    """identify and control-study refuse the setting on a robot without play, naming the flag
    that gave it (else the settings key)."""
    from jointplay.cli.neural_args import check_identify_for
    from jointplay.neural.identify.config import IdentifyConfig
    from jointplay.scene.definition import ideal_counterpart

    scene = default_scene()
    rigid = scene.with_robot(ideal_counterpart(scene.robot))
    asked = IdentifyConfig(contact_outputs=True)
    for flag in ("--contact-outputs", "--identify-contact-outputs", None):
        given = {"identify.contact_outputs": flag} if flag else {}
        with pytest.raises(DescriptionError, match=r"no clearance joint") as err:
            check_identify_for(asked, rigid, given)
        assert err.value.field == (flag or "identify.contact_outputs")
    assert check_identify_for(asked, scene, {}).contact_outputs is True
    assert check_identify_for(IdentifyConfig(), rigid, {}).contact_outputs is False


def test_noise_case_covers_the_eccentricity_sensors() -> None:
    from jointplay.neural.control.imc_settings import ControllerSettings
    from jointplay.neural.study.cases import NOISE, case_list, declared, noise_levels

    scene = default_scene()
    plain = noise_levels(scene)
    levels = noise_levels(scene, (2, 3))
    assert levels[: len(plain)] == plain
    assert levels[len(plain):] == (NOISE["ex"],) * 4
    noisy = case_list(scene, ["noise"], (), 30e-6, (2, 3))[0]
    told = dict(declared(ControllerSettings(), scene, noisy).measurement_noise)
    assert told["ex2"] == told["ey3"] == NOISE["ex"] and told["q2"] == NOISE["q"]


def test_controllers_run_on_a_model_that_measures_the_contact_state() -> None:
    """An ARX model of the 14 outputs, fitted to one run, as the internal model: every
    controller runs to the end with all 14 outputs recorded, the open loop's eccentricity
    reaches the bearing (beyond the 30 µm clearance), and the baselines' runs do not depend
    on it being measured (their other outputs equal to the bit)."""
    from jointplay.neural.control.imc_settings import ControllerSettings
    from jointplay.neural.identify.linear_fit import fit_arx, segments
    from jointplay.neural.identify.pipeline import _context, _signal_names
    from jointplay.neural.study.comparison import LINEAR, NEURAL, compare

    scene = default_scene().with_run(t_end=DURATION)
    measured, = _trajectories(True)
    names = _signal_names((2, 3), (2, 3))
    config = IdentifyConfig(contact_outputs=True, duration=DURATION)
    inner = inner_loop_for(scene, (), ())
    arx = fit_arx(segments([measured], 50), names, 2, 2, scene.run.output_step)
    arx = replace(arx, context=_context(scene, config, inner, default_limits(scene)))
    controllers = ("open loop", "PD", "computed torque", LINEAR)
    result = compare(scene, arx, ControllerSettings(), arx=arx, controllers=controllers,
                     analyse=False)
    for name in controllers:
        run = result.runs[name]
        assert not run.diverged and run.y.shape == (scene.run.n_outputs + 1, 14), name
    assert NEURAL not in result.runs
    eccentricity = result.runs["open loop"].y[:, 10:]
    assert np.hypot(eccentricity[:, 0], eccentricity[:, 1]).max() > 30e-6
    plain_run, = _trajectories(False)
    plain_arx = replace(fit_arx(segments([plain_run], 50), _signal_names((2, 3)), 2, 2,
                                scene.run.output_step), context=arx.context)
    plain = compare(scene, plain_arx, ControllerSettings(), controllers=("open loop", "PD"),
                    analyse=False)
    for name in ("open loop", "PD"):
        np.testing.assert_array_equal(result.runs[name].y[:, :10], plain.runs[name].y)


def test_study_baselines_run_beside_models_that_measure_the_contact_state() -> None:
    """The study runs its baselines once per case on a stand-in for the model (they need
    only the inner loop's gains), beside internal models of either output set."""
    from jointplay.neural.control.imc_settings import ControllerSettings
    from jointplay.neural.study.comparison import compare
    from jointplay.neural.study.runs import _dummy_model

    scene = default_scene().with_run(t_end=0.05)
    result = compare(scene, _dummy_model(scene), ControllerSettings(),
                     controllers=("open loop", "PD"), analyse=False)
    assert result.runs["PD"].y.shape == (scene.run.n_outputs + 1, 10)
