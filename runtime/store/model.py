"""A compiled model: load generated C, compile it through the cache, evaluate it cheaply.

Evaluation goes through CasADi's ``Function.buffer``: inputs and outputs are preallocated numpy
arrays handed to the compiled code once, so a call costs a copy in, the C, and a copy out,
not the construction of CasADi matrices (which costs 15-80 us per call).
"""

from __future__ import annotations

import hashlib
import json
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np

from jointplay.common.errors import GeneratedCodeError
from jointplay.robot.structure import Structure
from jointplay.store.build import DEFAULT_CFLAGS, LibraryGone, compile_source
from jointplay.store.layout import Layout

SOURCE_NAME = "model.c"
# The C of what integration and a default run never call (the Jacobian's input blocks, and
# wrappers that pair forward_dynamics with its full Jacobian): compiled on first use, linked
# against model.c's library.
DEFERRED_SOURCE_NAME = "model_deferred.c"
LAYOUT_NAME = "layout.json"
ROBOT_NAME = "robot.toml"
_HASH_LINE = re.compile(r"^ \* input hash: ([0-9a-f]{64})$", re.MULTILINE)


class FastFunction:
    """A compiled CasADi function bound to preallocated float64 buffers.

    ``inputs[i]`` and ``outputs[i]`` are numpy arrays shared with the C code: write inputs in
    place and call :meth:`trigger` for the lowest overhead, or call the object with arrays.
    Outputs are returned as dense arrays (column-major data reshaped to their shape); column
    vectors come back 1-D unless named in ``matrices``.

    Parameters
    ----------
    function : casadi.Function
        The function, loaded from the model's compiled library.
    matrices : frozenset of str, optional
        Outputs that are column vectors but come back 2-D.

    Attributes
    ----------
    function : casadi.Function
        The function.
    name : str
        Its name.
    inputs : list of numpy.ndarray
        The input buffers, one per input (its nonzeros, column-major).
    outputs : list of numpy.ndarray
        The output buffers.
    """

    def __init__(self, function: ca.Function, matrices: frozenset[str] = frozenset()) -> None:
        self.function = function
        self._squeeze = [function.size2_out(i) == 1 and function.name_out(i) not in matrices
                         for i in range(function.n_out())]
        self.name = function.name()
        # Typed as Any: CasADi's stubs list a size argument that its SWIG wrapper takes from
        # the buffer itself.
        self._buffer: Any
        self._buffer, self._trigger = function.buffer()
        self.inputs = [np.zeros(function.nnz_in(i)) for i in range(function.n_in())]
        self.outputs = [np.zeros(function.nnz_out(i)) for i in range(function.n_out())]
        for i, arr in enumerate(self.inputs):
            self._buffer.set_arg(i, arr.data)
        for i, arr in enumerate(self.outputs):
            self._buffer.set_res(i, arr.data)
        self._shapes = [function.size_out(i) for i in range(function.n_out())]
        self._scatter: list[tuple[np.ndarray, np.ndarray] | None] = []
        for i in range(function.n_out()):
            sp = function.sparsity_out(i)
            if sp.is_dense():
                self._scatter.append(None)
            else:
                rows, cols = sp.get_triplet()
                self._scatter.append((np.asarray(rows, int), np.asarray(cols, int)))
        self._in_sizes = [function.nnz_in(i) for i in range(function.n_in())]

    def trigger(self) -> None:
        self._trigger()

    def stats(self) -> dict[str, Any]:
        """Statistics of the last call (for integrators: steps, evaluations...)."""
        return dict(self._buffer.stats())

    def __call__(self, *args: Any) -> list[np.ndarray]:
        if len(args) != len(self.inputs):
            raise TypeError(f"{self.name} takes {len(self.inputs)} inputs "
                            f"({', '.join(self.function.name_in())}), got {len(args)}")
        for i, (arr, value) in enumerate(zip(self.inputs, args, strict=True)):
            v = np.asarray(value, dtype=float).reshape(-1, order="F")
            if v.size != self._in_sizes[i]:
                raise ValueError(f"{self.name}: input {self.function.name_in(i)!r} needs "
                                 f"{self._in_sizes[i]} values, got {v.size}")
            arr[:] = v
        self._trigger()
        return [self._dense(i) for i in range(len(self.outputs))]

    def _dense(self, i: int) -> np.ndarray:
        rows, cols = self._shapes[i]
        scatter = self._scatter[i]
        if scatter is None:
            out = self.outputs[i].reshape((rows, cols), order="F").copy()
        else:
            out = np.zeros((rows, cols))
            out[scatter[0], scatter[1]] = self.outputs[i]
        return out[:, 0] if self._squeeze[i] else out


