"""The model store: find generated code for a structure, build it through the compile cache,
and load it for cheap evaluation. Sympy-free: deriving a missing model is the only step that
imports :mod:`jointplay.derive`."""
