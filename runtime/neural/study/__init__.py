"""Controllers compared: every controller on one scene (``comparison``; the ``jointplay
control`` run in ``control_run``, its figures in ``control_plots``), the residual weight
chosen in closed loop (``closed_loop_choice``), and the study over seeds, trajectories and
clearances (``control_study`` over ``cases``, ``runs`` and ``report``).

May import: :mod:`jointplay.neural.model`, :mod:`jointplay.neural.identify` and
:mod:`jointplay.neural.control`."""
