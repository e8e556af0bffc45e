"""jointplay against the tools a user would otherwise reach for, on the same robot and scene.

In one process, on the scene's robot (default: the paper's 4-link arm, clearance at joints 2
and 3, Coulomb friction) and the same sympy equations (``jointplay.derive.derive``: Kane's
method, the contact placeholders bound to the law expressions exactly as the C emitter binds
them):

(a) PyDy: ``pydy.system.System`` with the Cython backend (``generator='cython'``) for the
    right-hand side, integrated by SciPy's LSODA. PyDy's own ``System.integrate`` calls
    ``odeint`` (LSODA), which cannot stop at events; the impact-speed capture below needs
    them, so LSODA is driven through ``solve_ivp(method='LSODA', events=...)``.
(b) what a newcomer writes: ``sympy.lambdify`` of M and f (NumPy), ``numpy.linalg.solve``,
    the same ``solve_ivp`` LSODA driver.
(c) Pinocchio's ABA as the right-hand side of the ideal-joint version of the robot,
    integrated by CVODES through CasADi (the integrator of jointplay's ideal run) at the same
    tolerances, with Pinocchio's analytical ABA derivatives as the Jacobian; the same
    Python-callback path is also driven by jointplay's compiled functions, so the two
    right-hand sides are compared from one calling path, and jointplay's own ``simulate`` of
    the ideal scene is timed beside them. Per call: ``pin.aba`` from Python against jointplay's
    ``forward_dynamics`` through ``FastFunction`` (inputs written, ``trigger``, output read).
(d) jointplay: ``simulate`` with its default integrator (the compiled BDF: a whole run in one
    call into C, contact onsets located on its dense output), swept over tolerances;
(e) jointplay's compiled right-hand side in the peers' own LSODA driver: the same integration
    as (a) and (b), so that the cost of the right-hand side and that of the integration
    scheme can be told apart.

Impact speed. Every code captures it by jointplay's rule: each clearance joint carries
a contact flag; when its penetration crosses zero upwards while flagged free, the integration
stops there (event location), the approach speed d(delta)/dt is captured as that joint's
``v_imp`` (floored by the law at ``contact.impact_speed_floor``), the flag flips, and the
integration restarts. A downward crossing while flagged in contact flips the flag back.

Accuracy. Every run is compared with one reference, jointplay's CVODES at rtol = atol = 1e-10
over the same output grid: the maximum over samples of the end-effector position error (the
matching measure), velocity and acceleration errors, and the final-state error in scaled units.
Tolerances are swept for every code, and each peer run is paired with the jointplay run whose
position error is nearest (in ratio): the report gives both errors and the ratio of CPU times
(peer / jointplay). Absolute tolerances are the same scaled ones for every code (rad; radial
clearance for eccentricities, clearance per ms for their rates).

Costs: CPU seconds (``time.process_time``) of a whole run, median of ``--repeats`` runs; code
generation and compilation are timed once and reported separately.

    python benchmarks/peers.py --out out/bench/peers
    python benchmarks/peers.py --quick            # a small smoke run
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from peers_pinocchio import pinocchio_section
from peers_rhs import Equations, PeerRhs, equations, jointplay_lsoda_rhs, newcomer_rhs, pydy_rhs
from peers_runs import (
    REFERENCE_RTOL,
    Trajectory,
    jointplay_sweep,
    match,
    prefix,
    run_peer,
)

from jointplay.bench import machine_facts, markdown_table, timed_runs, to_csv
from jointplay.cli.args import prepare_out_dir
from jointplay.common.files import atomic_write_text
from jointplay.common.timing import per_call_seconds

JOINTPLAY_RTOLS = (1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7, 3e-8, 1e-8, 1e-9)
PEER_RTOLS = (1e-4, 1e-5, 1e-6, 1e-7, 1e-8)
NEWCOMER_RTOLS = (1e-6,)
IDEAL_RTOLS = (1e-6, 1e-8)
PYDY_GOAL = 10.0  # jointplay at least this many times faster than PyDy at equal accuracy
ABA_GOAL = 2.0  # jointplay's ideal-joint rhs within this factor of pin.aba per call


# ---- driver -------------------------------------------------------------------------------------

ROW_COLUMNS: list[tuple[str, str, str]] = [
    ("code", "code", "{}"),
    ("t_end", "horizon s", "{:g}"),
    ("rtol", "rtol", "{:.0e}"),
    ("status", "status", "{}"),
    ("cpu_median_s", "CPU s (median)", "{:.3f}"),
    ("cpu_min_s", "min", "{:.3f}"),
    ("cpu_max_s", "max", "{:.3f}"),
    ("err_position", "pos err m", "{:.2e}"),
    ("err_velocity", "vel err m/s", "{:.2e}"),
    ("err_acceleration", "acc err m/s²", "{:.2e}"),
    ("err_final_state", "final-state err", "{:.2e}"),
    ("rhs_evaluations", "rhs evals", "{}"),
    ("impacts", "impacts", "{}"),
    ("note", "note", "{}"),
]
PAIR_COLUMNS: list[tuple[str, str, str]] = [
    ("code", "peer", "{}"),
    ("t_end", "horizon s", "{:g}"),
    ("peer_rtol", "peer rtol", "{:.0e}"),
    ("peer_err_position", "peer pos err m", "{:.2e}"),
    ("jp_rtol", "jointplay rtol", "{:.0e}"),
    ("jp_err_position", "jointplay pos err m", "{:.2e}"),
    ("error_ratio", "err ratio", "{:.2f}"),
    ("peer_cpu_s", "peer CPU s", "{:.3f}"),
    ("jp_cpu_s", "jointplay CPU s", "{:.3f}"),
    ("speedup", "peer / jointplay", "{:.1f}"),
]
CSV_KEYS = ["section", "code", "t_end", "rtol", "status", "note", "repeats", "cpu_median_s",
            "cpu_min_s", "cpu_max_s", "err_position", "err_velocity", "err_acceleration",
            "err_final_state", "steps", "rhs_evaluations", "jacobian_evaluations", "events",
            "impacts", "peer_rtol", "peer_err_position", "peer_err_velocity", "peer_cpu_s",
            "jp_rtol", "jp_err_position", "jp_err_velocity", "jp_cpu_s", "error_ratio",
            "speedup"]


def _horizon(scene: Any, t_end: float | None) -> Any:
    if t_end is None or t_end >= scene.run.t_end:
        return scene
    return scene.with_run(t_end=t_end)


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("scene", nargs="?", help="scene file (default: the paper scene)")
    parser.add_argument("--out", help="folder for peers.csv and peers.md")
    parser.add_argument("--t-end", type=float, help="horizon of jointplay and PyDy (default: "
                                                    "the scene's)")
    parser.add_argument("--pydy-t-end", type=float, help="shorter horizon for PyDy")
    parser.add_argument("--newcomer-t-end", type=float,
                        help="shorter horizon for the lambdify peer (it is slow)")
    parser.add_argument("--repeats", type=int, default=3,
                        help="timed runs per configuration (default 3)")
    parser.add_argument("--newcomer-repeats", type=int, default=1,
                        help="timed runs of the lambdify peer (default 1)")
    parser.add_argument("--pydy-rtols", default=",".join(f"{r:g}" for r in PEER_RTOLS))
    parser.add_argument("--quick", action="store_true", help="a small smoke run")
    return parser


def _say(text: str) -> None:
    print(text, file=sys.stderr, flush=True)


class _JointplayRuns:
    """jointplay's tolerance sweep per horizon, run once each, in the order first asked for."""

    def __init__(self, model: Any, reference: Any, rtols: Sequence[float], repeats: int):
        self.model, self.reference, self.rtols, self.repeats = model, reference, rtols, repeats
        self.by_horizon: dict[float, list[dict[str, Any]]] = {}
        self.rows: list[dict[str, Any]] = []

    def reference_for(self, s: Any) -> Trajectory:
        return prefix(self.reference, s.run.n_outputs + 1)

    def rows_for(self, s: Any) -> list[dict[str, Any]]:
        if s.run.t_end not in self.by_horizon:
            _say(f"jointplay sweep over {s.run.t_end:g} s")
            self.by_horizon[s.run.t_end] = jointplay_sweep(s, self.model, self.reference_for(s),
                                                           self.rtols, self.repeats)
            self.rows.extend(self.by_horizon[s.run.t_end])
        return self.by_horizon[s.run.t_end]