class Model:
    """A loaded, compiled robot model. Create it with :func:`load_model` (or :func:`model_for`).

    Parameters
    ----------
    folder : pathlib.Path
        The generated folder it was compiled from.
    library : pathlib.Path
        The compiled shared library.
    layout : Layout
        The generated folder's layout (coordinates, parameters, functions).
    compile_seconds : float
        s spent compiling (0 when the cache held it).
    default_parameters : numpy.ndarray or None
        The parameter vector used when a run gives none.
    cflags : tuple of str, optional
        The compiler flags it was built with.

    Attributes
    ----------
    name : str
        The model's name.
    structure : Structure
        What it was generated for.
    coordinates : list of str
        The generalised coordinates' names, in state order.
    parameters : list of str
        The parameter vector's slot names (what ``simulate(parameters=...)`` takes).
    torque_joints : list of int
        The 1-based driven joints.
    clearance_joints : list of int
        The 1-based clearance joints.
    n_coordinates : int
        The number of coordinates.
    n_state : int
        Twice that: the coordinates and their rates.
    default_parameters : numpy.ndarray or None
        As given.
    compile_seconds : float
        As given.
    """

    def __init__(self, folder: Path, library: Path, layout: Layout, compile_seconds: float,
                 default_parameters: np.ndarray | None,
                 cflags: tuple[str, ...] = DEFAULT_CFLAGS) -> None:
        self.folder = folder
        self.library = library
        self.layout = layout
        self.compile_seconds = compile_seconds
        self.name: str = layout.name
        self.structure: Structure = layout.structure
        self.coordinates = layout.coordinate_names
        self.parameters = layout.parameter_names
        self.torque_joints: list[int] = list(layout.torque_joints)
        self.clearance_joints: list[int] = list(layout.clearance_joints)
        self.n_coordinates = len(self.coordinates)
        self.n_state = 2 * self.n_coordinates
        self.default_parameters = default_parameters
        self.cflags = cflags
        self._rebuilt: set[str] = set()  # the libraries compiled again after a failed load
        self._functions: dict[str, FastFunction] = {}
        self.deferred_library: Path | None = None  # compiled on the first call that needs it
        self.deferred_compile_seconds = 0.0

    def __repr__(self) -> str:
        return (f"Model({self.name!r}, coordinates={self.coordinates}, "
                f"parameters={len(self.parameters)}, library={str(self.library)!r})")

    def function(self, name: str) -> FastFunction:
        """The compiled function ``name`` (see layout.json), loaded on first use."""
        if name not in self._functions:
            functions = self.layout.functions
            jacobians = {f.jacobian for f in functions.values()}
            if name not in functions and name not in jacobians \
                    and name not in self.layout.deferred:
                raise KeyError(f"{name!r} is not a function of this model; it has "
                               f"{', '.join(self.layout.functions)}")
            fn = self._external(name, deferred=name in self.layout.deferred)
            plain = name.removeprefix("differentiable_")
            if plain != name and plain in functions:
                matrices = frozenset(s.name for s in functions[plain].outputs if s.matrix)
            elif name in functions:
                matrices = frozenset(s.name for s in functions[name].outputs if s.matrix)
            else:  # a Jacobian: every block is a matrix
                matrices = frozenset(fn.name_out())
            self._functions[name] = FastFunction(fn, matrices)
        return self._functions[name]

    def _external(self, name: str, deferred: bool) -> ca.Function:
        """``name`` from the eager library, or from the deferred one (compiled, once and
        cached, on the first call that needs it, saying so on stderr). A cached library that
        does not load is compiled again once, then loaded again."""
        from jointplay.common.errors import BuildError
        from jointplay.store.build import discard_entry

        if deferred and self.deferred_library is None:
            self.deferred_library, self.deferred_compile_seconds = self._compile_deferred()
        library = self.deferred_library if deferred else self.library
        assert library is not None
        try:
            return ca.external(name, str(library))
        except RuntimeError as err:
            cause = _last_line(err)
            which = "deferred" if deferred else "eager"
            if which in self._rebuilt:
                raise BuildError(f"the compiled model {library} cannot be loaded ({cause})") \
                    from None
            note(f"the compiled model {library} does not load; compiling it again")
            self._rebuilt.add(which)
            discard_entry(library.parent)
            if deferred:
                self.deferred_library, self.deferred_compile_seconds = \
                    self._compile_deferred()
                library = self.deferred_library
            else:
                source, _ = read_generated(self.folder)
                self.library, self.compile_seconds = compile_source(
                    source, self.cflags, what=f"model {self.name!r}")
                self._functions.clear()
                library = self.library
        try:
            return ca.external(name, str(library))
        except RuntimeError as again:
            raise BuildError(f"the compiled model {library} cannot be loaded "
                             f"({_last_line(again)})") from None

    def casadi_function(self, name: str) -> ca.Function:
        """The compiled function as a CasADi ``Function`` (for integrators and AD): a function
        with a generated Jacobian comes from the deferred library, beside that Jacobian, where
        the model has one (CasADi looks a compiled function's Jacobian up in its library)."""
        differentiable = f"differentiable_{name}"
        if differentiable in self.layout.deferred:
            return self.function(differentiable).function
        return self.function(name).function

    def _compile_deferred(self) -> tuple[Path, float]:

        # The eager library first (from the cache, or rebuilt if it was removed): the
        # deferred one is linked against it by its path.
        source, _ = read_generated(self.folder)
        self.library, seconds = compile_source(source, self.cflags,
                                               what=f"model {self.name!r}")
        self.compile_seconds += seconds
        deferred = read_deferred(self.folder, self.layout)

        what = (f"the rest of model {self.name!r} ({', '.join(self.layout.deferred[:2])}, "
                "...: not needed to integrate)")
        # The build holds the eager library (a shared lock) while it links against it; one
        # removed (`jointplay cache clear`) before it was held is compiled again.
        for attempt in range(3):
            try:
                return compile_source(deferred, self.cflags, libraries=(str(self.library),),
                                      what=what)
            except LibraryGone:
                if attempt == 2:
                    raise
                self.library, seconds = compile_source(source, self.cflags)
                self.compile_seconds += seconds
        raise AssertionError("unreachable")

    # ---- parameters ------------------------------------------------------------------------
    def parameter_vector(self, values: Mapping[str, float] | Sequence[float] | None = None,
                         **overrides: float) -> np.ndarray:
        """A parameter vector: the model's defaults, updated by name (or a full sequence)."""
        if values is not None and not isinstance(values, Mapping):
            vec = np.asarray(values, dtype=float).ravel()
            if vec.size != len(self.parameters):
                raise ValueError(f"the parameter vector has {len(self.parameters)} entries "
                                 f"({', '.join(self.parameters)}), got {vec.size}")
            return vec.copy()
        if self.default_parameters is None:
            raise GeneratedCodeError(
                f"{self.folder} has no {ROBOT_NAME} with default values; pass a full vector")
        vec = self.default_parameters.copy()
        for name, value in {**(values or {}), **overrides}.items():
            if name not in self.parameters:
                from jointplay.common.hints import did_you_mean

                raise KeyError(f"{name!r} is not a parameter of this model"
                               + did_you_mean(str(name), self.parameters))
            vec[self.parameters.index(name)] = float(value)
        return vec

    # ---- evaluation ------------------------------------------------------------------------
    def _zeros_if_none(self, value: Any, size: int) -> Any:
        return np.zeros(size) if value is None else value

    def mass_matrix(self, q: Any, p: Any) -> np.ndarray:
        return self.function("mass_matrix")(q, p)[0]

    def forcing(self, x: Any, tau: Any, p: Any, v_imp: Any = None) -> np.ndarray:
        v_imp = self._zeros_if_none(v_imp, len(self.clearance_joints))
        return self.function("forcing")(x, tau, p, v_imp)[0]

    def forward_dynamics(self, x: Any, tau: Any, p: Any, v_imp: Any = None) -> np.ndarray:
        """dx/dt = [u; M(q)^-1 f(x, tau, p, v_imp)]."""
        v_imp = self._zeros_if_none(v_imp, len(self.clearance_joints))
        return self.function("forward_dynamics")(x, tau, p, v_imp)[0]

    def jacobian(self, x: Any, tau: Any, p: Any, v_imp: Any = None) -> dict[str, np.ndarray]:
        """Exact Jacobians of forward_dynamics with respect to x, tau, p and v_imp."""
        v_imp = self._zeros_if_none(v_imp, len(self.clearance_joints))
        blocks = self.function("jac_forward_dynamics")(x, tau, p, v_imp, np.zeros(0))
        return dict(zip(("x", "tau", "p", "v_imp"), blocks, strict=True))

    def contact(self, x: Any, p: Any, v_imp: Any = None) -> dict[str, np.ndarray]:
        """Per clearance joint: delta, delta_dot, v_t, f_n, f_t, f_x, f_y."""
        v_imp = self._zeros_if_none(v_imp, len(self.clearance_joints))
        fn = self.function("contact")
        return dict(zip(fn.function.name_out(), fn(x, p, v_imp), strict=True))

    def energy(self, x: Any, p: Any) -> dict[str, float]:
        fn = self.function("energy")
        return {k: float(v.ravel()[0])
                for k, v in zip(fn.function.name_out(), fn(x, p), strict=True)}

    def end_effector(self, x: Any, udot: Any, p: Any) -> dict[str, np.ndarray]:
        fn = self.function("end_effector")
        return dict(zip(fn.function.name_out(), fn(x, udot, p), strict=True))


