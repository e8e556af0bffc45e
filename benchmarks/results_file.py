"""What writing and reading a results file costs, by way of writing it, side by side.

Two real runs of the paper scene with their ideal counterparts: ``short`` (``--short-t-end``,
output every 1 ms; the size of a README run) and ``series`` (``--series-t-end`` at
``--series-step``; the size of a large sweep series file). For each, the median of
``--repeats`` writes of the same result (wall and CPU time) by:

* ``netcdf_h5py_memory``: the netCDF-4/CF layout with h5py dimension scales, built in memory
  (HDF5 core driver) and written with plain file I/O, with its checksums (Fletcher-32 on
  every numeric variable, the SHA-256 digest of the content): what ``jointplay`` does;
* ``netcdf_h5py_memory_unchecked``: the same without checksums (``checksums=False``: the
  layout's version 2, as written before checksums existed);
* ``netcdf_h5netcdf_memory``: the same layout through h5netcdf, in memory;
* ``netcdf_h5py_disk``: the same layout written by HDF5 straight to the file (no memory
  image): the alternative to the core driver;
* ``legacy_h5py_disk``: the earlier plain-HDF5 layout (no dimensions), straight to the file;
* ``netcdf_netcdf4_memory``: the same layout through netCDF4-python (the netCDF-C library)
  in memory, when that package is importable (it is not a dependency);

and two ways of reading the checked and the unchecked file back: ``jointplay.read`` (which
checks every size, type and shape, and the checksums where the file has them) and
``xarray.open_dataset(...).load()`` (HDF5 verifies Fletcher-32 where present). Bytes are the
file's size. A second table gives what the checksums cost: the checked file's write time,
read time and size over the unchecked one's.

Writes ``results_file.csv`` and ``results_file.md`` into ``--out`` (atomically) and prints
the Markdown.

    python benchmarks/results_file.py --out out/results_file
"""

from __future__ import annotations

import argparse
import csv
import functools
import importlib.util
import io
import os
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

import jointplay
from jointplay.common.files import (
    atomic_path,
    atomic_write_bytes,
    atomic_write_text,
    write_hdf5_in_memory,
)
from jointplay.results import netcdf
from jointplay.results.write import write_hdf5, write_hdf5_v1


def _h5netcdf_memory(result: Any, path: Path) -> None:
    import h5netcdf

    def build(fh: Any) -> None:
        with h5netcdf.File(fh, "w") as nc:
            netcdf.write_file(nc, result)

    write_hdf5_in_memory(path, build)


def _h5py_disk(result: Any, path: Path) -> None:
    import h5py

    with atomic_path(path) as tmp, h5py.File(tmp, "w", track_order=True) as fh:
        netcdf.write_file(netcdf.NetcdfGroup(fh), result)


class _Attrs:
    def __init__(self, target: Any) -> None:
        self.target = target

    def __setitem__(self, key: str, value: Any) -> None:
        self.target.setncattr(key, value)


class _Nc4Variable:
    def __init__(self, var: Any) -> None:
        self.attrs = _Attrs(var)


class _Nc4Group:
    """The layout's few netCDF operations on netCDF4-python (the netCDF-C library)."""

    def __init__(self, group: Any) -> None:
        self.group = group
        self.attrs = _Attrs(group)

    @property
    def dimensions(self) -> dict[str, int]:
        return {name: len(dim) for name, dim in self.group.dimensions.items()}

    @dimensions.setter
    def dimensions(self, sizes: dict[str, int]) -> None:
        for name, size in sizes.items():
            self.group.createDimension(name, size)

    def create_variable(self, name: str, dims: tuple[str, ...], data: Any = None,
                        dtype: Any = None, **options: Any) -> _Nc4Variable:
        values = np.asarray(data)
        kind = str if values.dtype.kind in "UO" else values.dtype
        var = self.group.createVariable(name, kind, dims, zlib="compression" in options)
        if kind is str:
            for i, text in enumerate(values.tolist()):
                var[i] = text
        elif values.size:
            var[...] = values
        return _Nc4Variable(var)

    def create_group(self, name: str) -> _Nc4Group:
        return _Nc4Group(self.group.createGroup(name))


def _netcdf4_memory(result: Any, path: Path) -> None:
    import netCDF4

    ds = netCDF4.Dataset("memory.nc", "w", memory=1 << 16)
    try:
        netcdf.write_file(_Nc4Group(ds), result)
    finally:
        image = ds.close()
    atomic_write_bytes(path, bytes(image))


WRITERS: dict[str, Callable[[Any, Path], None]] = {
    "netcdf_h5py_memory": write_hdf5,
    "netcdf_h5py_memory_unchecked": functools.partial(write_hdf5, checksums=False),
    "netcdf_h5netcdf_memory": _h5netcdf_memory,
    "netcdf_h5py_disk": _h5py_disk,
    "legacy_h5py_disk": write_hdf5_v1,
}
if importlib.util.find_spec("netCDF4") is not None:  # not a dependency: measured if present
    WRITERS["netcdf_netcdf4_memory"] = _netcdf4_memory


