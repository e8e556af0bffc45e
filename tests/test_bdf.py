"""The compiled BDF integrator (run.integrator = "bdf"): located contact phases."""

from __future__ import annotations

import numpy as np

from jointplay.scene import default_scene
from jointplay.sim import simulate


def _bdf(**run: object):  # type: ignore[no-untyped-def]
    return default_scene().with_run(integrator="bdf", t_end=0.006, **run)


def test_located_peaks_do_not_depend_on_the_output_step() -> None:
    """The peak of the first impact is located on the dense output, so a 1 ms and a 1 us
    output grid report the same value (to 1e-6 relative), and it is above every sample."""
    coarse = simulate(_bdf(output_step=1e-3))
    fine = simulate(_bdf(output_step=1e-6))
    assert len(coarse.impacts) >= 3
    np.testing.assert_allclose(coarse.impacts.peak_force[:3], fine.impacts.peak_force[:3],
                               rtol=1e-6)
    np.testing.assert_allclose(coarse.impacts.max_penetration[:3],
                               fine.impacts.max_penetration[:3], rtol=1e-6)
    for k, joint in enumerate(fine.clearance_joints):
        rows = fine.impacts.joint == joint
        assert np.max(fine.impacts.peak_force[rows]) >= np.max(fine.normal_force[:, k])
        assert np.max(fine.impacts.max_penetration[rows]) >= np.max(fine.penetration[:, k])


def test_bdf_follows_cvodes_through_the_first_impacts() -> None:
    """Same scene, same tolerances: onset times and tip path agree with CVODES."""
    a = simulate(_bdf(rtol=1e-8, atol=1e-8))
    b = simulate(default_scene().with_run(integrator="cvodes", t_end=0.006, rtol=1e-8,
                                          atol=1e-8))
    np.testing.assert_allclose(a.impacts.time[:4], b.impacts.time[:4], atol=1e-6)
    np.testing.assert_allclose(a.impacts.speed[:4], b.impacts.speed[:4], rtol=1e-3)
    assert np.max(np.abs(a.tip_position - b.tip_position)) < 1e-6
    assert bool(np.all(a.impacts.separated[:4]))
    assert np.all((a.impacts.restitution[:4] > 0.85) & (a.impacts.restitution[:4] < 0.95))