def read_generated(folder: str | Path) -> tuple[str, Layout]:
    """Read and cross-check model.c and layout.json of a generated folder."""
    folder = Path(folder)
    try:
        source = (folder / SOURCE_NAME).read_text(encoding="utf-8")
        layout = Layout.from_dict(json.loads((folder / LAYOUT_NAME).read_text(encoding="utf-8")),
                                  str(folder / LAYOUT_NAME))
    except FileNotFoundError as err:
        raise GeneratedCodeError(f"{folder} is not a generated model: {err.filename} is "
                                 "missing; regenerate it with `jointplay derive`") from None
    except json.JSONDecodeError as err:
        raise GeneratedCodeError(f"{folder / LAYOUT_NAME} is not valid JSON ({err}); "
                                 "regenerate it with `jointplay derive`") from None
    except UnicodeDecodeError as err:
        raise GeneratedCodeError(f"{folder}: a generated file is not valid UTF-8 ({err}); "
                                 "regenerate it with `jointplay derive`") from None
    except OSError as err:
        raise GeneratedCodeError(f"{folder}: cannot read the generated files "
                                 f"({err.strerror or err}); regenerate them with "
                                 "`jointplay derive`") from None
    match = _HASH_LINE.search(source[:2000])
    if not match or match.group(1) != layout.input_hash:
        raise GeneratedCodeError(f"{folder}: the input hash of {SOURCE_NAME} does not match "
                                 f"{LAYOUT_NAME}; regenerate the folder with `jointplay derive`")
    body = source[source.find("*/\n") + 3:]
    if hashlib.sha256(body.encode()).hexdigest() != layout.provenance.get("code_sha256"):
        raise GeneratedCodeError(f"{folder / SOURCE_NAME} was edited after it was generated "
                                 "(its checksum does not match layout.json); regenerate it "
                                 "with `jointplay derive` instead of editing it")
    return source, layout


