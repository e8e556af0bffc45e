"""Archard wear of the clearance joints: the record a run returns, its files and its plot.

A robot description with ``[wear] model = "archard"`` compiles, per clearance joint, the
integrands of Archard's law (J. F. Archard, J. Appl. Phys. 24:981, 1953; for revolute
clearance joints, P. Flores, Mech. Mach. Theory 44:1211, 2009): the worn volume grows as
k F_n |v_t| / H, and locally the depth as k p |v_t| / H under the contact pressure p, taken as
Hertz's elliptical line-contact pressure over the contact arc (see jointplay.derive.wear).
The compiled loop integrates both over every step it takes (Gauss-Legendre on its dense
output, never the output samples), the depth exactly over each of ``WEAR_BINS`` angular bins
around the bearing (in the frame of the bearing's link) and around the journal (in the frame
of the journal's link). Each bin holds its mean depth, so that the volume is the integral of
the depth over either surface: V = sum(depth) * R L * 2 pi / bins.

One wear coefficient and hardness hold for both surfaces, so bearing and journal lose the same
volume, spread differently: the bearing where the journal presses on it, the journal all
round when it turns. The depth is a record of the run: the geometry is not updated with it.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

# Angular bins around each surface (1 degree).
WEAR_BINS = 360
SURFACES = ("bearing", "journal")


@dataclass(frozen=True)
class WearProfile:
    """Archard wear integrated over a run, per clearance joint (order: ``joints``)."""

    joints: list[int]  # 1-based joint numbers
    angle: np.ndarray  # (bins,) rad, bin centres, in the frame of the surface's link
    bearing_depth: np.ndarray  # (nc, bins) m, mean worn depth over each bin of the bearing
    journal_depth: np.ndarray  # (nc, bins) m, same on the journal
    volume: np.ndarray  # (nc,) m^3, worn volume of each surface (the same for both)

    @property
    def bins(self) -> int:
        return int(self.angle.size)

    def depth(self, surface: str) -> np.ndarray:
        return self.bearing_depth if surface == "bearing" else self.journal_depth

    def integrated_volume(self, surface: str, radius: np.ndarray,
                          length: np.ndarray) -> np.ndarray:
        """Integral of the depth over the surface, (nc,) m^3 (radius, length per joint)."""
        width = 2 * np.pi / self.bins
        return self.depth(surface).sum(axis=1) * np.asarray(radius) * np.asarray(length) * width


def wear_profile(joints: list[int], volume: np.ndarray, depth: np.ndarray) -> WearProfile:
    """The record from the loop's arrays: volume (nc,), depth (2, nc, bins)."""
    bins = depth.shape[-1]
    angle = (np.arange(bins) + 0.5) * 2 * np.pi / bins
    return WearProfile(joints=list(joints), angle=angle, bearing_depth=depth[0].copy(),
                       journal_depth=depth[1].copy(), volume=volume.copy())


# Sweep columns (overall, and per joint with the suffix _joint{j}).
WEAR_METRICS = ("wear_volume", "max_bearing_wear_depth", "max_journal_wear_depth")


def wear_metrics(wear: WearProfile) -> dict[str, float]:
    """Worn volume (m^3, summed over joints) and deepest wear (m) on bearing and journal."""
    out = {"wear_volume": float(wear.volume.sum()),
           "max_bearing_wear_depth": float(wear.bearing_depth.max()),
           "max_journal_wear_depth": float(wear.journal_depth.max())}
    for k, j in enumerate(wear.joints):
        out[f"wear_volume_joint{j}"] = float(wear.volume[k])
        out[f"max_bearing_wear_depth_joint{j}"] = float(wear.bearing_depth[k].max())
        out[f"max_journal_wear_depth_joint{j}"] = float(wear.journal_depth[k].max())
    return out


# ---------------------------------------------------------------------------------- files

