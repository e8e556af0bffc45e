"""One way to make and save a figure: an Agg canvas (no display, no global pyplot state) and
an atomic PNG write. matplotlib is imported on first use, so importing a plotting module
costs nothing until a figure is drawn."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.common.files import atomic_path

if TYPE_CHECKING:
    from matplotlib.figure import Figure

DPI = 130
# The id (``Line2D.get_gid``) of every drawn journal orbit: the data a reader sees, which a
# check of the figure reads back (compare figures append ":" and the run's label).
ORBIT_GID = "orbit"


def figure(rows: int, cols: int, width: float, height: float, *,
           sharex: bool = False, **subplot_kw: Any) -> tuple[Figure, Any]:
    """A constrained-layout figure with a ``rows`` x ``cols`` array of axes (never squeezed)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(rows, cols, squeeze=False, sharex=sharex, subplot_kw=subplot_kw or None)
    return fig, axes


def save(fig: Figure, path: Path | str, *, dpi: int = DPI) -> Path:
    """Save as PNG through a temporary name, so a reader never sees a half-written file."""
    path = Path(path)
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=dpi)
    return path
