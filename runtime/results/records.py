"""What a simulation returns: every quantity as numpy arrays over the output times.

Arrays are float64, indexed by output sample first. ``nc`` is the number of clearance joints
(``clearance_joints`` gives their 1-based joint numbers, in the order of the second axis).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from jointplay.results.accuracy import Accuracy
    from jointplay.results.sensitivities import Sensitivities
    from jointplay.results.solution import DenseSolution
    from jointplay.results.wear import WearProfile

# Columns of the contact-phase table beyond the four an impact always had, with their units.
PHASE_FIELDS: tuple[tuple[str, str, str], ...] = (
    ("onset_angle", "rad", "position of the onset on the bearing, atan2(ey, ex)"),
    ("peak_force", "N", "largest normal force of the phase (located on the dense output)"),
    ("peak_force_time", "s", "when it occurs"),
    ("max_penetration", "m", "largest penetration of the phase (d(delta)/dt = 0, located)"),
    ("max_penetration_time", "s", "when it occurs"),
    ("separation_time", "s", "end of the phase (located); NaN while still in contact at the end"),
    ("exit_speed", "m/s", "separation speed -d(delta)/dt at separation; NaN without separation"),
    ("duration", "s", "separation_time - time, or the run's end - time without separation"),
    ("restitution", "1", "effective restitution exit_speed / speed; NaN without separation"),
    ("impulse", "N s", "integral of the normal force over the phase"),
    ("damping_energy", "J", "energy taken out by the hysteresis damping during the phase"),
    ("friction_energy", "J", "energy taken out by friction during the phase"),
    ("separated", "bool", "True: ended in separation; False: still in continuous contact"),
)


def _empty(n: int = 0) -> np.ndarray:
    return np.full(n, np.nan)


@dataclass(frozen=True)
class Impacts:
    """One row per contact phase (an impact and what follows until separation), onset order.

    Every time and extremum is located (events on the penetration and its rate, maxima on the
    integrator's dense output), never read off the output samples. ``time``, ``joint``,
    ``speed`` and ``eccentricity`` describe the onset; the rest (see :data:`PHASE_FIELDS`)
    describe the phase. Runs with a fixed-step method fill only the onset columns (the rest
    NaN); see docs/reference/results-file.md. Each attribute is an array with one entry per
    phase (m of them).

    Attributes
    ----------
    time : numpy.ndarray
        (m,) s, onset of contact, located by event detection.
    joint : numpy.ndarray
        (m,) int, the 1-based joint number.
    speed : numpy.ndarray
        (m,) m/s, normal approach speed d(delta)/dt at onset (before flooring).
    eccentricity : numpy.ndarray
        (m, 2) m, journal centre minus bearing centre at onset.
    onset_angle : numpy.ndarray
        rad, position of the onset on the bearing, atan2(ey, ex).
    peak_force : numpy.ndarray
        N, largest normal force of the phase (located on the dense output).
    peak_force_time : numpy.ndarray
        s, when it occurs.
    max_penetration : numpy.ndarray
        m, largest penetration of the phase (d(delta)/dt = 0, located).
    max_penetration_time : numpy.ndarray
        s, when it occurs.
    separation_time : numpy.ndarray
        s, end of the phase (located); NaN while still in contact at the end.
    exit_speed : numpy.ndarray
        m/s, separation speed -d(delta)/dt at separation; NaN without separation.
    duration : numpy.ndarray
        s, ``separation_time - time``, or the run's end minus ``time`` without separation.
    restitution : numpy.ndarray
        Effective restitution ``exit_speed / speed``; NaN without separation.
    impulse : numpy.ndarray
        N s, integral of the normal force over the phase.
    damping_energy : numpy.ndarray
        J, energy taken out by the hysteresis damping during the phase.
    friction_energy : numpy.ndarray
        J, energy taken out by friction during the phase.
    separated : numpy.ndarray
        bool, True: the phase ended in separation; False: still in continuous contact.
    """

    time: np.ndarray  # (m,) s, onset of contact located by event detection
    joint: np.ndarray  # (m,) int, 1-based joint number
    speed: np.ndarray  # (m,) m/s, normal approach speed d(delta)/dt at onset (before flooring)
    eccentricity: np.ndarray  # (m, 2) m, journal centre minus bearing centre at onset
    onset_angle: np.ndarray = field(default_factory=_empty)
    peak_force: np.ndarray = field(default_factory=_empty)
    peak_force_time: np.ndarray = field(default_factory=_empty)
    max_penetration: np.ndarray = field(default_factory=_empty)
    max_penetration_time: np.ndarray = field(default_factory=_empty)
    separation_time: np.ndarray = field(default_factory=_empty)
    exit_speed: np.ndarray = field(default_factory=_empty)
    duration: np.ndarray = field(default_factory=_empty)
    restitution: np.ndarray = field(default_factory=_empty)
    impulse: np.ndarray = field(default_factory=_empty)
    damping_energy: np.ndarray = field(default_factory=_empty)
    friction_energy: np.ndarray = field(default_factory=_empty)
    separated: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))

    def __post_init__(self) -> None:
        # Tables built from the four onset columns alone get NaN phase columns of their length.
        m = int(np.asarray(self.time).size)
        for name, _, _ in PHASE_FIELDS:
            value = np.asarray(getattr(self, name))
            if value.size != m:
                fill = np.zeros(m, dtype=bool) if name == "separated" else _empty(m)
                object.__setattr__(self, name, fill)
        if np.asarray(self.eccentricity).size == 0:
            object.__setattr__(self, "eccentricity", np.zeros((m, 2)) if m == 0
                               else np.full((m, 2), np.nan))

    def __len__(self) -> int:
        return int(self.time.size)

    def for_joint(self, joint: int) -> Impacts:
        """The rows of one clearance joint (1-based joint number)."""
        rows = np.asarray(self.joint) == joint
        return Impacts(**{name: np.asarray(getattr(self, name))[rows]
                          for name in self.column_names()})

    @staticmethod
    def column_names() -> tuple[str, ...]:
        return ("time", "joint", "speed", "eccentricity",
                *(name for name, _, _ in PHASE_FIELDS))

    def to_pandas(self) -> Any:
        """A ``pandas.DataFrame``, one row per phase (see
        :func:`jointplay.results.export.impacts_frame`)."""
        from jointplay.results.export import impacts_frame

        return impacts_frame(self)


def eccentricity_columns(coordinate_names: Sequence[str], clearance_joints: Sequence[int]
                         ) -> dict[int, tuple[int, int]]:
    """Columns of (ex, ey) for each clearance joint in the model's coordinate order
    (:func:`jointplay.robot.structure.coordinate_layout`): the joint angles first, then
    (ex, ey) joint by joint in ``clearance_joints`` order."""
    first = len(coordinate_names) - 2 * len(clearance_joints)
    return {j: (first + 2 * k, first + 2 * k + 1) for k, j in enumerate(clearance_joints)}


@dataclass(frozen=True)
class SimulationResult:
    """A simulated trajectory and everything derived from it (SI units throughout).

    N is the number of output samples, n the number of coordinates, nc the number of
    clearance joints. ``result.sol`` is the dense output (the state at any time in the run);
    ``result.to_xarray()`` and ``result.impacts.to_pandas()`` give the ecosystem's shapes
    (the ``[xarray]`` extra).

    Attributes
    ----------
    scene_name : str
        The scene's name.
    integrator : str
        The integrator that ran: ``"bdf"``, ``"cvodes"``, ``"idas"``, ``"radau"`` or ``"rk4"``.
    t : numpy.ndarray
        (N,) s, the output times.
    coordinate_names : list of str
        The coordinates' names, e.g. ``["q2", "q3", "ex2", "ey2", "ex3", "ey3"]``.
    q : numpy.ndarray
        (N, n) the coordinates: rad for angles, m for eccentricities.
    u : numpy.ndarray
        (N, n) their time derivatives.
    udot : numpy.ndarray
        (N, n) their accelerations (from the model at each output sample).
    tau : numpy.ndarray
        (N, ntau) N m, the drive torque of each driven joint.
    torque_joints : list of int
        The 1-based joints the columns of ``tau`` belong to.
    tip_position : numpy.ndarray
        (N, 2) m, the end effector (tip of the last link, where the payload sits).
    tip_velocity : numpy.ndarray
        (N, 2) m/s.
    tip_acceleration : numpy.ndarray
        (N, 2) m/s^2.
    clearance_joints : list of int
        The 1-based clearance joints, in the order of the per-joint columns below.
    radial_clearance : numpy.ndarray
        (nc,) m, bearing minus journal radius of each clearance joint.
    eccentricity : numpy.ndarray
        (N, nc, 2) m, journal centre minus bearing centre.
    penetration : numpy.ndarray
        (N, nc) m, ``|e| - c`` (negative: no contact).
    penetration_rate : numpy.ndarray
        (N, nc) m/s.
    normal_force : numpy.ndarray
        (N, nc) N, >= 0.
    friction_force : numpy.ndarray
        (N, nc) N, on the journal along the tangent.
    contact_force : numpy.ndarray
        (N, nc, 2) N, the total contact force on the journal, x and y.
    sliding_speed : numpy.ndarray
        (N, nc) m/s.
    impacts : Impacts
        One row per contact phase, every time and peak located.
    energy : dict of str to numpy.ndarray
        (N,) J each: ``kinetic``, ``gravity``, ``contact`` (elastic), ``total`` (their sum),
        ``drive_work`` (work of the drive torques since t0), ``dissipated`` (by contact damping
        and friction since t0) and ``balance`` = total - total[0] - drive_work + dissipated,
        zero for an exact solution.
    parameter_names : list of str
        The names of the parameter vector's slots.
    parameters : numpy.ndarray
        The parameter vector the run used.
    stats : dict
        The solver's statistics: steps, right-hand side and Jacobian evaluations, events,
        impacts, wall time.
    metadata : dict
        The scene's text, the versions, the model's hash.
    ideal : SimulationResult or None
        The same scene with ideal joints (``compare_ideal=True``).
    wear : WearProfile or None
        Archard wear of the clearance joints, when compiled in.
    accuracy : Accuracy or None
        The run checked at 10x tighter tolerances (``verify=True``).
    sensitivities : Sensitivities or None
        Derivatives of the outputs with respect to named parameters
        (``simulate(..., sensitivities=[...])``).

    Examples
    --------
    >>> import numpy as np
    >>> import jointplay
    >>> result = jointplay.simulate(jointplay.default_scene().with_run(t_end=0.02))
    >>> result.n_samples, result.q.shape, result.tip_position.shape
    (21, (21, 6), (21, 2))
    >>> result.clearance_joints, result.normal_force.shape
    ([2, 3], (21, 2))
    >>> bool(np.max(np.abs(result.energy["balance"])) < 1e-3)  # J: the balance closes
    True
    >>> result.sol(0.0105).shape  # the state between two samples, from the dense output
    (12,)
    """

    scene_name: str
    integrator: str  # "cvodes", "idas", "rk4" or "radau"
    t: np.ndarray  # (N,) s
    coordinate_names: list[str]  # e.g. ["q2", "q3", "ex2", "ey2", "ex3", "ey3"]
    q: np.ndarray  # (N, n) coordinates: rad for angles, m for eccentricities
    u: np.ndarray  # (N, n) their time derivatives
    udot: np.ndarray  # (N, n) accelerations (from the model at each output sample)
    tau: np.ndarray  # (N, ntau) N m, drive torque of each moving joint
    torque_joints: list[int]  # 1-based joints the columns of tau belong to
    tip_position: np.ndarray  # (N, 2) m, end effector (tip of the last link, payload)
    tip_velocity: np.ndarray  # (N, 2) m/s
    tip_acceleration: np.ndarray  # (N, 2) m/s^2
    clearance_joints: list[int]
    radial_clearance: np.ndarray  # (nc,) m, Rb - Rj of each clearance joint
    eccentricity: np.ndarray  # (N, nc, 2) m, journal centre minus bearing centre
    penetration: np.ndarray  # (N, nc) m, |e| - c (negative: no contact)
    penetration_rate: np.ndarray  # (N, nc) m/s
    normal_force: np.ndarray  # (N, nc) N, >= 0
    friction_force: np.ndarray  # (N, nc) N, on the journal along the tangent
    contact_force: np.ndarray  # (N, nc, 2) N, total contact force on the journal, x and y
    sliding_speed: np.ndarray  # (N, nc) m/s
    impacts: Impacts
    # Energy (J), each (N,): kinetic, gravity (potential), contact (elastic potential), total
    # (their sum), drive_work (work done by the drive torques since t0), dissipated (by contact
    # damping and friction since t0), and balance = total - total[0] - drive_work + dissipated,
    # which is zero for an exact solution.
    energy: dict[str, np.ndarray]
    parameter_names: list[str]
    parameters: np.ndarray  # the parameter vector the run used
    stats: dict[str, Any]  # solver statistics: steps, rhs / jacobian evaluations, events, wall time
    metadata: dict[str, Any] = field(default_factory=dict)  # scene text, versions, model hash
    ideal: SimulationResult | None = None  # the same scene with ideal joints (--compare-ideal)
    wear: WearProfile | None = None  # Archard wear of the clearance joints, when compiled
    accuracy: Accuracy | None = None  # the run checked at 10x tighter tolerances (verify=True)
    # d outputs / d named parameters (simulate(..., sensitivities=[...])), else None
    sensitivities: Sensitivities | None = None

    @property
    def n_samples(self) -> int:
        return int(self.t.size)

    @property
    def implausible(self) -> str | None:
        """Why this run is not physically plausible (a journal through its bearing, an energy
        balance that does not close), where it was kept with ``run.plausibility = "warn"``;
        None where every check passed or none ran (``"off"``)."""
        text = self.metadata.get("implausible")
        return str(text) if text else None

    # --- The fields SciPy's solve_ivp returns, for code written against it. A run that cannot
    # go on raises SimulationError (time, joint, cause) instead of returning, so a result in
    # hand always reached its end: status 0, success True.

    @property
    def status(self) -> int:
        """0: the integration reached the end of the run (as ``solve_ivp``'s status 0)."""
        return int(self.stats.get("status", 0))

    @property
    def success(self) -> bool:
        """True when the integration reached the end of the run (``status == 0``)."""
        return self.status == 0

    @property
    def message(self) -> str:
        """What happened, in words."""
        if self.success:
            return (f"The solver ({self.integrator}) reached the end of the run, "
                    f"t = {float(self.t[-1]):g} s, with {len(self.impacts)} contact phases.")
        return str(self.stats.get("message", f"status {self.status}"))

    @property
    def nfev(self) -> int:
        """Evaluations of the right-hand side (the forward dynamics)."""
        return int(self.stats.get("rhs_evaluations", 0))

    @property
    def njev(self) -> int:
        """Evaluations of its Jacobian."""
        return int(self.stats.get("jacobian_evaluations", 0))

    @property
    def nlu(self) -> int:
        """Factorisations of the Newton matrix: LU decompositions for bdf, linear-solver
        set-ups for cvodes and idas, one per step for radau (its inverse is taken once per
        step), none for rk4."""
        if "lu_decompositions" in self.stats:
            return int(self.stats["lu_decompositions"])
        if self.integrator == "radau":
            return int(self.stats.get("steps", 0))
        return 0

    @property
    def sol(self) -> DenseSolution:
        """The state x = (q, u) at any time of the run: ``result.sol(t)`` with a scalar t
        gives shape (n,), with a 1-D array (n, m), like ``solve_ivp``'s ``sol``.

        From the integrator's dense output for a result just simulated with ``bdf``,
        ``cvodes`` or ``idas``; otherwise (fixed-step methods, results read from a file) a
        cubic Hermite interpolant of the samples. ``sol.method`` says which and
        ``sol.accuracy`` what error to expect (see :mod:`jointplay.results.solution`).
        """
        from jointplay.results.solution import sample_solution

        dense = self.__dict__.get("_dense")
        if dense is not None:
            return dense
        why = ("a fixed-step run" if self.integrator in ("rk4", "radau")
               else "the integrator's dense output lives only in the run that made it; this "
                    "result was read or rebuilt")
        return sample_solution(self, why)

    def __getstate__(self) -> dict[str, Any]:
        # The dense output holds the live integrator (compiled code, closures): it does not
        # travel (pickle, Dask workers, deepcopy); a copy's ``sol`` interpolates the samples.
        state = dict(self.__dict__)
        state.pop("_dense", None)
        return state

    def with_dense_output(self, solution: DenseSolution) -> SimulationResult:
        """This result with ``solution`` as its ``sol`` (set by the simulator)."""
        object.__setattr__(self, "_dense", solution)
        return self

    def with_accuracy(self, accuracy: Accuracy) -> SimulationResult:
        """A copy of this result with its accuracy statement. The copy keeps this run's dense
        output: the statement describes the trajectory, it does not change it (a plain
        ``dataclasses.replace`` would drop the dense output, and the copy's orbits would be
        interpolated between samples)."""
        from dataclasses import replace

        copy = replace(self, accuracy=accuracy)
        dense = self.__dict__.get("_dense")
        return copy.with_dense_output(dense) if dense is not None else copy

    @property
    def eccentricity_columns(self) -> dict[int, tuple[int, int]]:
        """Columns of (ex, ey) in q, u and udot for each clearance joint.

        The model's coordinate order (:func:`jointplay.robot.structure.coordinate_layout`):
        the joint angles first, then (ex, ey) joint by joint in ``clearance_joints`` order.
        """
        return eccentricity_columns(self.coordinate_names, self.clearance_joints)

    @property
    def coordinate_units(self) -> list[str]:
        """SI unit of each coordinate: rad for angles, m for eccentricities."""
        units = ["rad"] * len(self.coordinate_names)
        for columns in self.eccentricity_columns.values():
            for c in columns:
                units[c] = "m"
        return units

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset`` with dimensions time, joint, coordinate (see
        :func:`jointplay.results.export.result_dataset`)."""
        from jointplay.results.export import result_dataset

        return result_dataset(self)