@dataclass
class _Findings:
    """Everything the report states."""

    scene: Any
    pydy_scene: Any
    newcomer_scene: Any
    reference_cpu_s: float
    repeats: int
    newcomer_repeats: int
    rows: list[dict[str, Any]]
    peer_rows: list[dict[str, Any]]
    pairs: list[dict[str, Any]]
    jp_by_horizon: dict[float, list[dict[str, Any]]]
    per_call_peer: dict[str, float]
    per_call: dict[str, Any]
    build: dict[str, float]
    load_start: str


def main(argv: Sequence[str] | None = None) -> int:
    args = _parser().parse_args(argv)

    from jointplay.scene.definition import default_scene, load_scene
    from jointplay.sim import load_scene_model

    scene = load_scene(args.scene) if args.scene else default_scene()
    if args.quick:
        args.t_end = args.t_end or 0.02
        args.newcomer_t_end = min(args.newcomer_t_end or 0.01, 0.01)
        args.repeats = 1
    scene = _horizon(scene, args.t_end)
    pydy_scene = _horizon(scene, args.pydy_t_end)
    newcomer_scene = _horizon(scene, args.newcomer_t_end)
    pydy_rtols = [float(r) for r in args.pydy_rtols.split(",") if r.strip()]
    jp_rtols = JOINTPLAY_RTOLS[::3] if args.quick else JOINTPLAY_RTOLS
    out = prepare_out_dir(args.out) if args.out else None
    load_start = " ".join(f"{v:.2f}" for v in os.getloadavg())

    model = load_scene_model(scene)
    _say(f"reference: jointplay cvodes rtol {REFERENCE_RTOL:g} over {scene.run.t_end:g} s")
    ref_timed = timed_runs(scene.with_run(integrator="cvodes", rtol=REFERENCE_RTOL,
                                          atol=REFERENCE_RTOL), model, 1)
    assert ref_timed.result is not None, ref_timed.failure
    jp = _JointplayRuns(model, ref_timed.result, jp_rtols, args.repeats)
    jp.rows_for(scene)
    _say("deriving the shared sympy equations")
    eq = equations(scene.robot)
    build: dict[str, float] = {"sympy derivation (shared)": eq.derive_s}
    per_call_peer, peer_rows = _peers(eq, scene, model, jp, build, [
        (pydy_scene, rtol, args.repeats) for rtol in pydy_rtols],
        (newcomer_scene, args.newcomer_repeats))
    rows = jp.rows + peer_rows
    pairs: list[dict[str, Any]] = []
    for code in dict.fromkeys(r["code"] for r in peer_rows):
        mine = [r for r in peer_rows if r["code"] == code]
        pairs += match(mine, jp.by_horizon[mine[0]["t_end"]])

    _say("Pinocchio (ideal joints)")
    ideal_rows, per_call = pinocchio_section(scene, args.repeats, IDEAL_RTOLS)
    rows.extend(ideal_rows)
    text = _report(_Findings(
        scene=scene, pydy_scene=pydy_scene, newcomer_scene=newcomer_scene,
        reference_cpu_s=ref_timed.cpu_s[0], repeats=args.repeats,
        newcomer_repeats=args.newcomer_repeats, rows=rows, peer_rows=peer_rows, pairs=pairs,
        jp_by_horizon=jp.by_horizon, per_call_peer=per_call_peer, per_call=per_call,
        build=build, load_start=load_start))
    print(text)
    if out is not None:
        table = [{"section": "run", **r} for r in rows] + \
                [{"section": "matched", **q} for q in pairs]
        atomic_write_text(out / "peers.csv", to_csv(table, CSV_KEYS))
        atomic_write_text(out / "peers.md", text)
        print(f"wrote {out / 'peers.csv'}\nwrote {out / 'peers.md'}")
    return 0


