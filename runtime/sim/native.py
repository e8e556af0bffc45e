"""The compiled integration loop (driver.c) bound through ctypes.

driver.c is compiled once into the build cache (keyed by its text, like a model) and runs a
whole simulation in one call: the BDF method, the event search, impact-speed capture, the
quadratures and the dense outputs. It calls the model's generated functions through
pointers taken from the model's own library, so it is never rebuilt for a new robot, and
scene torques are handed over as data (a postfix program or a table), so a new torque never
needs a compiler either.
"""

from __future__ import annotations

import ctypes
import functools
import math
from collections.abc import Collection
from importlib import resources
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from jointplay.common.errors import SimulationError
from jointplay.results.wear import WEAR_BINS
from jointplay.scene.expressions import TimeFunction
from jointplay.sim.torque_data import TorqueData as TorqueData
from jointplay.sim.torque_data import torque_data
from jointplay.sim.torque_data import traced_program as traced_program
from jointplay.store.build import compile_source
from jointplay.store.model import FastFunction, Model


class _FunctionNames(Protocol):
    @property
    def functions(self) -> Collection[str]: ...


class _WearSetting(Protocol):
    @property
    def wear(self) -> object | None: ...


class IntegratorModel(Protocol):
    """What the compiled loop asks of a model: an arm's :class:`jointplay.store.Model` or a
    mechanism's :class:`jointplay.mechanism.model.MechanismModel`."""

    @property
    def library(self) -> Path: ...
    @property
    def n_state(self) -> int: ...
    @property
    def n_coordinates(self) -> int: ...
    @property
    def clearance_joints(self) -> list[int]: ...
    @property
    def torque_joints(self) -> list[int]: ...
    @property
    def layout(self) -> _FunctionNames: ...
    @property
    def structure(self) -> _WearSetting: ...

    def function(self, name: str) -> FastFunction: ...


# driver.c's status codes (enum at its top) and what each means to a user.
OK, TOO_MUCH_WORK, STEP_COLLAPSED, NONFINITE, INTERRUPTED, BAD_TORQUE, CHATTER, NO_MEMORY = \
    range(8)
# Fields of one contact-phase row (enum PH_* in driver.c).
PHASE_COLUMNS = ("joint", "time", "speed", "ex", "ey", "peak_force", "peak_force_time",
                 "max_penetration", "max_penetration_time", "separation_time", "exit_speed",
                 "impulse", "damping_energy", "friction_energy")
STAT_NAMES = ("steps", "rhs_evaluations", "jacobian_evaluations", "lu_decompositions",
              "error_test_failures", "newton_failures", "events", "impacts",
              "reduced_lu_decompositions", "sensitivity_jacobians")
# The driver's own C flags: -O3 (it is small and compiled once; its LU and difference updates
# vectorise, without reassociation, so the results equal -O2's); -fno-math-errno as for models.
NEWTON_MATRICES = ("auto", "full", "reduced")
"""The driver's Newton matrices of a second-order system, by their number in its config."""
DRIVER_CFLAGS = ("-O3", "-fPIC", "-shared", "-fno-math-errno")
DRIVER_WHAT = "the BDF integrator, jointplay/sim/driver.c,"

_int_p = ctypes.POINTER(ctypes.c_int)
_dbl_p = ctypes.POINTER(ctypes.c_double)
_i64_p = ctypes.POINTER(ctypes.c_longlong)


class _Function(ctypes.Structure):
    _fields_ = [("eval", ctypes.c_void_p), ("n_in", ctypes.c_longlong),
                ("n_out", ctypes.c_longlong), ("sz_arg", ctypes.c_longlong),
                ("sz_res", ctypes.c_longlong), ("sz_iw", ctypes.c_longlong),
                ("sz_w", ctypes.c_longlong), ("sparsity_out0", _i64_p)]