def read_deferred(folder: str | Path, layout: Layout) -> str:
    """The deferred library's C text of a generated folder, checked against layout.json."""
    path = Path(folder) / DEFERRED_SOURCE_NAME
    try:
        source = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise GeneratedCodeError(f"{folder} is not a whole generated model: {path} is "
                                 "missing; regenerate it with `jointplay derive`") from None
    except (OSError, UnicodeDecodeError) as err:
        raise GeneratedCodeError(f"{path} cannot be read ({err}); regenerate the folder with "
                                 "`jointplay derive`") from None
    match = _HASH_LINE.search(source[:3000])
    if not match or match.group(1) != layout.input_hash:
        raise GeneratedCodeError(f"{folder}: the input hash of {DEFERRED_SOURCE_NAME} does not "
                                 f"match {LAYOUT_NAME}; regenerate the folder with "
                                 "`jointplay derive`")
    body = source[source.find("*/\n") + 3:]
    if hashlib.sha256(body.encode()).hexdigest() != layout.provenance.get(
            "deferred_code_sha256"):
        raise GeneratedCodeError(f"{path} was edited after it was generated (its checksum does "
                                 "not match layout.json); regenerate it with `jointplay derive` "
                                 "instead of editing it")
    return source


def read_defaults(folder: Path, layout: Layout) -> np.ndarray | None:
    """The default parameter vector from the folder's robot.toml (None if it has none)."""
    from jointplay.common.errors import DescriptionError
    from jointplay.robot import load_robot

    if not (folder / ROBOT_NAME).exists():
        return None
    try:
        robot = load_robot(folder / ROBOT_NAME)
    except DescriptionError as err:
        raise GeneratedCodeError(f"{folder / ROBOT_NAME} is not a valid robot description "
                                 f"({err.field}: {err.message}); regenerate the folder with "
                                 "`jointplay derive`") from None
    if robot.parameters() and [p.name for p in robot.parameters()] == layout.parameter_names:
        return np.asarray(robot.parameter_values())
    return None


