"""Contact summaries come from the contact-phase table, never from the output samples.

The phase tables here are built by hand with known values (the located values themselves
are the simulator's to produce and to check against closed forms).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from test_output import make_result

from jointplay.cli import contact_lines
from jointplay.results.contacts import joint_contact, joint_contacts, overall
from jointplay.results.records import Impacts, SimulationResult


@pytest.fixture(scope="module")
def result() -> SimulationResult:
    return make_result(n=400, ideal=False)


def onsets_only(result: SimulationResult, integrator: str) -> SimulationResult:
    i = result.impacts
    return dataclasses.replace(result, integrator=integrator,
                               impacts=Impacts(i.time, i.joint, i.speed, i.eccentricity))


def test_located_values_come_from_the_table(result: SimulationResult) -> None:
    imp = result.impacts
    for k, joint in enumerate((2, 3)):
        rows = imp.for_joint(joint)
        c = joint_contact(result, k)
        assert c.located and c.note is None
        assert (c.joint, c.impacts) == (joint, len(rows))
        top = int(np.argmax(rows.peak_force))
        assert (c.peak_force, c.peak_force_time) == (rows.peak_force[top],
                                                     rows.peak_force_time[top])
        deep = int(np.argmax(rows.max_penetration))
        assert (c.max_penetration, c.max_penetration_time) == (
            rows.max_penetration[deep], rows.max_penetration_time[deep])
        fast = int(np.argmax(rows.speed))
        assert (c.max_approach_speed, c.max_approach_speed_time) == (rows.speed[fast],
                                                                     rows.time[fast])
        assert c.sampled_peak_force == result.normal_force[:, k].max()
        assert c.sampled_peak_force < c.peak_force  # the samples miss the peak


def test_the_located_peak_is_reported_even_where_samples_are_far_lower(
        result: SimulationResult) -> None:
    """A table peak 5x the largest sample (a brief impact between two samples) is the peak."""
    i = result.impacts
    peak = i.peak_force.copy()
    peak[3] = 5.0 * result.normal_force.max()
    brief = dataclasses.replace(result, impacts=dataclasses.replace(i, peak_force=peak))
    c = joint_contact(brief, result.clearance_joints.index(int(i.joint[3])))
    assert c.peak_force == peak[3] and c.peak_force_time == i.peak_force_time[3]


@pytest.mark.parametrize("integrator", ["rk4", "radau", "cvodes"])
def test_not_located_is_nan_with_a_note(result: SimulationResult, integrator: str) -> None:
    bare = onsets_only(result, integrator)
    for c in joint_contacts(bare):
        assert math.isnan(c.peak_force) and math.isnan(c.max_penetration)
        assert math.isnan(c.peak_force_time) and not c.located
        assert c.note is not None and c.note.startswith("not located")
        assert (integrator in c.note) == (integrator != "cvodes")
        assert c.impacts > 0 and c.max_approach_speed > 0  # onset columns still count
    # One phase not located is enough: the unknown one could be the largest.
    i = result.impacts
    partial = i.peak_force.copy()
    partial[0] = np.nan
    mixed = dataclasses.replace(result, impacts=dataclasses.replace(i, peak_force=partial))
    k = result.clearance_joints.index(int(i.joint[0]))
    assert math.isnan(joint_contact(mixed, k).peak_force)


def test_no_impacts(result: SimulationResult) -> None:
    empty = Impacts(np.zeros(0), np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros((0, 2)))
    apart = dataclasses.replace(result, impacts=empty, normal_force=0.0 * result.normal_force,
                                penetration=-np.abs(result.penetration) - 1e-9)
    c = joint_contact(apart, 0)
    assert c.located and c.impacts == 0
    assert (c.peak_force, c.max_penetration) == (0.0, 0.0)
    assert math.isnan(c.max_approach_speed)
    # In contact at the samples, but no phase recorded: not located, never 0.
    touching = dataclasses.replace(result, impacts=empty)
    c = joint_contact(touching, 0)
    assert not c.located and math.isnan(c.peak_force) and "without a recorded onset" in c.note


def test_overall() -> None:
    assert overall([1.0, 3.0]) == 3.0
    assert math.isnan(overall([1.0, math.nan]))
    assert overall([]) == 0.0


def test_summary_lines(result: SimulationResult) -> None:
    text = "\n".join(contact_lines(result))
    c = joint_contact(result, 0)
    assert f"peak normal force {c.peak_force:.4g} N at {c.peak_force_time:.7g} s" in text
    assert f"max penetration {c.max_penetration * 1e6:.4g} um" in text
    assert "(located)" in text and "sampled" not in text
    assert f"joint 2: {c.impacts} impacts, largest approach speed" in text
    bare = "\n".join(contact_lines(onsets_only(result, "rk4")))
    assert "(located)" not in bare and "peak normal force and max penetration not located" in bare
    assert "fixed-step rk4" in bare
    # The sampled maximum is shown only under a label that says what it is.
    for line in bare.splitlines():
        if f"{c.sampled_peak_force:.4g} N" in line:
            assert "sampled every 2.506 ms (not the peak)" in line
