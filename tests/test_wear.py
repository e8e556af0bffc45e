"""Archard wear integrated in the compiled loop, against closed forms; its files.

The closed-form case: one link whose centre of mass sits on its joint, resting on the bottom
of its bearing under gravity (at the static penetration, so the normal force is m g from the
start) and spinning freely at a constant speed (no friction, no drive): the sliding speed is
w Rj, so V = k m g w Rj T / H; on the bearing the depth is Hertz's ellipse at the bottom, on
the journal it is uniform over whole turns. The damped case: impacts and rubbing on a bearing
that turns, against the integral of the run's own normal force and sliding speed, and the
wear's position in each surface's frame.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointplay import simulate
from jointplay.results.wear import WEAR_BINS
from jointplay.scene.definition import scene_from_dict

MASS, SPIN, RB, RJ, LENGTH = 2.0, 10.0, 10.0e-3, 9.97e-3, 12.0e-3
K_WEAR, HARDNESS, E, NU, G = 3.0e-4, 1.5e9, 207e9, 0.3, 9.81
TURNS = 3


def _stiffness() -> float:
    """Hertz's pin-in-hole K of the joint (clearance-physics reference form)."""
    sigma = 2 * (1 - NU**2) / E
    return 4 / (3 * sigma) * math.sqrt(RB * RJ / (RB - RJ))


def _static_penetration() -> float:
    return (MASS * G / _stiffness()) ** (1 / 1.5)


def _scene(**run: float) -> object:
    c = RB - RJ
    return scene_from_dict({
        "name": "spinning_journal",
        "robot": {
            "name": "spinning_journal",
            "links": [{"length": 0.2, "mass": MASS, "inertia": 0.01, "com": 0.0}],
            "joints": [{"kind": "clearance", "bearing_radius": RB, "journal_radius": RJ,
                        "bearing_E": E, "journal_E": E, "bearing_nu": NU, "journal_nu": NU,
                        "length": LENGTH}],
            "gravity": {"enabled": True, "vector": [0.0, -G]},
            "friction": {"law": "none"},
            "drive": {"enabled": False},
            "wear": {"model": "archard", "coefficient": K_WEAR, "hardness": HARDNESS},
        },
        "initial": {"q1": 0.0, "dq1": SPIN, "ex1": 0.0, "ey1": -(c + _static_penetration())},
        "run": {"t_end": TURNS * 2 * math.pi / SPIN, "output_step": 2 * math.pi / SPIN / 50,
                "rtol": 1e-9, "atol": 1e-9, **run},
    })


@pytest.fixture(scope="module")
def spinning():  # type: ignore[no-untyped-def]
    return simulate(_scene())


def _ellipse_share(x: np.ndarray) -> np.ndarray:
    x = np.clip(x, -1, 1)
    return 0.5 + (x * np.sqrt(1 - x**2) + np.arcsin(x)) / math.pi


def test_volume_is_archard_closed_form(spinning) -> None:  # type: ignore[no-untyped-def]
    duration = TURNS * 2 * math.pi / SPIN
    want = K_WEAR * MASS * G * SPIN * RJ * duration / HARDNESS
    assert spinning.wear.volume[0] == pytest.approx(want, rel=1e-9)
    # the run's own samples agree: normal force m g, sliding speed w Rj throughout
    assert np.allclose(spinning.normal_force[:, 0], MASS * G, rtol=1e-7)
    assert np.allclose(spinning.sliding_speed[:, 0], SPIN * RJ, rtol=1e-7)