def _xarray_read(path: Path) -> None:
    import xarray as xr

    with xr.open_dataset(path) as ds:
        ds.load()


READERS: dict[str, Callable[[Path], Any]] = {"jointplay_read": jointplay.read,
                                             "xarray_load": _xarray_read}


def _medians(action: Callable[[], Any], repeats: int) -> tuple[float, float]:
    """Median wall and CPU seconds of ``repeats`` calls (CPU time is what other processes on
    a shared machine inflate least; wall time includes the file system)."""
    wall, cpu = [], []
    for _ in range(repeats):
        start, start_cpu = time.perf_counter(), time.process_time()
        action()
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return statistics.median(wall), statistics.median(cpu)


def measure(name: str, result: Any, repeats: int, folder: Path) -> list[dict[str, Any]]:
    rows = []
    for writer, write in WRITERS.items():
        path = folder / f"{name}_{writer}.h5"
        wall, cpu = _medians(functools.partial(write, result, path), repeats)
        rows.append({"run": name, "samples": result.n_samples, "action": f"write {writer}",
                     "median_wall_s": wall, "median_cpu_s": cpu,
                     "bytes": path.stat().st_size})
    for kind in ("", "_unchecked"):
        current = folder / f"{name}_netcdf_h5py_memory{kind}.h5"
        for reader, read in READERS.items():
            wall, cpu = _medians(functools.partial(read, current), repeats)
            rows.append({"run": name, "samples": result.n_samples,
                         "action": f"read {reader}{kind}", "median_wall_s": wall,
                         "median_cpu_s": cpu, "bytes": current.stat().st_size})
    base = next(r for r in rows if r["action"] == "write netcdf_h5py_memory")
    for row in rows:
        row["wall_ratio"] = row["median_wall_s"] / base["median_wall_s"]
        row["cpu_ratio"] = row["median_cpu_s"] / base["median_cpu_s"]
    return rows


def cost_rows(rows: list[dict[str, Any]]) -> list[str]:
    """Markdown rows: checked over unchecked, for jointplay's write and both reads."""
    found = {(r["run"], r["action"]): r for r in rows}
    lines = []
    for run in dict.fromkeys(r["run"] for r in rows):
        for checked, unchecked in (("write netcdf_h5py_memory",
                                    "write netcdf_h5py_memory_unchecked"),
                                   ("read jointplay_read", "read jointplay_read_unchecked"),
                                   ("read xarray_load", "read xarray_load_unchecked")):
            a, b = found[(run, checked)], found[(run, unchecked)]
            lines.append(f"| {run} | {checked} | {a['median_wall_s'] / b['median_wall_s']:.2f} "
                         f"| {a['median_cpu_s'] / b['median_cpu_s']:.2f} | "
                         f"{a['bytes'] / b['bytes']:.3f} |")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--short-t-end", type=float, default=0.2)
    parser.add_argument("--series-t-end", type=float, default=2.0)
    parser.add_argument("--series-step", type=float, default=1e-4)
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    scene = jointplay.default_scene()
    runs = {"short": scene.with_run(t_end=args.short_t_end),
            "series": scene.with_run(t_end=args.series_t_end, output_step=args.series_step)}
    rows = []
    load = os.getloadavg()[0]
    with tempfile.TemporaryDirectory(dir=args.out) as tmp:
        for name, run_scene in runs.items():
            result = jointplay.simulate(run_scene, compare_ideal=True, quiet=True)
            rows += measure(name, result, args.repeats, Path(tmp))
    keys = list(rows[0])
    buf = io.StringIO()
    table = csv.DictWriter(buf, keys, lineterminator="\n")
    table.writeheader()
    table.writerows(rows)
    atomic_write_text(args.out / "results_file.csv", buf.getvalue())
    md = [f"Results file: median of {args.repeats} (1-minute load average {load:.1f} before; "
          f"{os.cpu_count()} CPUs); ratios to jointplay's write", "",
          "| run | samples | action | wall s | CPU s | MB | wall ratio | CPU ratio |",
          "|---|---:|---|---:|---:|---:|---:|---:|"]
    md += [f"| {r['run']} | {r['samples']} | {r['action']} | {r['median_wall_s']:.3f} | "
           f"{r['median_cpu_s']:.3f} | {r['bytes'] / 1e6:.2f} | {r['wall_ratio']:.2f} | "
           f"{r['cpu_ratio']:.2f} |" for r in rows]
    md += ["", "What the checksums cost: the checked file over the unchecked one (ratios of "
           "median wall and CPU time, and of size)", "",
           "| run | action | wall ratio | CPU ratio | size ratio |", "|---|---|---:|---:|---:|"]
    md += cost_rows(rows)
    text = "\n".join(md) + "\n"
    atomic_write_text(args.out / "results_file.md", text)
    print(text)


if __name__ == "__main__":
    main()