def check_generated(folder: str | Path) -> None:
    """Raise :class:`GeneratedCodeError` unless every file of ``folder`` loads."""
    folder = Path(folder)
    _, layout = read_generated(folder)
    if layout.deferred:
        read_deferred(folder, layout)
    read_defaults(folder, layout)


def load_model(folder: str | Path, cflags: tuple[str, ...] = DEFAULT_CFLAGS) -> Model:
    """Compile (or reuse from the cache) and load the generated model in ``folder``.

    Parameters
    ----------
    folder : str or pathlib.Path
        A generated folder (``generated/NAME`` or one that ``jointplay derive --out`` wrote).
    cflags : tuple of str, optional
        The compiler flags; a different set is a different cached build.

    Returns
    -------
    Model
        The loaded model.

    Raises
    ------
    GeneratedCodeError
        When the folder's files are missing, edited by hand, or stamped by other tool versions.
    BuildError
        When compiling or loading fails.
    """
    folder = Path(folder)
    source, layout = read_generated(folder)
    defaults = read_defaults(folder, layout)
    library, seconds = compile_source(source, cflags, what=f"model {layout.name!r}")
    return Model(folder, library, layout, seconds, defaults, cflags)


def _last_line(err: Exception) -> str:
    """The last line of a loader's error (the one that says why), shortened."""
    return (str(err).strip().splitlines() or ["unknown error"])[-1][:200]


def note(message: str) -> None:
    """A one-line note on stderr (something was repaired; the run goes on)."""
    import sys

    print(f"jointplay: note: {message}", file=sys.stderr)
