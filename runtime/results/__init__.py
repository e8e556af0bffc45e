"""What a simulation returns and where it goes: the result records, HDF5/CSV files, the
ecosystem's shapes (xarray, pandas), per-joint contact summaries, figures and animations."""

from jointplay.results.records import Impacts, SimulationResult

__all__ = ["Impacts", "SimulationResult"]
