"""The figures of a real run: every journal orbit is drawn from the run's dense output on
every path (simulate with and without the accuracy check, ``plot``, ``compare``, the API), so
the drawn orbit never leaves the clearance by more than the located maximum penetration; and
the labels and marks of the figures that once misled a reader."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from jointplay.cli import main
from jointplay.common import figure_process
from jointplay.common import figures as figure_module
from jointplay.common.figures import ORBIT_GID
from jointplay.results.contacts import joint_contact
from jointplay.results.records import SimulationResult

# The short run of the paper scene: its first impact burst (3.5 to 10 ms) and some settling.
T_END = 0.05
# How far the drawn orbit may pass the clearance beyond the located maximum penetration (m):
# the dense output is within the run's tolerances, far below this.
ORBIT_SLACK = 0.1e-6


@pytest.fixture
def drawn(monkeypatch: pytest.MonkeyPatch) -> list[Any]:
    """Every figure saved while the test runs, in order (the data a reader would see)."""
    figures: list[Any] = []
    original = figure_module.png_bytes

    def keep(fig: Any, **kwargs: Any) -> bytes:
        figures.append(fig)
        return original(fig, **kwargs)

    monkeypatch.setattr(figure_module, "png_bytes", keep)
    monkeypatch.setattr(figure_module, "WORKERS", 1)  # drawn in this process, not in a worker
    monkeypatch.setattr(figure_process, "ENABLED", False)  # nor in a figure process
    return figures


def orbit_lines(figures: list[Any]) -> dict[str, Any]:
    """The drawn orbit lines by gid (``orbit``, or ``orbit:LABEL`` in a comparison) and the
    figure title they sit under, as ``{gid: [(title, line), ...]}``."""
    lines: dict[str, Any] = {}
    for fig in figures:
        for ax in fig.axes:
            for line in ax.get_lines():
                gid = line.get_gid()
                if gid and gid.split(":")[0] == ORBIT_GID:
                    lines.setdefault(gid, []).append((ax.get_title(), line))
    return lines


def assert_orbits_bounded(result: SimulationResult, lines: list[tuple[str, Any]]) -> None:
    """One drawn orbit per clearance joint, each from the dense output of the run, with
    max |e| <= c + located maximum penetration + ORBIT_SLACK and reaching c (it touched)."""
    assert len(lines) == len(result.clearance_joints)
    for k, joint in enumerate(result.clearance_joints):
        line = next(ln for t, ln in lines if t.endswith(f"joint {joint}")
                    or f"joint {joint} " in t)
        assert "dense output of the bdf run" in line.get_label(), line.get_label()
        x, y = (np.asarray(v, dtype=float) * 1e-6 for v in line.get_data())
        reach = float(np.max(np.hypot(x, y)))
        contact = joint_contact(result, k)
        assert contact.located and contact.impacts > 0
        c = float(result.radial_clearance[k])
        assert reach <= c + contact.max_penetration + ORBIT_SLACK, (joint, reach, c,
                                                                    contact.max_penetration)
        assert reach >= c, (joint, reach, c)


def _read(path: Path) -> SimulationResult:
    from jointplay.results.look import read_result

    return read_result(path)


@pytest.mark.parametrize("verify", [[], ["--no-verify"]])  # [] checks: it is affordable
def test_simulate_draws_orbits_from_the_dense_output(
        verify: list[str], tmp_path: Path, drawn: list[Any],
        capsys: pytest.CaptureFixture[str]) -> None:
    run, plots = tmp_path / "run.h5", tmp_path / "plots"
    assert main(["simulate", "--t-end", str(T_END), *verify, "--out", str(run), "--plot",
                 str(plots)]) == 0
    checked = "  accuracy (checked against the same run at " in capsys.readouterr().out
    assert checked == (verify == [])
    lines = orbit_lines(drawn)
    assert list(lines) == [ORBIT_GID]
    assert_orbits_bounded(_read(run), lines[ORBIT_GID])


def test_plot_and_compare_draw_orbits_from_the_replayed_dense_output(
        tmp_path: Path, drawn: list[Any], capsys: pytest.CaptureFixture[str]) -> None:
    first, second = tmp_path / "a.h5", tmp_path / "b.h5"
    assert main(["simulate", "--t-end", str(T_END), "--out", str(first), "--quiet"]) == 0
    assert main(["simulate", "--t-end", str(T_END), "--set", "friction.mu=0.2", "--out",
                 str(second), "--quiet"]) == 0
    assert main(["plot", str(first), "--out", str(tmp_path / "plot")]) == 0
    assert_orbits_bounded(_read(first), orbit_lines(drawn)[ORBIT_GID])
    drawn.clear()
    assert main(["compare", str(first), str(second), "--out", str(tmp_path / "cmp")]) == 0
    lines = orbit_lines(drawn)
    assert sorted(lines) == [f"{ORBIT_GID}:a", f"{ORBIT_GID}:b"]
    assert_orbits_bounded(_read(first), lines[f"{ORBIT_GID}:a"])
    assert_orbits_bounded(_read(second), lines[f"{ORBIT_GID}:b"])
    assert "orbits from the" in capsys.readouterr().out


@pytest.mark.slow
def test_api_figure_helpers_draw_orbits_from_the_dense_output(tmp_path: Path,
                                                              drawn: list[Any]) -> None:
    from jointplay.results.look import compare_runs
    from jointplay.results.plots import plot_result
    from jointplay.scene.definition import default_scene
    from jointplay.sim import simulate, with_accuracy

    scene = default_scene().with_run(t_end=T_END)
    plain = simulate(scene)
    checked = with_accuracy(plain, scene)
    verified = simulate(scene, verify=True)
    for i, result in enumerate((plain, checked, verified)):
        drawn.clear()
        plot_result(result, tmp_path / f"figures{i}")
        assert_orbits_bounded(result, orbit_lines(drawn)[ORBIT_GID])
    assert checked.accuracy is not None and checked.sol.method == "bdf"
    drawn.clear()
    compare_runs([("plain", plain), ("checked", checked)], tmp_path / "cmp")
    lines = orbit_lines(drawn)
    assert_orbits_bounded(plain, lines[f"{ORBIT_GID}:plain"])
    assert_orbits_bounded(checked, lines[f"{ORBIT_GID}:checked"])


# ------------------------------------------------------------------- labels, marks, workers


@pytest.fixture(scope="module")
def synthetic() -> SimulationResult:
    from test_output import make_result

    return make_result(n=200)


def _by_title(figures: list[Any], ending: str) -> Any:
    return next(fig for fig in figures if fig.get_suptitle().endswith(ending))


def test_figures_say_what_they_show(synthetic: SimulationResult, tmp_path: Path,
                                    drawn: list[Any]) -> None:
    from jointplay.results.plots import plot_result

    plot_result(synthetic, tmp_path)
    tip = _by_title(drawn, "end-effector response")
    labels = [ax.get_ylabel() for ax in tip.axes]
    assert "position [m]" in labels and not any("displacement" in s for s in labels)
    forces = _by_title(drawn, "contact forces")
    for k, joint in enumerate(synthetic.clearance_joints):
        ax = forces.axes[k]
        peaks = [ln for ln in ax.get_lines() if ln.get_label().startswith("located peak")]
        assert len(peaks) == 1
        rows = synthetic.impacts.for_joint(joint)
        np.testing.assert_array_equal(peaks[0].get_xdata(), rows.peak_force_time)
        np.testing.assert_array_equal(peaks[0].get_ydata(), rows.peak_force)
        assert ax.get_ylim()[1] >= rows.peak_force.max()  # the located peaks are in view
        sampled = [ln.get_label() for ln in ax.get_lines()]
        assert any("output samples, every " in s for s in sampled)
        assert "largest located peak" in ax.get_title()
    energy = _by_title(drawn, "energy")
    top, middle, bottom = energy.axes
    assert {ln.get_label() for ln in middle.get_lines()} == {"contact (elastic)",
                                                              "dissipated (since t₀)"}
    assert "gravity" in {ln.get_label() for ln in top.get_lines()}
    shown = next(ln for ln in middle.get_lines() if ln.get_label().startswith("dissipated"))
    assert 0.1 <= float(np.max(np.abs(shown.get_ydata()))) < 1000  # on its own SI prefix
    assert middle.get_ylabel().startswith("energy [") and middle.get_ylabel().endswith("J]")
    assert "residual" in bottom.get_ylabel()


def test_compared_peaks_are_told_apart(synthetic: SimulationResult, tmp_path: Path,
                                       drawn: list[Any]) -> None:
    from jointplay.results.look import compare_runs

    compare_runs([("a", synthetic), ("b", synthetic)], tmp_path)
    impacts = _by_title(drawn, "impacts, runs side by side")
    peaks = impacts.axes[1]
    a, b = (ln for ln in peaks.get_lines() if ln.get_label().split(":")[0] in ("a", "b"))
    np.testing.assert_array_equal(a.get_xydata(), b.get_xydata())  # the same peaks...
    assert a.get_marker() != b.get_marker()  # ...drawn so that both show
    assert a.get_markerfacecolor() == "none" and a.get_markersize() > b.get_markersize()


def test_forked_workers_draw_the_same_files(synthetic: SimulationResult,
                                            tmp_path: Path) -> None:
    from jointplay.results.plots import plot_result

    original = figure_module.WORKERS
    try:
        figure_module.WORKERS = 1
        here = plot_result(synthetic, tmp_path / "here")
        figure_module.WORKERS = 3
        forked = plot_result(synthetic, tmp_path / "forked")
    finally:
        figure_module.WORKERS = original
    assert [p.name for p in here] == [p.name for p in forked]
    for a, b in zip(here, forked, strict=True):
        assert a.read_bytes() == b.read_bytes(), a.name
    assert sorted(p.name for p in (tmp_path / "forked").iterdir()) == sorted(
        p.name for p in forked)  # no temporary left


@pytest.mark.slow
def test_sweep_figure_has_units_and_no_offset_text(tmp_path: Path, drawn: list[Any]) -> None:
    from test_sweep import GRID, _write

    from jointplay.sweep import run_sweep

    run_sweep(_write(tmp_path, GRID), tmp_path / "out", workers=0)
    clearance = next(fig for fig in drawn if "against joint2.clearance" in fig.get_suptitle())
    fig_axes = clearance.axes
    assert fig_axes[-1].get_xlabel() == "joint2.clearance [mm]"  # 0.02 to 0.1 mm
    clearance.canvas.draw()
    for ax in fig_axes:
        assert ax.yaxis.get_offset_text().get_text() == "", ax.get_title()
    penetration = next(ax for ax in fig_axes if ax.get_title().startswith("max penetration"))
    assert penetration.get_ylabel() in ("[µm]", "[nm]", "[mm]", "[m]")


def test_the_transient_peak_in_a_title_is_the_norm_the_summary_gives() -> None:
    """The end-effector figure's off-scale transient: its title gives the largest x-y norm
    of the run's samples (what the run's summary reports as the largest error against the
    ideal joints), not the largest single component, and says where it lies, also when it
    lies after the shaded transient."""
    from jointplay.common.figures import figure
    from jointplay.results.plots import _off_scale

    t = np.linspace(0.0, 1.0, 101)
    values = np.zeros((101, 2))
    values[3] = (30.0, 40.0)  # norm 50; largest component 40
    values[50:] = np.column_stack([np.sin(t[50:]), np.cos(t[50:])])
    _, axes = figure(1, 1, 4.0, 3.0)
    title = _off_scale(axes[0, 0], t, values, (0.2, "first impact burst"), "m/s²", "error")
    assert title.endswith("largest |sample| 50 m/s² at 0.03 s (in the transient)"), title
    values[30] = (60.0, 80.0)  # after the transient's end: still the run's largest
    title = _off_scale(axes[0, 0], t, values, (0.2, "first impact burst"), "m/s²", "error")
    assert title.endswith("largest |sample| 100 m/s² at 0.3 s (after it)"), title


def test_the_release_transient_and_its_title_do_not_depend_on_the_run_length(
        tmp_path: Path, drawn: list[Any]) -> None:
    """The paper scene cut at 0.2 s and at 1 s: the same release transient (the first impact
    burst; a rule on the motion, not on the run's length), and the end-effector figure's
    acceleration-error title gives the largest error the summary prints."""
    import jointplay
    from jointplay.cli.summary import summary
    from jointplay.results.derived import release_transient_end
    from jointplay.results.plots import plot_end_effector

    ends, titles = [], []
    for t_end in (0.2, 1.0):
        result = jointplay.simulate(jointplay.default_scene().with_run(t_end=t_end),
                                    compare_ideal=True)
        end, rule = release_transient_end(result) or (np.nan, "")
        assert rule == "end of the first impact burst"
        ends.append(end)
        plot_end_effector(result, tmp_path / f"ee{t_end}.png")
        title = drawn[-1].axes[5].get_title()  # the acceleration error, bottom right
        printed = next(line for line in summary(result).splitlines()
                       if "acceleration error vs ideal" in line)
        largest = printed.split("max ")[1].split(" m/s^2")[0]
        assert f"largest |sample| {largest} m/s² at" in title, (title, printed)
        titles.append(title)
    # the two runs step differently through the same impacts: the ends agree to 0.1 ms
    assert abs(ends[0] - ends[1]) < 1e-4, ends
    assert ends[0] > 0.015, ends  # the whole burst (to about 21 ms), not its first 4.5 ms
    assert titles[0] == titles[1]