def _peers(eq: Equations, scene: Any, model: Any, jp: _JointplayRuns, build: dict[str, float],
           pydy_runs: Sequence[tuple[Any, float, int]], newcomer_run: tuple[Any, int]
           ) -> tuple[dict[str, float], list[dict[str, Any]]]:
    """Build PyDy's and the lambdify right-hand sides (their build times into ``build``);
    their cost per call; then PyDy and jointplay's rhs in the same driver at ``pydy_runs``
    (horizon, rtol, repeats), and the lambdify peer once."""
    with tempfile.TemporaryDirectory(prefix="jointplay-peers-") as tmp:
        _say("PyDy: generating and compiling the Cython right-hand side")
        pydy = pydy_rhs(eq, scene.robot, scene, Path(tmp) / "pydy")
        build["PyDy codegen + Cython compile (wall)"] = pydy.build_s
        _say("sympy.lambdify")
        newcomer = newcomer_rhs(eq, scene.robot, scene)
        build["sympy.lambdify (wall)"] = newcomer.build_s
        per_call_peer = _peer_per_call(model, scene, pydy, newcomer)
        same_driver = jointplay_lsoda_rhs(model, scene)
        runs = [(pydy, s, rtol, repeats) for s, rtol, repeats in pydy_runs]
        runs += [(same_driver, s, rtol, repeats) for s, rtol, repeats in pydy_runs]
        runs += [(newcomer, newcomer_run[0], rtol, newcomer_run[1]) for rtol in NEWCOMER_RTOLS]
        return per_call_peer, _peer_runs(runs, model, jp)


