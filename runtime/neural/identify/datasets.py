"""The identification trajectories in HDF5 (``datasets.h5`` of a model folder): one group per
split and run, written atomically, read back with a message naming the file when it is not
one."""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.files import write_hdf5_in_memory
from jointplay.neural.identify.trajectories import ARRAYS, SPLITS, Trajectory

DATA_FORMAT = "jointplay-narx-data"


def write_datasets(path: Path, trajectories: Sequence[Trajectory], meta: dict[str, Any]) -> None:
    write_hdf5_in_memory(path, lambda f: _fill(f, trajectories, meta))


def _fill(f: Any, trajectories: Sequence[Trajectory], meta: dict[str, Any]) -> None:
    """The file's layout, written into an open h5py file."""
    f.attrs["format"] = DATA_FORMAT
    f.attrs["format_version"] = 1
    f.attrs["meta"] = json.dumps(meta)
    f.attrs["doc"] = ("Identification trajectories, one group per split and run. y: plant "
                      "outputs (absolute), r: the ideal robot's, v: torque added to the "
                      "inner loop's from each sample to the next, tau_base: feedforward "
                      "(drives the ideal robot), tau_inner: the inner PD's torque.")
    for split in SPLITS:
        group = f.create_group(split)
        for i, tr in enumerate(t for t in trajectories if t.split == split):
            g = group.create_group(f"{i:03d}")
            for name in ARRAYS:
                g.create_dataset(name, data=getattr(tr, name), compression="gzip",
                                 shuffle=True)
            g.attrs["family"] = tr.family
            g.attrs["seed"] = tr.seed
            g.attrs["description"] = json.dumps(tr.description)


def read_datasets(path: str | Path) -> tuple[list[Trajectory], dict[str, Any]]:
    import h5py

    path = Path(path)
    try:
        with h5py.File(path, "r") as f:
            if f.attrs.get("format") != DATA_FORMAT:
                raise DescriptionError("--model", f"{path}: not a jointplay identification "
                                       "dataset")
            meta = json.loads(f.attrs["meta"])
            out = []
            for split in SPLITS:
                for key in sorted(f[split]):
                    g = f[split][key]
                    arrays = {n: np.array(g[n]) for n in ARRAYS}
                    out.append(Trajectory(split, str(g.attrs["family"]), int(g.attrs["seed"]),
                                          description=json.loads(g.attrs["description"]),
                                          **arrays))
    except (OSError, KeyError, ValueError) as err:
        raise DescriptionError("--model", f"{path}: cannot be read ({err}); the file is "
                               "corrupt: run `jointplay identify` again") from None
    return out, meta



__all__ = ["DATA_FORMAT", "read_datasets", "write_datasets"]