def write_group(parent: Any, wear: WearProfile) -> None:
    """``/wear`` of a result file: angle, bearing_depth, journal_depth, volume."""
    group = parent.create_group("wear", track_order=True)
    group.attrs["doc"] = ("Archard wear integrated over the run: mean depth per angular bin "
                          "around each surface, and the worn volume")
    group.attrs["joints"] = np.asarray(wear.joints, dtype=np.int64)
    for name, data, unit, doc in (
            ("angle", wear.angle, "rad", "bin centres, in the frame of the surface's link"),
            ("bearing_depth", wear.bearing_depth, "m", "(joint, bin) mean depth on the bearing"),
            ("journal_depth", wear.journal_depth, "m", "(joint, bin) mean depth on the journal"),
            ("volume", wear.volume, "m^3", "worn volume per joint (each surface)")):
        ds = group.create_dataset(name, data=np.asarray(data))
        ds.attrs["unit"] = unit
        ds.attrs["doc"] = doc


def read_group(group: Any) -> WearProfile:
    return WearProfile(joints=[int(j) for j in np.asarray(group.attrs["joints"]).ravel()],
                       angle=group["angle"][()], bearing_depth=group["bearing_depth"][()],
                       journal_depth=group["journal_depth"][()], volume=group["volume"][()])


def csv_path(path: str | Path) -> Path:
    """Where the wear table goes beside the samples: ``RUN.csv`` -> ``RUN.wear.csv``."""
    path = Path(path)
    stem = path.name.removesuffix(".csv") if path.suffix == ".csv" else path.name
    return path.with_name(f"{stem}.wear.csv")


def write_csv(wear: WearProfile, path: Path) -> None:
    """One row per angular bin: angle, then per joint the bearing's and the journal's depth;
    the volumes in a last row named ``volume`` (m^3, in each depth column)."""
    from jointplay.common.files import atomic_path

    heads = ["angle [rad]"]
    columns = [wear.angle]
    for k, j in enumerate(wear.joints):
        for surface in SURFACES:
            heads.append(f"{surface}_depth{j} [m]")
            columns.append(wear.depth(surface)[k])
    table = np.column_stack(columns)
    lines = [",".join(heads)]
    lines += [",".join(f"{v:.17g}" for v in row) for row in table]
    lines.append(",".join(["volume [m^3]"] + [f"{wear.volume[k]:.17g}"
                                              for k in range(len(wear.joints))
                                              for _ in SURFACES]))
    with atomic_path(path) as tmp:
        Path(tmp).write_text("\n".join(lines) + "\n", encoding="utf-8")


# ---------------------------------------------------------------------------------- plot

def plot(wear: WearProfile, path: str | Path, title: str = "") -> Path:
    """Polar plot of the worn depth around each bearing and journal (nm or um), angles in
    the frame of each surface's link (PNG, drawn on an Agg canvas without pyplot)."""
    from jointplay.common.figures import figure, save

    nc = len(wear.joints)
    fig, axes = figure(nc, 2, 8.5, 4.4 * nc, projection="polar")
    closed = np.append(wear.angle, wear.angle[0])
    deepest = max(float(wear.bearing_depth.max()), float(wear.journal_depth.max()))
    scale, unit = (1e9, "nm") if deepest < 1e-6 else (1e6, "um")
    for k, j in enumerate(wear.joints):
        for col, surface in enumerate(SURFACES):
            ax = axes[k][col]
            depth = wear.depth(surface)[k] * scale
            ax.plot(closed, np.append(depth, depth[0]), lw=1.2)
            ax.fill(closed, np.append(depth, depth[0]), alpha=0.25)
            top = float(depth.max())
            if top > 0:
                ax.set_rticks(np.round(np.linspace(0, top, 4)[1:], 3))
            link = j - 1 if surface == "bearing" else j
            frame = f"link {link} frame" if link else "ground frame"
            ax.set_title(f"joint {j} {surface} ({frame}): deepest {top:.3g} {unit}\n"
                         f"volume {wear.volume[k] * 1e9:.3g} mm^3", fontsize=9)
            ax.tick_params(labelsize=7)
    if title:
        fig.suptitle(title, fontsize=10)
    return save(fig, path, dpi=110)