class _Config(ctypes.Structure):
    _fields_ = [("nq", ctypes.c_int), ("nx", ctypes.c_int), ("nc", ctypes.c_int),
                ("ntau", ctypes.c_int), ("np", ctypes.c_int),
                ("p", _dbl_p), ("scale", _dbl_p), ("ecc_index", _int_p),
                ("clearance", _dbl_p), ("drive_index", _int_p),
                ("torque_kind", _int_p), ("torque_start", _int_p), ("torque_len", _int_p),
                ("ops", _int_p), ("consts", _dbl_p), ("table_t", _dbl_p), ("table_v", _dbl_p),
                ("rtol", ctypes.c_double), ("atol", ctypes.c_double),
                ("h_max", ctypes.c_double), ("h_init", ctypes.c_double),
                ("max_steps", ctypes.c_long), ("max_events", ctypes.c_long),
                ("max_order", ctypes.c_int),
                ("f", _Function), ("jac", _Function), ("contact", _Function),
                ("wear", _Function), ("wear_bins", ctypes.c_int), ("normal", _Function),
                ("ns", ctypes.c_int), ("dp", _dbl_p), ("dc", _dbl_p), ("s0", _dbl_p),
                ("jac_in", _Function), ("sp_p", _i64_p), ("sp_v", _i64_p),
                ("sens_errcon", ctypes.c_int), ("sens_scale", _dbl_p),
                ("dir_in", _Function), ("dir_k", ctypes.c_int),
                ("gap_fn", _Function), ("power_fn", _Function), ("peaks", ctypes.c_int),
                ("newton", ctypes.c_int)]