def _peer_per_call(model: Any, scene: Any, pydy: PeerRhs, newcomer: PeerRhs
                   ) -> dict[str, float]:
    """Per right-hand-side call of each code at a probe state, and how far they agree."""
    x_probe = np.zeros(model.n_state)
    x_probe[0] = -math.pi
    v0 = np.full(len(model.clearance_joints), 0.1)
    per_call_peer = {
        "PyDy rhs (us/call)": per_call_seconds(lambda: pydy.rhs(0.1, x_probe, v0)) * 1e6,
        "lambdify rhs (us/call)": per_call_seconds(
            lambda: newcomer.rhs(0.1, x_probe, v0), repeats=3) * 1e6,
    }
    fd = model.function("forward_dynamics")
    fd.inputs[0][:] = x_probe
    fd.inputs[2][:] = model.parameter_vector()
    fd.inputs[3][:] = v0
    per_call_peer["jointplay forward_dynamics trigger (us/call)"] = \
        per_call_seconds(fd.trigger) * 1e6
    p = model.parameter_vector()
    tau01 = np.array([float(f.numpy(0.1)) for f in scene.torques])
    agree = float(np.max(np.abs(pydy.rhs(0.1, x_probe, v0)
                                - model.forward_dynamics(x_probe, tau01, p, v0))))
    agree_nc = float(np.max(np.abs(newcomer.rhs(0.1, x_probe, v0)
                                   - model.forward_dynamics(x_probe, tau01, p, v0))))
    per_call_peer["max |PyDy rhs - jointplay rhs| at a probe state"] = agree
    per_call_peer["max |lambdify rhs - jointplay rhs| at a probe state"] = agree_nc
    return per_call_peer


def _peer_runs(runs: Sequence[tuple[PeerRhs, Any, float, int]], model: Any,
               jp: _JointplayRuns) -> list[dict[str, Any]]:
    """Each peer at each tolerance over its horizon (jointplay's sweep there first)."""
    peer_rows: list[dict[str, Any]] = []
    for peer, peer_scene, rtol, repeats in runs:
        jp.rows_for(peer_scene)
        _say(f"{peer.name}: rtol {rtol:g} over {peer_scene.run.t_end:g} s")
        row = run_peer(peer, model, peer_scene, jp.reference_for(peer_scene), rtol, repeats)
        peer_rows.append(row)
        _say(f"  {row.get('cpu_median_s', math.nan):.2f} s CPU, position error "
             f"{row.get('err_position', math.nan):.2e} m")
    return peer_rows


def _goal_lines(f: _Findings) -> list[str]:
    """The verdicts on the two goals, and the facts beside them."""
    scene = f.scene
    pydy_pairs = [q for q in f.pairs if q["code"].startswith("PyDy")]
    matched = [q for q in pydy_pairs if 0.5 <= q["error_ratio"] <= 2.0]
    md = []
    if matched:
        best = min(matched, key=lambda q: abs(math.log(q["error_ratio"])))
        verdict = "met" if best["speedup"] >= PYDY_GOAL else "NOT met"
        md.append(f"- >= {PYDY_GOAL:g}x faster than PyDy at equal accuracy: {verdict}: "
                  f"{best['speedup']:.1f}x at position error {best['peer_err_position']:.2e} m "
                  f"(PyDy rtol {best['peer_rtol']:g}) vs {best['jp_err_position']:.2e} m "
                  f"(jointplay rtol {best['jp_rtol']:g}), over {best['t_end']:g} s; every "
                  "matched pair: " + ", ".join(f"{q['speedup']:.1f}x" for q in matched))
    else:
        md.append(f"- >= {PYDY_GOAL:g}x faster than PyDy at equal accuracy: no PyDy run "
                  "could be matched within a factor 2 in error (see the tables)")
    md += _driver_lines(f)
    us_pydy = f.per_call_peer["PyDy rhs (us/call)"]
    us_jp = f.per_call_peer["jointplay forward_dynamics trigger (us/call)"]
    md.append(f"- per right-hand-side call: PyDy {us_pydy:.1f} us, lambdify "
              f"{f.per_call_peer['lambdify rhs (us/call)']:.0f} us, jointplay {us_jp:.2f} us "
              f"(PyDy / jointplay {us_pydy / us_jp:.0f}x)")
    per_call = f.per_call
    verdict = "met" if per_call["ratio"] <= ABA_GOAL else "NOT met"
    md.append(f"- ideal-joint rhs within {ABA_GOAL:g}x of Pinocchio's ABA per call (both "
              f"called from Python with numpy arrays): {verdict}: jointplay "
              f"{per_call['jp_in_trigger_out_us']:.2f} us vs pin.aba "
              f"{per_call['pin_aba_us']:.2f} us ({per_call['ratio']:.2f}x); trigger alone "
              f"{per_call['jp_trigger_us']:.2f} us")
    default_jp = next((r for r in f.jp_by_horizon[scene.run.t_end]
                       if r["rtol"] == scene.run.rtol and r["status"] == "ok"), None)
    if default_jp is not None:
        md.append(f"- jointplay at the scene's tolerance (rtol {scene.run.rtol:g}): "
                  f"{default_jp['cpu_median_s']:.3f} s CPU for {scene.run.t_end:g} s "
                  f"simulated, position error {default_jp['err_position']:.2e} m")
    return md


