"""Neural identification and control, in four packages:

- :mod:`jointplay.neural.model`: the shared model code (the NARX network and its folder, the
  scheduling signals, the inner-loop plant identification sees, the plant every loop is judged
  on, the residual blend against the linear twin);
- :mod:`jointplay.neural.identify`: identification (excitation, datasets, the linear and
  LPV-ARX fits, training, evaluation) into a model folder;
- :mod:`jointplay.neural.control`: the internal-model controller (its settings, compiled step
  and loop kernel, the mismatch filter, the closed loop and its metrics);
- :mod:`jointplay.neural.study`: controllers compared on a scene (``jointplay control``) and
  over seeds, trajectories and clearances (``jointplay control-study``).

``model`` imports none of the others; ``identify`` and ``control`` import ``model`` only;
``study`` may import all three (tests/test_neural_layout.py checks it). Importing
:mod:`jointplay` does not import torch; these modules do, when used."""
