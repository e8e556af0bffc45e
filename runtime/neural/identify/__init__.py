"""Identification: the excitation torques (``excitation``), the seeded trajectories
(``trajectories``) and their HDF5 file (``datasets``), the linear ARX and LPV-ARX fits
(``linear_fit``, ``lpv``), training the network (``training``), its errors and report
(``evaluation``), the settings (``config``), and the whole run into a model folder
(``pipeline``).

May import: :mod:`jointplay.neural.model`; never the controller (``control``) nor the
studies (``study``). Choosing the residual weight in closed loop needs the controller: the
caller hands that choice in (:func:`jointplay.neural.study.closed_loop_choice.identify_model`)."""