def _turning_scene() -> object:
    """A turning bearing: link 1 spins at 20 rad/s about an ideal joint 1 and carries the
    bearing of joint 2; link 2 (the journal) turns the other way relative to it. No gravity,
    no drive; damped impacts (ce = 0.5) with friction (mu = 0.1) that decelerates sliding."""
    return scene_from_dict({
        "name": "turning_bearing",
        "robot": {
            "name": "turning_bearing",
            "links": [{"length": 0.2, "mass": 1.0, "inertia": 0.01, "com": 0.0},
                      {"length": 0.2, "mass": 1.0, "inertia": 0.004, "com": 0.1}],
            "joints": [{"kind": "ideal"},
                       {"kind": "clearance", "bearing_radius": RB, "journal_radius": RJ,
                        "bearing_E": E, "journal_E": E, "bearing_nu": NU, "journal_nu": NU,
                        "length": LENGTH}],
            "gravity": {"enabled": False},
            "contact": {"law": "lankarani-nikravesh", "restitution": 0.5, "exponent": 1.5},
            "friction": {"law": "coulomb", "mu": 0.1, "v0": 1e-4, "v1": 1e-2},
            "drive": {"enabled": False},
            "wear": {"model": "archard", "coefficient": K_WEAR, "hardness": HARDNESS},
        },
        "initial": {"q1": 0.0, "dq1": 20.0, "q2": 0.0, "dq2": -15.0},
        "run": {"t_end": 0.02, "output_step": 1e-6, "rtol": 1e-10, "atol": 1e-10},
    })


def test_damped_impacts_on_a_turning_bearing_wear_by_the_normal_force() -> None:
    """Damped, rubbing impacts on a bearing that turns: the worn volume is k/H times the
    integral of the normal force (damping included) times the sliding speed, taken here by
    the trapezoidal rule from the run's own samples every 1 us (to 1e-5; measured 1.1e-7);
    the elastic force K d^1.5 alone would give 0.75 % less (checked, so the test can tell).
    Each surface's wear sits where the contact was in that surface's own frame: the centroid
    of the bearing's depth is the F_n |v_t|-weighted mean contact angle in link 1's frame, the
    journal's in link 2's (to 1e-3 rad, measured 5e-5; in the ground's frame it would be
    0.18 rad off)."""
    from scipy.integrate import trapezoid

    result = simulate(_turning_scene())
    wear = result.wear
    assert wear is not None and len(result.impacts) >= 3
    assert not np.all(result.impacts.separated)  # impacts, then sustained rubbing contact
    rate = np.abs(result.sliding_speed[:, 0])
    normal = result.normal_force[:, 0]
    elastic = _stiffness() * np.maximum(result.penetration[:, 0], 0.0) ** 1.5
    want = K_WEAR / HARDNESS * trapezoid(normal * rate, result.t)
    elastic_only = K_WEAR / HARDNESS * trapezoid(elastic * rate, result.t)
    assert wear.volume[0] == pytest.approx(want, rel=1e-5)
    assert abs(elastic_only - want) > 100 * 1e-5 * want
    angle = np.arctan2(result.eccentricity[:, 0, 1], result.eccentricity[:, 0, 0])
    bins = (np.arange(WEAR_BINS) + 0.5) * 2 * math.pi / WEAR_BINS
    frames = {"bearing": result.q[:, 0], "journal": result.q[:, 0] + result.q[:, 1]}
    for surface, frame in frames.items():
        expected = np.angle(trapezoid(normal * rate * np.exp(1j * (angle - frame)), result.t))
        centroid = np.angle(np.sum(wear.depth(surface)[0] * np.exp(1j * bins)))
        assert abs(np.angle(np.exp(1j * (centroid - expected)))) < 1e-3, surface
    ground = np.angle(trapezoid(normal * rate * np.exp(1j * angle), result.t))
    bearing = np.angle(np.sum(wear.depth("bearing")[0] * np.exp(1j * bins)))
    assert abs(np.angle(np.exp(1j * (bearing - ground)))) > 0.1


