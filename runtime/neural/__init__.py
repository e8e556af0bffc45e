"""Neural identification and control: datasets and the NARX network, its linear (ARX) twin,
the internal-model controller and its compiled step, closed-loop comparisons and studies.

Importing :mod:`jointplay` does not import torch; these modules do, when used."""
