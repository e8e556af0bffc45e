"""MkDocs hook: a results table drawn as a figure, at build time, from the table itself.

A table preceded by ``<!-- figure: CAPTION -->`` gets a bar chart under it: one group of bars
per row (labelled by the first cell), one bar per numeric column (the first number of each
cell, so ``4.28e-4 / 4.23e-3`` draws the median of a "median / worst" cell). The figure is
drawn from the numbers on the page, so it cannot disagree with them. An axis spanning more
than two decades is drawn logarithmic. Options after the caption, separated by ``;``:
``columns=2,3`` (which columns to draw, counted from 1 with the labels as column 1),
``label=1,2`` (the columns that name a row), ``split=A,B`` (cells holding "a / b": one series
per number, named A and B) and ``unit=TEXT`` (the axis label).
"""

from __future__ import annotations

import io
import posixpath
import re
from typing import Any

from mkdocs.structure.files import File, Files
from mkdocs.structure.pages import Page

FOLDER = "img/tables"
_MARK = re.compile(r"^<!-- figure: (?P<spec>[^>]*?) -->\n(?P<table>(?:\|.*\n?)+)", re.M)
_NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
_drawn: dict[str, list[tuple[str, str]]] = {}


def _cells(line: str) -> list[str]:
    line = line.strip().removeprefix("|").removesuffix("|")
    return [c.strip() for c in re.split(r"(?<!\\)\|", line)]


def _plain(cell: str) -> str:
    return re.sub(r"[*`\\]", "", cell).strip()


def _numbers(cell: str) -> list[float]:
    text = _plain(cell).replace("\u2212", "-").replace("\u00a0", "").replace(" ", "")
    return [float(n) for n in _NUMBER.findall(text)]


def _first_number(cell: str) -> float | None:
    found = _numbers(cell)
    return found[0] if found else None


def _options(spec: str) -> tuple[str, dict[str, str]]:
    caption, *rest = [part.strip() for part in spec.split(";")]
    options = dict(part.split("=", 1) for part in rest if "=" in part)
    return caption, {k.strip(): v.strip() for k, v in options.items()}


def draw(table: str, caption: str, options: dict[str, str]) -> bytes:
    """The SVG of ``table`` (Markdown) as grouped horizontal bars."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    lines = [ln for ln in table.strip().splitlines() if ln.strip()]
    header, rows = _cells(lines[0]), [_cells(ln) for ln in lines[2:]]
    wanted = ([int(c) - 1 for c in options["columns"].split(",")] if "columns" in options
              else list(range(1, len(header))))
    series = []
    split = options["split"].split(",") if "split" in options else []
    for column in wanted:
        cells = [row[column] if column < len(row) else "" for row in rows]
        if split:  # "a / b" cells: one series per number, named by the option
            for k, name in enumerate(split):
                values = [(_numbers(c)[k] if len(_numbers(c)) > k else None) for c in cells]
                series.append((name.strip(), values))
            continue
        values = [_first_number(c) for c in cells]
        if any(v is not None for v in values):
            series.append((_plain(header[column]), values))
    if not series:
        raise ValueError(f"table '{caption}': no numeric column to draw")
    label_columns = [int(c) - 1 for c in options.get("label", "1").split(",")]
    keep = [i for i in range(len(rows)) if any(v[i] is not None for _, v in series)]
    rows = [rows[i] for i in keep]  # a row with nothing to draw (a summary row) is left out
    series = [(name, [values[i] for i in keep]) for name, values in series]
    labels = [" ".join(_plain(row[c]) for c in label_columns) for row in rows]
    height = 0.8 / len(series)
    figure = Figure(figsize=(7.5, 0.9 + 0.32 * len(rows) * max(1, len(series) * 0.6)))
    axes = figure.add_subplot()
    for k, (name, values) in enumerate(series):
        ys = [i + (k - (len(series) - 1) / 2) * height for i in range(len(rows))]
        xs = [v if v is not None else 0.0 for v in values]
        axes.barh(ys, xs, height=height * 0.95, label=name)
    positive = [v for _, values in series for v in values if v is not None and v > 0]
    if positive and max(positive) / min(positive) > 100 and all(
            v is None or v > 0 for _, values in series for v in values):
        axes.set_xscale("log")
    axes.set_yticks(range(len(rows)), labels, fontsize=8)
    axes.invert_yaxis()
    axes.set_xlabel(options.get("unit", ""), fontsize=9)
    axes.tick_params(axis="x", labelsize=8)
    axes.grid(axis="x", alpha=0.3)
    if len(series) > 1:
        axes.legend(fontsize=8, loc="best")
    axes.set_title(caption, fontsize=10)
    figure.tight_layout()
    out = io.StringIO()
    figure.savefig(out, format="svg", metadata={"Date": None})
    return out.getvalue().encode("utf-8")


def on_files(files: Files, config: Any, **kwargs: Any) -> Files:
    _drawn.clear()
    for file in list(files.documentation_pages()):
        text = file.content_string
        for n, match in enumerate(_MARK.finditer(text), start=1):
            caption, options = _options(match["spec"])
            name = f"{FOLDER}/{file.src_uri.removesuffix('.md').replace('/', '-')}-{n}.svg"
            files.append(File.generated(config, name, content=draw(match["table"], caption,
                                                                   options)))
            _drawn.setdefault(file.src_uri, []).append((name, caption))
    return files


def on_page_markdown(markdown: str, page: Page, config: Any, files: Files,
                     **kwargs: Any) -> str:
    figures = iter(_drawn.get(page.file.src_uri, []))

    def add_figure(match: re.Match[str]) -> str:
        name, caption = next(figures)
        link = posixpath.relpath(name, posixpath.dirname(page.file.src_uri) or ".")
        return f"{match['table'].rstrip()}\n\n![{caption}]({link})\n"

    return _MARK.sub(add_figure, markdown)