def test_bearing_depth_is_hertz_ellipse_at_the_bottom(spinning) -> None:  # type: ignore[no-untyped-def]
    wear = spinning.wear
    sigma = 2 * (1 - NU**2) / E
    half_width = math.sqrt(4 * MASS * G * RB * RJ / (RB - RJ) * sigma / (math.pi * LENGTH))
    alpha = half_width / RB  # contact half-angle on the bearing
    width = 2 * math.pi / WEAR_BINS
    edges = np.arange(WEAR_BINS + 1) * width
    share = (_ellipse_share((edges[1:] - 1.5 * math.pi) / alpha)
             - _ellipse_share((edges[:-1] - 1.5 * math.pi) / alpha))
    want = wear.volume[0] * share / (RB * LENGTH * width)
    assert np.count_nonzero(want) >= 2  # the contact arc spans bins
    assert np.allclose(wear.bearing_depth[0], want, rtol=1e-7, atol=1e-9 * want.max())


def test_journal_depth_is_uniform_over_whole_turns(spinning) -> None:  # type: ignore[no-untyped-def]
    depth = spinning.wear.journal_depth[0]
    want = spinning.wear.volume[0] / (2 * math.pi * RJ * LENGTH)
    # pieces of half a bin resolve the passing contact ellipse to 1.4e-4 (measured)
    assert np.allclose(depth, want, rtol=5e-4)


def test_wear_needs_the_compiled_loop() -> None:
    from jointplay.common.errors import DescriptionError

    with pytest.raises(DescriptionError, match="integrator"):
        simulate(_scene(integrator="cvodes"))


def test_wear_files_round_trip(spinning, tmp_path) -> None:  # type: ignore[no-untyped-def]
    from jointplay.results.write import read_hdf5, write_csv, write_hdf5

    write_hdf5(spinning, tmp_path / "run.h5")
    back = read_hdf5(tmp_path / "run.h5")
    assert back.wear is not None
    np.testing.assert_array_equal(back.wear.bearing_depth, spinning.wear.bearing_depth)
    np.testing.assert_array_equal(back.wear.volume, spinning.wear.volume)
    paths = write_csv(spinning, tmp_path / "run.csv")
    assert tmp_path / "run.wear.csv" in paths
    lines = (tmp_path / "run.wear.csv").read_text().splitlines()
    assert lines[0] == "angle [rad],bearing_depth1 [m],journal_depth1 [m]"
    assert len(lines) == WEAR_BINS + 2 and lines[-1].startswith("volume [m^3],")
    table = np.loadtxt(lines[1:-1], delimiter=",")
    np.testing.assert_array_equal(table[:, 1], spinning.wear.bearing_depth[0])
    assert float(lines[-1].split(",")[1]) == spinning.wear.volume[0]


def test_polar_plot_and_summary(spinning, tmp_path) -> None:  # type: ignore[no-untyped-def]
    from jointplay.cli import summary
    from jointplay.results.plots import plot_result

    paths = plot_result(spinning, tmp_path)
    assert tmp_path / "wear.png" in paths and (tmp_path / "wear.png").stat().st_size > 10_000
    assert f"joint 1 wear: volume {spinning.wear.volume[0]:.4g} m^3" in summary(spinning)


def test_sweep_rows_carry_the_wear(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """The wear sweep's table has the wear columns, equal to a direct run of the case."""
    import tomllib
    from pathlib import Path

    from jointplay.sweep import run_sweep, sweep_from_dict

    path = Path(__file__).resolve().parent.parent / "scenes" / "sweep_wear.toml"
    data = tomllib.loads(path.read_text())
    data["run"] = {"t_end": 0.05}
    data["parameters"] = {"joint2.clearance": {"values": [3.0e-5]},
                          "friction.mu": {"values": [0.05]}}
    sweep = sweep_from_dict(data, source=str(path), base=path.parent)
    table = run_sweep(sweep, tmp_path / "sweep", workers=0, plots=False).table.to_pydict()
    direct = simulate(sweep.cases[0].scene)
    assert direct.wear is not None and direct.wear.volume[0] > 0
    assert table["wear_volume_joint2"][0] == direct.wear.volume[0]
    assert table["max_bearing_wear_depth_joint3"][0] == direct.wear.bearing_depth[1].max()
    assert table["wear_volume"][0] == direct.wear.volume.sum()