@functools.cache
def driver_library() -> ctypes.CDLL:
    """driver.c compiled (or taken from the build cache) and loaded."""
    source = resources.files("jointplay.sim").joinpath("driver.c").read_text(encoding="utf-8")
    path, _ = compile_source(source, DRIVER_CFLAGS, what=DRIVER_WHAT)
    try:
        lib = ctypes.CDLL(str(path))
    except OSError as err:  # a damaged cache entry: rebuilt once, like a model's
        from jointplay.store.build import discard_entry
        from jointplay.store.model import note

        note(f"the compiled integrator {path} does not load ({err}); compiling it again")
        discard_entry(path.parent)
        path, _ = compile_source(source, DRIVER_CFLAGS, what=DRIVER_WHAT)
        lib = ctypes.CDLL(str(path))
    lib.jp_create.restype = ctypes.c_void_p
    lib.jp_create.argtypes = [ctypes.POINTER(_Config)]
    lib.jp_free.argtypes = [ctypes.c_void_p]
    lib.jp_reset.argtypes = [ctypes.c_void_p, ctypes.c_double, _dbl_p]
    lib.jp_hold.argtypes = [ctypes.c_void_p, _dbl_p]
    lib.jp_integrate.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_long, _dbl_p,
                                 _dbl_p, _dbl_p]
    lib.jp_current.argtypes = [ctypes.c_void_p, _dbl_p]
    lib.jp_n_phases.restype = ctypes.c_long
    lib.jp_n_phases.argtypes = [ctypes.c_void_p]
    lib.jp_phases.argtypes = [ctypes.c_void_p, _dbl_p]
    lib.jp_flags.argtypes = [ctypes.c_void_p, _dbl_p, _dbl_p]
    lib.jp_stats.argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_long)]
    lib.jp_failure.argtypes = [ctypes.c_void_p, _dbl_p, _dbl_p, _int_p]
    lib.jp_n_state.argtypes = [ctypes.c_void_p]
    lib.jp_wear.argtypes = [ctypes.c_void_p, _dbl_p, _dbl_p]
    lib.jp_sens_record.argtypes = [ctypes.c_void_p]
    lib.jp_phase_sens.argtypes = [ctypes.c_void_p, _dbl_p]
    lib.jp_map.argtypes = [ctypes.POINTER(_Function), ctypes.c_long, ctypes.c_void_p,
                           ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
    if lib.jp_phase_fields() != len(PHASE_COLUMNS):
        raise RuntimeError("driver.c and native.py disagree on the phase record")
    return lib


@functools.cache
def _model_library(path: str) -> ctypes.CDLL:
    lib = ctypes.CDLL(path)
    if lib.model_casadi_int_size() != ctypes.sizeof(ctypes.c_longlong):
        raise RuntimeError(f"{path}: casadi_int is not 64-bit; the driver cannot call it")
    return lib


def _function(model: IntegratorModel, name: str,
              library: str | None = None) -> tuple[_Function, Any]:
    """The generated function ``name`` of the model's eager library (or of ``library``)."""
    lib = _model_library(library or str(model.library))
    fn = _Function()
    fn.eval = ctypes.cast(getattr(lib, name), ctypes.c_void_p).value
    n_in = getattr(lib, f"{name}_n_in")
    n_in.restype = ctypes.c_longlong
    n_out = getattr(lib, f"{name}_n_out")
    n_out.restype = ctypes.c_longlong
    fn.n_in, fn.n_out = n_in(), n_out()
    sizes = [ctypes.c_longlong() for _ in range(4)]
    getattr(lib, f"{name}_work")(*(ctypes.byref(s) for s in sizes))
    fn.sz_arg, fn.sz_res, fn.sz_iw, fn.sz_w = (s.value for s in sizes)
    sparsity = getattr(lib, f"{name}_sparsity_out")
    sparsity.restype = _i64_p
    fn.sparsity_out0 = sparsity(ctypes.c_longlong(0))
    return fn, lib


def _ptr(array: np.ndarray, kind: Any) -> Any:
    return array.ctypes.data_as(kind)


class SensitivityInputs:
    """What the loop needs to integrate sensitivities beside the state: each named
    parameter's direction in the parameter vector (ns, np), its change of each clearance
    (ns, nc), the initial state's derivative (ns, nx, unscaled), and with ``error_control``
    the parameters' sizes (ns) that weigh the sensitivities in the error test."""

    def __init__(self, directions: np.ndarray, clearance: np.ndarray,
                 initial: np.ndarray, sizes: np.ndarray | None = None,
                 error_control: bool = False) -> None:
        self.directions = np.ascontiguousarray(directions, dtype=np.float64)
        self.clearance = np.ascontiguousarray(clearance, dtype=np.float64)
        self.initial = np.ascontiguousarray(initial, dtype=np.float64)
        self.sizes = np.ascontiguousarray(sizes if sizes is not None
                                          else np.ones(self.directions.shape[0]),
                                          dtype=np.float64)
        self.error_control = bool(error_control)

    @property
    def count(self) -> int:
        return int(self.directions.shape[0])


class NativeIntegrator:
    """One compiled run object: a model, a parameter vector, torques and tolerances.

    ``reset(x0)`` puts it at t = 0; ``integrate(t_end, t_out)`` advances to ``t_end`` and
    returns the states, quadratures and captured approach speeds at ``t_out``; ``hold(u)``
    adds constant torques from now on (closed-loop control). With ``sensitivities``, each
    output row also holds d state / d parameter (after the quadratures, one block of nx per
    parameter, scaled like the state: see :meth:`sensitivity_rows`). ``peaks=False``: no
    phase's peak normal force is located (its columns NaN); the trajectory is the same.
    ``newton``: the Newton matrix a second-order system's steps factor ("auto", "full" or
    "reduced": see :func:`jointplay.simulate`).
    """

    def __init__(self, model: IntegratorModel, p: np.ndarray, scale: np.ndarray,
                 ecc_index: np.ndarray, clearance: np.ndarray, drive_index: np.ndarray,
                 torques: tuple[TimeFunction, ...], *, rtol: float, atol: float,
                 max_steps: int, max_events: int, max_order: int = 5,
                 h_max: float = math.inf,
                 h_init: float = 0.0, sensitivities: SensitivityInputs | None = None,
                 model_gaps: bool = False, peaks: bool = True, newton: str = "auto") -> None:
        self.lib = driver_library()
        self.model = model
        self.nx = model.n_state
        self.nc = len(model.clearance_joints)
        self.ntau = len(model.torque_joints)
        # Arrays the C side points into: kept alive as attributes.
        self._p = np.ascontiguousarray(p, dtype=np.float64)
        self._scale = np.ascontiguousarray(scale, dtype=np.float64)
        self._ecc = np.ascontiguousarray(ecc_index, dtype=np.int32).reshape(-1)
        self._clearance = np.ascontiguousarray(clearance, dtype=np.float64)
        self._drive = np.ascontiguousarray(drive_index, dtype=np.int32)
        self._torques = torque_data(torques)
        self._ecc_buf = self._ecc if self._ecc.size else np.zeros(1, np.int32)
        self._clr_buf = self._clearance if self._clearance.size else np.zeros(1)
        self._drive_buf = self._drive if self._drive.size else np.zeros(1, np.int32)
        cfg = _Config()
        cfg.nq, cfg.nx, cfg.nc = model.n_coordinates, self.nx, self.nc
        cfg.ntau, cfg.np = self.ntau, self._p.size
        cfg.p, cfg.scale = _ptr(self._p, _dbl_p), _ptr(self._scale, _dbl_p)
        cfg.ecc_index = _ptr(self._ecc_buf, _int_p)
        cfg.clearance = _ptr(self._clr_buf, _dbl_p)
        cfg.drive_index = _ptr(self._drive_buf, _int_p)
        td = self._torques
        cfg.torque_kind, cfg.torque_start = _ptr(td.kind, _int_p), _ptr(td.start, _int_p)
        cfg.torque_len, cfg.ops = _ptr(td.length, _int_p), _ptr(td.ops, _int_p)
        cfg.consts, cfg.table_t = _ptr(td.consts, _dbl_p), _ptr(td.table_t, _dbl_p)
        cfg.table_v = _ptr(td.table_v, _dbl_p)
        cfg.rtol, cfg.atol, cfg.h_max, cfg.h_init = rtol, atol, h_max, h_init
        cfg.max_steps, cfg.max_events = max_steps, max_events
        cfg.max_order = max_order
        cfg.peaks = int(peaks)
        cfg.newton = NEWTON_MATRICES.index(newton)
        # Loading through the model first heals a damaged cached library (model.function
        # rebuilds it once); the driver then calls into the library that loads.
        # The state block of the Jacobian alone, where the model has it as its own function.
        jacobian = ("jac_state" if "jac_state" in model.layout.functions
                    else "jac_forward_dynamics")
        for name in ("forward_dynamics", jacobian, "contact")[:3 if self.nc else 2]:
            model.function(name)
        cfg.f, _ = _function(model, "forward_dynamics")
        cfg.jac, _ = _function(model, jacobian)
        if self.nc:
            cfg.contact, _ = _function(model, "contact")
            # The normal forces alone, for the event scan's samples, where the model has them
            # as their own function (generated since; without it the scan reads contact's).
            if "normal_force" in model.layout.functions:
                model.function("normal_force")
                cfg.normal, _ = _function(model, "normal_force")
        # Archard wear, integrated in the loop, for a model generated with it.
        self.wear_bins = WEAR_BINS if model.structure.wear is not None else 0
        if self.wear_bins:
            model.function("wear")
            cfg.wear, _ = _function(model, "wear")
            cfg.wear_bins = self.wear_bins
        if model_gaps:
            # A mechanism: its cut clearance joints' gaps and its driver's power come from
            # the model (functions "gaps" and "drive_power"), not from coordinates.
            cfg.gap_fn, _ = _function(model, "gaps")
            cfg.power_fn, _ = _function(model, "drive_power")
        self.n_sensitivities = 0
        if sensitivities is not None and sensitivities.count:
            if not isinstance(model, Model):
                raise TypeError("parameter sensitivities need an arm's model "
                                f"(jointplay.store.Model), got {type(model).__name__}")
            self._sensitivity_config(cfg, model, sensitivities)
        self._config = cfg
        handle = self.lib.jp_create(ctypes.byref(cfg))
        if not handle:
            raise MemoryError("the integrator could not allocate its work arrays")
        self._handle = ctypes.c_void_p(handle)
        self.n_values = int(self.lib.jp_n_state(self._handle))
        self.n_quadratures = self.n_values - self.nx - self.n_sensitivities * self.nx

    def _sensitivity_config(self, cfg: _Config, model: Model,
                            sens: SensitivityInputs) -> None:
        """Point the loop at the sensitivity inputs and the model's parameter Jacobians (its
        deferred library, compiled on first use)."""
        from jointplay.derive.deferred import INPUT_DIRECTIONAL, INPUT_JACOBIANS

        self._sens = sens
        self.n_sensitivities = sens.count
        model.function(INPUT_JACOBIANS)
        library = str(model.deferred_library)
        cfg.ns = sens.count
        cfg.dp, cfg.s0 = _ptr(sens.directions, _dbl_p), _ptr(sens.initial, _dbl_p)
        self._dc_buf = sens.clearance if sens.clearance.size else np.zeros(1)
        cfg.dc = _ptr(self._dc_buf, _dbl_p)
        cfg.jac_in, lib = _function(model, INPUT_JACOBIANS, library)
        pattern = getattr(lib, f"{INPUT_JACOBIANS}_sparsity_out")
        pattern.restype = _i64_p
        cfg.sp_p = pattern(ctypes.c_longlong(1))
        cfg.sp_v = pattern(ctypes.c_longlong(2))
        cfg.sens_errcon = int(sens.error_control)
        cfg.sens_scale = _ptr(sens.sizes, _dbl_p)
        # The forcing along the named directions by forward-mode AD, where the model has it
        # (generated since; without it the loop reads the full input blocks of jac_in).
        if INPUT_DIRECTIONAL in model.layout.deferred:
            cfg.dir_in, _ = _function(model, INPUT_DIRECTIONAL, library)
            seeds = getattr(lib, f"{INPUT_DIRECTIONAL}_sparsity_in")
            seeds.restype = _i64_p
            cfg.dir_k = int(seeds(ctypes.c_longlong(4))[1])

    def sensitivity_rows(self, values: np.ndarray) -> np.ndarray:
        """d state / d parameter (rows, nx, ns), unscaled, from output rows of integrate."""
        start = self.nx + self.n_quadratures
        blocks = values[:, start:start + self.n_sensitivities * self.nx]
        scaled = blocks.reshape(values.shape[0], self.n_sensitivities, self.nx)
        return np.transpose(scaled * self._scale[None, None, :], (0, 2, 1))

    def phase_sensitivities(self) -> np.ndarray:
        """The phases' sensitivity records (n_phases, record): see driver.c, sens_peak."""
        n = int(self.lib.jp_n_phases(self._handle))
        size = int(self.lib.jp_sens_record(self._handle))
        out = np.zeros((n, size))
        if n and self.n_sensitivities:
            self.lib.jp_phase_sens(self._handle, _ptr(out, _dbl_p))
        return out

    def __del__(self) -> None:
        handle = getattr(self, "_handle", None)
        if handle is not None and handle.value:
            self.lib.jp_free(handle)
            # Cleared in place: at interpreter shutdown the ctypes module global may already
            # be gone, and a new c_void_p could not be made.
            handle.value = None

    def reset(self, x0: np.ndarray, t0: float = 0.0) -> None:
        x = np.ascontiguousarray(x0, dtype=np.float64)
        self.lib.jp_reset(self._handle, float(t0), _ptr(x, _dbl_p))

    def hold(self, u: np.ndarray) -> None:
        held = np.ascontiguousarray(u, dtype=np.float64)
        if held.size == 0:
            held = np.zeros(1)
        self.lib.jp_hold(self._handle, _ptr(held, _dbl_p))

    def integrate(self, t_end: float, t_out: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
        """Values (n_out, nx + nquad) and approach speeds (n_out, nc) at ``t_out``, and the
        status code (OK unless the run failed or was interrupted)."""
        times = np.ascontiguousarray(t_out, dtype=np.float64)
        values = np.full((times.size, self.n_values), np.nan)
        speeds = np.zeros((times.size, max(self.nc, 1)))
        status = int(self.lib.jp_integrate(self._handle, float(t_end), times.size,
                                           _ptr(times, _dbl_p), _ptr(values, _dbl_p),
                                           _ptr(speeds, _dbl_p)))
        return values, speeds[:, :self.nc], status

    def current(self) -> np.ndarray:
        out = np.zeros(self.n_values)
        self.lib.jp_current(self._handle, _ptr(out, _dbl_p))
        return out

    def flags(self) -> tuple[np.ndarray, np.ndarray]:
        flags, speeds = np.zeros(max(self.nc, 1)), np.zeros(max(self.nc, 1))
        self.lib.jp_flags(self._handle, _ptr(flags, _dbl_p), _ptr(speeds, _dbl_p))
        return flags[:self.nc], speeds[:self.nc]

    def phases(self) -> np.ndarray:
        n = int(self.lib.jp_n_phases(self._handle))
        out = np.zeros((n, len(PHASE_COLUMNS)))
        if n:
            self.lib.jp_phases(self._handle, _ptr(out, _dbl_p))
        return out

    def stats(self) -> dict[str, int]:
        out = (ctypes.c_long * len(STAT_NAMES))()
        self.lib.jp_stats(self._handle, out)
        return dict(zip(STAT_NAMES, (int(v) for v in out), strict=True))

    def wear(self) -> tuple[np.ndarray, np.ndarray] | None:
        """Wear so far, or None without it: volume (nc,) m^3 and mean depth per bin
        (2, nc, bins) m, bearings then journals (see jointplay.results.wear)."""
        if not self.wear_bins:
            return None
        volume = np.zeros(self.nc)
        depth = np.zeros((2, self.nc, self.wear_bins))
        self.lib.jp_wear(self._handle, _ptr(volume, _dbl_p), _ptr(depth, _dbl_p))
        return volume, depth

    def failure(self) -> tuple[float, float, int]:
        t, h, joint = ctypes.c_double(), ctypes.c_double(), ctypes.c_int()
        self.lib.jp_failure(self._handle, ctypes.byref(t), ctypes.byref(h), ctypes.byref(joint))
        return t.value, h.value, joint.value


def raise_for_status(status: int, integ: NativeIntegrator, torque_fields: list[str],
                     joint_of: Any) -> None:
    """Turn a driver status into the exception a user should see."""
    if status == OK:
        return
    t, h, index = integ.failure()
    if status == INTERRUPTED:
        from jointplay.common.interrupts import interrupt

        interrupt()  # recorded as the command line's own handler would have
    if status == BAD_TORQUE:
        raise SimulationError(t, f"the drive torque {torque_fields[index]} is not finite at "
                              f"t = {t:.9g} s; fix the expression or the table there")
    if status == TOO_MUCH_WORK:
        raise SimulationError(t, "too many steps between outputs: raise run.max_steps or relax "
                              "run.rtol / run.atol", joint_of())
    if status == CHATTER:
        raise SimulationError(t, "too many contact transitions between two outputs (contact "
                              "chatter); raise contact.impact_speed_floor or tighten the "
                              "tolerances", joint_of())
    if status == NONFINITE:
        raise SimulationError(t, "the state stopped being finite (NaN or Inf); tighten "
                              "run.rtol / run.atol or check the parameters", joint_of())
    if status == STEP_COLLAPSED:
        raise SimulationError(t, f"the step size collapsed ({h:.3g} s: error test or Newton "
                              "failures repeated); the contact may be too stiff for the "
                              "tolerances, or the motion has diverged: relax run.rtol / "
                              "run.atol, or check the parameters", joint_of())
    raise MemoryError("the integrator ran out of memory for its contact-phase records")


def map_function(model: IntegratorModel, name: str, inputs: list[np.ndarray],
                 count: int) -> list[np.ndarray]:
    """Evaluate the model's function ``name`` on ``count`` samples in one C loop.

    Each input is either one vector used for every sample or an array of ``count`` rows;
    outputs come back as arrays of ``count`` rows (dense; every mapped output is a vector).
    """
    fn, _ = _function(model, name)
    lib = driver_library()
    held = [np.ascontiguousarray(a, dtype=np.float64) for a in inputs]
    in_ptrs = (ctypes.c_void_p * max(len(held), 1))(*(a.ctypes.data if a.size else None
                                                       for a in held))
    in_strides = (ctypes.c_long * max(len(held), 1))(*(
        a.shape[1] if a.ndim == 2 else 0 for a in held))
    # The eager library's own function: only its output sizes are read here, and asking
    # for the differentiable one would compile the deferred library after every run.
    casadi_fn = model.function(name).function
    outs = [np.zeros((count, casadi_fn.nnz_out(i))) for i in range(casadi_fn.n_out())]
    out_ptrs = (ctypes.c_void_p * len(outs))(*(o.ctypes.data if o.size else None
                                               for o in outs))
    out_strides = (ctypes.c_long * len(outs))(*(o.shape[1] for o in outs))
    rc = lib.jp_map(ctypes.byref(fn), count, in_ptrs, in_strides, out_ptrs, out_strides)
    if rc:
        raise RuntimeError(f"{name} failed on a sample (status {rc})")
    return outs