def _driver_lines(f: _Findings) -> list[str]:
    """PyDy against jointplay's rhs in the same driver, and the work each integration did."""
    md = []
    same = {r["rtol"]: r for r in f.peer_rows
            if r["code"].startswith("jointplay rhs") and r["status"] == "ok"}
    driver_pairs = [(r, same[r["rtol"]]) for r in f.peer_rows if r["code"].startswith("PyDy")
                    and r["status"] == "ok" and r["rtol"] in same]
    if driver_pairs:
        md.append("- PyDy against jointplay's rhs in the same LSODA driver (same tolerance, so "
                  "only the right-hand side differs): " + ", ".join(
                      f"rtol {a['rtol']:g}: {a['cpu_median_s'] / b['cpu_median_s']:.1f}x "
                      f"(errors {a['err_position']:.1e} / {b['err_position']:.1e} m)"
                      for a, b in driver_pairs))
    jp_at = {r["rtol"]: r for r in f.jp_by_horizon[f.pydy_scene.run.t_end]
             if r["status"] == "ok"}
    for r in f.peer_rows:
        if r["code"].startswith("PyDy") and r["status"] == "ok" \
                and r["rtol"] == f.scene.run.rtol and r["rtol"] in jp_at:
            j = jp_at[r["rtol"]]
            md.append(f"- work at rtol {r['rtol']:g}: jointplay's simulate {j['steps']} steps, "
                      f"{j['rhs_evaluations']} rhs and {j['jacobian_evaluations']} Jacobian "
                      f"evaluations; LSODA (PyDy) {r['rhs_evaluations']} rhs evaluations "
                      f"(finite-difference Jacobians included), {r['jacobian_evaluations']} "
                      "Jacobians")
    return md


def _report(f: _Findings) -> str:
    scene = f.scene
    md = ["# jointplay and its peers", "",
          f"Scene: {scene.source or scene.name}; horizon {scene.run.t_end:g} s (PyDy "
          f"{f.pydy_scene.run.t_end:g} s, lambdify {f.newcomer_scene.run.t_end:g} s), output "
          f"every {scene.run.output_step:g} s. Reference: jointplay CVODES rtol = atol = "
          f"{REFERENCE_RTOL:g} ({f.reference_cpu_s:.2f} s CPU). CPU times are medians of "
          f"{f.repeats} runs (lambdify: {f.newcomer_repeats}).", "",
          "## Goals", "", *_goal_lines(f)]
    md += ["", "## Peer / jointplay at matched accuracy", "",
           "Each peer run is paired with the jointplay run whose end-effector position error "
           "is nearest; `err ratio` = peer error / jointplay error (within 0.5-2 counts as "
           "matched), `peer / jointplay` = ratio of CPU times.", "",
           markdown_table(f.pairs, PAIR_COLUMNS), "",
           "## Per call", "",
           *(f"- {k}: {v:.3g}" for k, v in f.per_call_peer.items()),
           *(f"- {k}: {v:.3g}" for k, v in f.per_call.items()), "",
           "## Code generation and compilation (once, not in the run times)", "",
           *(f"- {k}: {v:.2f} s" for k, v in f.build.items()), "",
           "## Every run", "", markdown_table(f.rows, ROW_COLUMNS), "",
           "## Machine", "", f"- load average (1/5/15 min) at the start: {f.load_start}",
           *(f"- {k}: {v}" for k, v in machine_facts().items()), ""]
    return "\n".join(md)


if __name__ == "__main__":
    sys.exit(main())
