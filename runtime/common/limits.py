"""Every size a user gives, and the limit it is checked against at validation (exit 2).

The limits keep a run's memory and time bounded and its numbers meaningful in float64; they
are far beyond what a study of a clearance robot needs. docs/reference/limits-and-errors.md lists
them.
"""

from __future__ import annotations

# ---- a scene's run settings ([run], --t-end, --step, ...) ----------------------------------
MAX_T_END = 1.0e5
"""s. Beyond a day of simulated time a run is a mistake (and output times lose precision)."""
MIN_OUTPUT_STEP = 1.0e-9
"""s. Finer outputs than a nanosecond resolve nothing the contact laws describe."""
MAX_OUTPUTS = 2_000_000
"""Output samples of one run (t_end / output_step); about 2 GB of results at 4 links."""
MIN_STEP = 1.0e-12
"""s, the fixed step of rk4 / radau."""
MAX_FIXED_STEPS = 2_000_000_000
"""Fixed steps of one run (t_end / step)."""
MAX_MAX_STEPS = 1_000_000_000
"""run.max_steps, the adaptive integrators' work bound between two outputs."""
MIN_RTOL = 1.0e-14
"""run.rtol; below a few float64 epsilons an error test cannot pass."""
MIN_ATOL = 1.0e-20
"""run.atol (scaled units)."""

# ---- files read ------------------------------------------------------------------------------
MAX_TOML_BYTES = 1 << 20
"""A scene, robot or sweep file (1 MiB): these are hand-written descriptions."""
MAX_TOML_NESTING = 64
"""Nesting of arrays and inline tables in a scene, robot or sweep file (deeper would exhaust
the parser's recursion; a description needs three)."""
MAX_TABLE_BYTES = 256 << 20
"""A torque table (CSV, 256 MiB)."""

# ---- sweeps ----------------------------------------------------------------------------------
MAX_CASES = 1_000_000
"""Cases of one sweep, and values of one swept name (grid num, random count, values)."""

# ---- identification --------------------------------------------------------------------------
MAX_TRAJECTORIES = 10_000
"""identify: --train + --validation + --test."""
MAX_IDENTIFY_SAMPLES = 50_000_000
"""identify: samples over all trajectories ((train + validation + test) x duration / step)."""
MAX_LAGS = 100
"""identify --lags, each."""
MAX_HIDDEN_WIDTH = 4096
"""identify --hidden, each layer's width."""
MAX_HIDDEN_LAYERS = 16
"""identify --hidden, number of layers."""
MAX_ITERATIONS = 100_000
"""identify --iterations, each phase."""
MIN_WINDOW = 2
"""identify --window, the fewest samples."""
MAX_WINDOW = 1_000_000
"""identify --window, samples."""
MAX_WORKERS = 1024
"""--workers of identify and sweep."""

# ---- calibration ----------------------------------------------------------------------------
MAX_MEASURED = 1.0e6
"""A measured tip coordinate (m) or joint angle (rad), in absolute value: beyond any robot's
reach or turning (a scene's initial angles lie within 1e3 rad); larger numbers overflow the
fit's squared residuals."""
MIN_NOISE = 1.0e-15
"""calibrate --noise, the least standard deviation (m or rad): no sensor resolves a
femtometre, and residuals divided by less overflow float64 (1e-320 makes them infinite)."""
MAX_CALIBRATION_RUNS = 100_000
"""Runs of one stage of calibrate: --scan-points, --grid-line-points, --valley-check-points,
--profile-points and --starts each, and the grid's --grid-points squared."""

# ---- physical plausibility ------------------------------------------------------------------
# Every physical number of a robot or scene, whichever door it comes through (a TOML file,
# --set, a sweep, or the Python API's overrides), is checked against these ranges with the
# rest of the input (exit 2). They are wide (orders of magnitude beyond any robot a clearance
# study is about) and only refuse numbers no real robot has, which would otherwise overflow or
# underflow mid-run (an exponent of 1e300, a hardness of 5e-324).
PHYSICAL_RANGES: dict[str, tuple[float, float, str, str]] = {
    # kind: (lowest, highest, unit, what it is)
    "link.length": (1.0e-4, 100.0, "m", "link length"),
    "link.mass": (1.0e-6, 1.0e6, "kg", "link mass"),
    "link.inertia": (1.0e-15, 1.0e9, "kg m^2", "link inertia"),
    "payload.mass": (0.0, 1.0e6, "kg", "payload mass"),
    "joint.angle": (-1.0e3, 1.0e3, "rad", "locked joint angle"),
    "joint.radius": (1.0e-5, 1.0, "m", "bearing or journal radius"),
    "joint.E": (1.0e5, 1.0e13, "Pa", "Young's modulus"),
    "joint.length": (1.0e-5, 10.0, "m", "joint axial length"),
    "gravity": (-1.0e3, 1.0e3, "m/s^2", "gravity component"),
    "contact.exponent": (0.5, 3.0, "", "contact force exponent"),
    "contact.impact_speed_floor": (1.0e-9, 10.0, "m/s", "impact speed floor"),
    "friction.mu": (0.0, 5.0, "", "friction coefficient"),
    "friction.v0": (0.0, 10.0, "m/s", "friction ramp start speed"),
    "friction.v1": (1.0e-9, 100.0, "m/s", "friction ramp end speed"),
    "lubrication.viscosity": (1.0e-6, 1.0e3, "Pa s", "lubricant viscosity"),
    "wear.coefficient": (1.0e-12, 1.0, "", "wear coefficient"),
    "wear.hardness": (1.0e6, 1.0e12, "Pa", "surface hardness"),
    "initial.angle": (-1.0e3, 1.0e3, "rad", "initial joint angle"),
    "initial.speed": (-1.0e4, 1.0e4, "rad/s", "initial joint speed"),
    "initial.eccentricity_rate": (-100.0, 100.0, "m/s", "initial journal speed"),
}
MIN_RADIAL_CLEARANCE = 1.0e-9
"""m, bearing_radius - journal_radius of a joint with play (a nanometre)."""
MIN_RESTITUTION = 1.0e-3
"""contact.restitution, the least: the damping of the Flores and Gonthier laws grows as
1/restitution (1e-300 would collapse the step at the first impact); measured coefficients of
metal impacts are above 0.1."""

# ---- stops during a run (exit 1) ----------------------------------------------------------
MAX_PENETRATION_FRACTION = 0.02
"""Penetration of a journal into its bearing, as a fraction of the journal radius, beyond which
the run stops: the contact laws describe small elastic deformations (micrometres in the
built-in scenes, below 2e-4 of the radius); 2 % of the radius (0.2 mm for a 10 mm journal) is
a state no metal joint survives, reached only from an impossible input."""
MAX_ENERGY_RESIDUAL = 0.01
"""The energy balance's residual (total energy change - drive work + dissipated energy), as a
fraction of the largest energy of the run (kinetic, drive work or dissipated), beyond which
the run stops: the built-in scenes close it to below 5e-4."""

__all__ = [name for name in dir() if name.isupper()]
