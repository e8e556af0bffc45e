"""One way to make and save a figure: an Agg canvas (no display, no global pyplot state) and
an atomic PNG write. matplotlib is imported on first use, so importing a plotting module
costs nothing until a figure is drawn.

A set of figures is drawn by :func:`draw_all`: in this process by default; with
:data:`WORKERS` None, on Linux in a few forked workers at once, each returning its PNG bytes
to the parent, which writes every file itself (so an output transaction of
:func:`jointplay.common.files.all_or_nothing` sees them all).
"""

from __future__ import annotations

import functools
import os
import struct
import sys
import threading
import warnings
import zlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.common import interrupts
from jointplay.common.files import atomic_write_bytes

if TYPE_CHECKING:
    from matplotlib.figure import Figure

DPI = 130
# zlib level of the PNG files: 1 encodes the paper scene's largest figure in 0.6x the time
# of the default 6 (0.083 against 0.137 CPU s, through Pillow), for a file 10 % larger.
PNG_COMPRESSION = 1
# The id (``Line2D.get_gid``) of every drawn journal orbit: the data a reader sees, which a
# check of the figure reads back (compare figures append ":" and the run's label).
ORBIT_GID = "orbit"
# Most workers :func:`draw_all` forks (a figure set has 6-10 figures) when WORKERS is None:
# up to this many, never more than the CPUs this process may use. The default, 1, draws every
# figure in this process: on two cores the forked workers took more wall and CPU time than
# the one process (each pays its share of matplotlib's start-up), and a run of them once
# hung on a worker waiting for the pool's task lock (docs/results/figure-cost.md).
MAX_WORKERS = 4
WORKERS: int | None = 1
# At most this many intervals between the major ticks of a figure laid out at fixed margins.
TICKS_X = 5
TICKS_Y = 4
# The tick spacings allowed, as matplotlib's default locator has them (times a power of 10).
_STEPS = (1, 2, 2.5, 5, 10)

# A figure job draws and saves one figure, returning its path.
FigureJob = Callable[[], Path]

# Set in a drawing worker: save() keeps (path, PNG bytes) here instead of writing.
_captured: list[tuple[Path, bytes]] | None = None
# The jobs of the draw_all call in progress (a forked worker finds them here by index).
_jobs: Sequence[FigureJob] = ()


@dataclass(frozen=True)
class Margins:
    """Fixed geometry of a figure's axes grid, in inches: the space left, right, above and
    below it, and between its rows and columns. A figure laid out this way is drawn once per
    save; a constrained layout measures every text first and draws twice (twice the cost)."""

    left: float = 0.9
    right: float = 0.3
    top: float = 0.6
    bottom: float = 0.6
    between_rows: float = 0.6
    between_cols: float = 0.9


