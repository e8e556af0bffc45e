"""The model code identification and the controller share: the NARX network
(``narx_model``) and its model folder (``narx``), the scheduling signals (``scheduling``), the
inner loop the models are identified under (``inner_loop``), the plant every closed loop is
judged on (``plant``), and the network's residual blended against its linear twin (``twin``).

May import: nothing of the other neural packages (``identify``, ``control``, ``study``)."""
