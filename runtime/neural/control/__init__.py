"""The internal-model controller: its settings (``imc_settings``), what it asks of a model
(``internal_model``), the CasADi step (``imc_step``), the compiled controller (``imc``) and
its loop kernel in C (``imc_kernel``, ``kernel_network``), the mismatch filter for declared
sensor noise (``mismatch_filter``) and the horizon chosen for it (``noise_tuning``), the
closed loop and its laws (``loop``), its metrics (``metrics``) and accuracy statement
(``loop_accuracy``).

May import: :mod:`jointplay.neural.model`; never identification (``identify``: a controller
runs from a model folder, not from training) nor the studies (``study``)."""

# The exit status of ``jointplay control`` and ``control-study`` when a controller diverged
# (README, "Limits, interrupts and errors").
EXIT_DIVERGED = 3
