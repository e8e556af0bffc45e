"""Every size a user gives, and the limit it is checked against at validation (exit 2).

The limits keep a run's memory and time bounded and its numbers meaningful in float64; they
are far beyond what a study of a clearance robot needs. The README lists them ("Limits").
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

__all__ = [name for name in dir() if name.isupper()]