def figure(rows: int, cols: int, width: float, height: float, *,
           sharex: bool = False, margins: Margins | None = None,
           **subplot_kw: Any) -> tuple[Figure, Any]:
    """A figure with a ``rows`` x ``cols`` array of axes (never squeezed): at the fixed
    ``margins`` when given, else in a constrained layout."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), dpi=DPI, layout=None if margins else "constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(rows, cols, squeeze=False, sharex=sharex, subplot_kw=subplot_kw or None)
    if margins is not None:
        cell_width = (width - margins.left - margins.right
                      - (cols - 1) * margins.between_cols) / cols
        cell_height = (height - margins.top - margins.bottom
                       - (rows - 1) * margins.between_rows) / rows
        fig.subplots_adjust(left=margins.left / width, right=1.0 - margins.right / width,
                            bottom=margins.bottom / height, top=1.0 - margins.top / height,
                            wspace=margins.between_cols / cell_width,
                            hspace=margins.between_rows / cell_height)
        for ax in axes.flat:  # each tick is two lines and a text: few, readable ones
            ax.xaxis.set_major_locator(_in_view_locator()(nbins=TICKS_X, steps=_STEPS))
            ax.yaxis.set_major_locator(_in_view_locator()(nbins=TICKS_Y, steps=_STEPS))
    return fig, axes


@functools.cache
def _in_view_locator() -> type:
    """matplotlib's MaxNLocator without the ticks outside the view: it adds one beyond each
    end, and the axis makes (then hides) a tick for each, a third of the ticks made."""
    from matplotlib.ticker import MaxNLocator

    class InViewLocator(MaxNLocator):
        def __call__(self) -> Any:
            locs = super().__call__()
            if self.axis is None:
                return locs
            low, high = sorted(self.axis.get_view_interval())
            slack = 1e-9 * max(high - low, abs(high), abs(low), 1e-300)
            return locs[(locs >= low - slack) & (locs <= high + slack)]

    return InViewLocator


def png_bytes(fig: Figure, *, dpi: int | None = None) -> bytes:
    """The figure drawn on its Agg canvas at ``dpi`` (default :data:`DPI`) as a PNG file's
    bytes: 8-bit RGB where every pixel is opaque (the figures are), else RGBA; rows
    unfiltered, zlib level :data:`PNG_COMPRESSION`.

    Not ``savefig``: Pillow's encoder tries the PNG row filters on every row, which took 5x
    as long as the compression itself (0.107 against 0.019 CPU s on the largest figure of
    the paper scene), for a file no smaller (docs/results/figure-cost.md). The pixels are
    the same.
    """
    import numpy as np

    dpi = DPI if dpi is None else dpi
    if fig.get_dpi() != dpi:
        fig.set_dpi(dpi)
    fig.canvas.draw()
    rgba = np.asarray(fig.canvas.buffer_rgba())  # type: ignore[attr-defined]
    opaque = bool(rgba[..., 3].min() == 255)
    pixels = rgba[..., :3] if opaque else rgba
    height, width, channels = pixels.shape
    rows = np.zeros((height, 1 + width * channels), dtype=np.uint8)  # filter byte 0: none
    rows[:, 1:] = pixels.reshape(height, -1)
    metres = round(dpi / 0.0254)  # pixels per metre, so that viewers know the printed size
    return b"".join([
        _PNG_SIGNATURE,
        _chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2 if opaque else 6, 0, 0,
                                    0)),
        _chunk(b"pHYs", struct.pack(">IIB", metres, metres, 1)),
        _chunk(b"tEXt", b"Software\0" + _software().encode("latin-1")),
        _chunk(b"IDAT", zlib.compress(rows.tobytes(), PNG_COMPRESSION)),
        _chunk(b"IEND", b""),
    ])


_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _chunk(kind: bytes, data: bytes) -> bytes:
    """One PNG chunk: length, type, data, CRC of type and data."""
    return (struct.pack(">I", len(data)) + kind + data
            + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))


def _software() -> str:
    import matplotlib

    return f"matplotlib version {matplotlib.__version__}, https://matplotlib.org/"


def save(fig: Figure, path: Path | str, *, dpi: int | None = None) -> Path:
    """Save as PNG through a temporary name, so a reader never sees a half-written file (in a
    :func:`draw_all` worker: hand the bytes to the parent, which writes them)."""
    path = Path(path)
    data = png_bytes(fig, dpi=dpi)
    if _captured is not None:
        _captured.append((path, data))
    else:
        atomic_write_bytes(path, data)
    return path


# Threads that may run while draw_all forks: tqdm's monitor (started with the first progress
# bar, even a disabled one) only sleeps and, every few seconds, looks at tqdm's own bars,
# which a worker never touches.
FORK_SAFE_THREADS = ("tqdm_monitor",)


def worker_count(jobs: int) -> int:
    """How many workers :func:`draw_all` uses for ``jobs`` figures: 1 (this process) where
    forking is not available or not safe (a thread other than the main one and
    :data:`FORK_SAFE_THREADS` is running)."""
    if WORKERS is not None:
        return max(1, min(WORKERS, jobs))
    others = [t for t in threading.enumerate()
              if t is not threading.main_thread() and t.name not in FORK_SAFE_THREADS]
    if sys.platform != "linux" or others:
        return 1
    return max(1, min(MAX_WORKERS, jobs, len(os.sched_getaffinity(0))))


def capture(jobs: Sequence[FigureJob]) -> list[tuple[Path, bytes]]:
    """Run ``jobs`` here, keeping each saved figure as (path, PNG bytes) instead of writing
    it: the work of a process that draws for another."""
    global _captured
    _captured = []
    try:
        for job in jobs:
            job()
        return _captured
    finally:
        _captured = None


def _draw(index: int) -> list[tuple[Path, bytes]]:
    """Run job ``index`` in a forked worker; its figures as (path, PNG bytes)."""
    return capture([_jobs[index]])


def _ignore_interrupts() -> None:
    """In a worker: Ctrl-C reaches the whole process group, and this process alone stops
    the work (leaving the pool terminates the workers), without a traceback from each."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def warm_up() -> None:
    """Load matplotlib and its fonts here, once (a forked worker inherits them; a figure
    process loads them while the command simulates). Not the math-text parser (0.1 s): the
    default figures write no math."""
    fig, axes = figure(1, 1, 1.0, 1.0)
    axes[0, 0].set_title("F µm")
    axes[0, 0].set_xlabel("0.5")
    fig.canvas.draw()


def draw_all(jobs: Sequence[FigureJob], *, workers: int | None = None) -> list[Path]:
    """Run every job (each draws and saves one figure) and return the paths in job order.

    With more than one worker the jobs run in forked copies of this process, the costliest
    first is best (jobs are handed out in order as workers come free); the files are written
    here, in job order.
    """
    count = worker_count(len(jobs)) if workers is None else max(1, min(workers, len(jobs)))
    if count <= 1:
        return [job() for job in jobs]
    import multiprocessing

    warm_up()
    global _jobs
    _jobs = jobs
    try:
        with warnings.catch_warnings():
            # Python 3.12 warns of fork() in a process with other OS threads (numpy's BLAS
            # pool); a worker only draws with matplotlib and takes none of their locks.
            warnings.filterwarnings("ignore", message=r".*fork\(\) may lead to deadlocks",
                                    category=DeprecationWarning)
            with interrupts.started(lambda: multiprocessing.get_context("fork").Pool(
                    count, initializer=_ignore_interrupts)) as pool:
                drawn = pool.map(_draw, range(len(jobs)), chunksize=1)
    finally:
        _jobs = ()
    paths = []
    for figures in drawn:
        for path, data in figures:
            atomic_write_bytes(path, data)
            paths.append(path)
    return paths
