"""An animation of a mechanism run: the bodies to scale, each clearance joint's journal
orbit magnified in an inset (the arms' animation, :mod:`jointplay.results.animate`, drawn
from a mechanism's bodies).

Each body is drawn through its joint points (the points its joints hold on it, in its own
frame, placed by the body's origin and angle that the compiled model's ``outputs`` give),
a slider as a block on its guide; ground pivots and guides are drawn once. A clearance's
play (tenths of a millimetre on a rod of centimetres) is invisible to scale: its inset shows
the journal centre inside the clearance circle in micrometres, with the recent orbit and the
impact onsets so far.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.mechanism.description import MechanismScene
from jointplay.mechanism.model import MechanismModel, model_for
from jointplay.mechanism.simulate import MechanismResult
from jointplay.results.animate import (
    DPI,
    FPS,
    MAX_FRAMES,
    check_animation_path,
    clearance_inset,
    draw_inset,
    frame_indices,
    write_frames,
)


@dataclass(frozen=True)
class BodyPaths:
    """Where the bodies are at chosen samples.

    Attributes
    ----------
    bodies : list of str
        The bodies' names, in the file's order.
    points : dict of str to numpy.ndarray
        Per body, its joint points in the ground's axes (m), shape (samples, k, 2), in the
        order of :attr:`labels`.
    labels : dict of str to list of str
        Per body, the joint each point belongs to.
    ground : numpy.ndarray
        The joint points on the ground (m), shape (k, 2): pivots and guides' origins.
    ground_labels : list of str
        The joint each ground point belongs to.
    guides : list of tuple
        Each prismatic joint on the ground: (origin (2,), unit axis (2,)) in m.
    sliders : list of str
        The bodies a prismatic joint holds (drawn as blocks).
    """

    bodies: list[str]
    points: dict[str, np.ndarray]
    labels: dict[str, list[str]]
    ground: np.ndarray
    ground_labels: list[str]
    guides: list[tuple[np.ndarray, np.ndarray]]
    sliders: list[str]


def body_paths(scene: MechanismScene, result: MechanismResult,
               rows: np.ndarray | None = None, model: MechanismModel | None = None
               ) -> BodyPaths:
    """The bodies' joint points at the samples ``rows`` (default: all of them).

    The bodies' frames come from the compiled model (the same kinematics the equations were
    derived from); each joint point is the joint's ``at_parent`` in the parent's frame and
    its ``at_child`` in the child's. At a clearance joint the two differ by the
    eccentricity."""
    from jointplay.sim.native import map_function

    model = model or model_for(scene.mechanism)
    structure = model.structure
    rows = np.arange(len(result.t)) if rows is None else np.asarray(rows, dtype=int)
    values = scene.mechanism.parameter_values()
    p = model.parameter_vector(scene.mechanism)
    x = np.ascontiguousarray(result.x[rows])
    tau = np.zeros((len(rows), model.n_loads))
    v_imp = np.zeros((len(rows), len(model.clearance_joints)))
    frames = map_function(model, "outputs", [x, tau, p, v_imp], len(rows))[6]
    frames = frames.reshape(len(rows), len(structure.bodies), 3)
    points: dict[str, list[np.ndarray]] = {b: [] for b in structure.bodies}
    labels: dict[str, list[str]] = {b: [] for b in structure.bodies}
    ground: list[np.ndarray] = []
    ground_labels: list[str] = []
    guides: list[tuple[np.ndarray, np.ndarray]] = []
    sliders: list[str] = []
    for joint in structure.joints:
        if joint.type == "floating":
            continue
        j = joint.name
        for side, body in (("parent", joint.parent), ("child", joint.child)):
            local = np.array([values[f"{j}.{side}_x"], values[f"{j}.{side}_y"]])
            if body == "ground":
                ground.append(local)
                ground_labels.append(j)
                if joint.type == "prismatic":
                    turn = values[f"{j}.angle"]  # the guide's axis, turned by the joint's angle
                    axis = np.array([values[f"{j}.axis_x"], values[f"{j}.axis_y"]])
                    c, s = np.cos(turn), np.sin(turn)
                    axis = np.array([c * axis[0] - s * axis[1], s * axis[0] + c * axis[1]])
                    guides.append((local, axis / np.linalg.norm(axis)))
                continue
            k = structure.bodies.index(body)
            origin, angle = frames[:, k, :2], frames[:, k, 2]
            c, s = np.cos(angle), np.sin(angle)
            points[body].append(origin + np.stack([c * local[0] - s * local[1],
                                                   s * local[0] + c * local[1]], axis=1))
            labels[body].append(j)
        if joint.type == "prismatic":
            sliders.append(joint.child)
    return BodyPaths(list(structure.bodies),
                     {b: np.stack(v, axis=1) if v else np.zeros((len(rows), 0, 2))
                      for b, v in points.items()},
                     labels, np.array(ground).reshape(-1, 2), ground_labels, guides,
                     sliders)


def animate_mechanism(scene: MechanismScene, result: MechanismResult, path: str | Path, *,
                      fps: int = FPS, max_frames: int = MAX_FRAMES, quiet: bool = True,
                      model: MechanismModel | None = None) -> Path:
    """Write the animation of a mechanism run to ``path`` (.gif, or .mp4 with ffmpeg on
    PATH), atomically; return the path.

    Examples
    --------
    >>> from importlib.resources import files
    >>> import jointplay
    >>> from jointplay.mechanism.animate import animate_mechanism
    >>> path = files("jointplay.scenes") / "slider_crank.toml"
    >>> scene = jointplay.load_mechanism_scene(path).with_run(t_end=0.002)
    >>> result = jointplay.simulate_mechanism(scene)
    >>> animate_mechanism(scene, result, "crank.gif", max_frames=5).name
    'crank.gif'
    """
    path = check_animation_path(path)
    frames = frame_indices(len(result.t), max_frames)
    paths = body_paths(scene, result, frames, model)
    fig, art = _figure(scene, result, paths)
    t = result.t
    span = float(t[-1] - t[0]) if t.size > 1 else 1.0
    speed = (span / max(len(frames) - 1, 1)) * fps
    art["title"].set_text(f"{result.name}: played at {speed:.3g} x real time")
    onsets = np.asarray(result.impacts.eccentricity).reshape(-1, 2)
    joints = np.asarray(result.impacts.joint)
    row_of = {int(i): r for r, i in enumerate(frames)}
    moving = [*art["bodies"].values(), art["clock"],
              *(line for inset in art["insets"] for line in inset)]

    def draw(i: int) -> None:
        r = row_of[i]
        for body, line in art["bodies"].items():
            at = paths.points[body][r]
            if body in paths.sliders:
                line.set_data([at[0, 0]], [at[0, 1]])
            else:
                line.set_data(at[:, 0], at[:, 1])
        for k in range(len(result.cut_joints)):
            seen = (joints == k + 1) & (result.impacts.time <= t[i])
            draw_inset(art["insets"][k], t, i, result.eccentricity[:, k], onsets[seen])
        art["clock"].set_text(f"t = {t[i] * 1e3:.3f} ms")

    write_frames(fig, moving, draw, frames, path, fps=fps, quiet=quiet)
    return path


def _figure(scene: MechanismScene, result: MechanismResult,
            paths: BodyPaths) -> tuple[Any, dict[str, Any]]:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    nc = len(result.cut_joints)
    fig = Figure(figsize=(7.5 + 2.6 * (nc > 0), 5.0), dpi=DPI, layout="constrained")
    FigureCanvasAgg(fig)
    grid = fig.add_gridspec(max(nc, 1), 2, width_ratios=(3.0, 1.15 if nc else 0.01))
    ax = fig.add_subplot(grid[:, 0])
    every = np.concatenate([paths.ground] + [v.reshape(-1, 2) for v in paths.points.values()])
    low, high = every.min(axis=0), every.max(axis=0)
    margin = 0.12 * float(np.max(high - low)) + 1e-9
    ax.set_xlim(low[0] - margin, high[0] + margin)
    ax.set_ylim(low[1] - margin, high[1] + margin)
    ax.set_aspect("equal")
    ax.grid(True, alpha=0.3)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    for origin, axis in paths.guides:
        reach = np.array([low - margin, high + margin])
        ends = origin + np.outer([-1.0, 1.0], axis) * float(np.linalg.norm(reach[1] - reach[0]))
        ax.plot(ends[:, 0], ends[:, 1], color="0.6", lw=4.0, zorder=0, solid_capstyle="butt")
    if len(paths.ground):
        ax.plot(paths.ground[:, 0], paths.ground[:, 1], "^", color="0.3", ms=11, zorder=1,
                label="ground")
    bodies = {}
    for k, body in enumerate(paths.bodies):
        if body in paths.sliders:
            (line,) = ax.plot([], [], "s", color=f"C{k}", ms=18, mec="k", zorder=2, label=body)
        else:
            (line,) = ax.plot([], [], "-o", color=f"C{k}", lw=4.0, ms=6, mfc="w", zorder=3,
                              label=body)
        bodies[body] = line
    ax.legend(loc="upper left", fontsize=8)
    insets = [clearance_inset(fig.add_subplot(grid[k, 1]), joint, f"C{(k * 2 + 3) % 10}",
                              float(result.clearance[k]), result.eccentricity[:, k])
              for k, joint in enumerate(result.cut_joints)]
    title = ax.set_title("")
    clock = ax.text(0.98, 0.02, "", transform=ax.transAxes, ha="right", va="bottom",
                    fontsize=11, bbox={"boxstyle": "round", "fc": "w", "ec": "0.6"})
    return fig, {"bodies": bodies, "insets": insets, "title": title, "clock": clock}


__all__ = ["BodyPaths", "animate_mechanism", "body_paths"]
