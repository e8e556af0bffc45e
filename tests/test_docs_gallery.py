"""The gallery (docs/gallery.md) shows every figure the commands draw, and nothing else.

The figure files a command writes are read from the source: every file name ending ``.png``
that the runtime builds (a string or an f-string; ``{joint}`` stands for a joint number and
is written ``N`` on the page, any other field for the name it holds, e.g. ``NAME``,
``STEM``), and the benchmark reports' stems. The page must name each in backticks and show
a picture of it, drawn by ``python docs/gallery/draw.py``.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PAGE = ROOT / "docs" / "gallery.md"
PICTURES = ROOT / "docs" / "img" / "gallery"


def _field(node: ast.FormattedValue) -> str:
    text = ast.unparse(node.value)
    return "N" if text == "joint" else text.rsplit(".", 1)[-1].upper()


def figure_names() -> set[str]:
    """The names of the PNG files the runtime writes, placeholders as the page writes them."""
    names: set[str] = set()
    stems: set[str] = set()
    for path in (ROOT / "runtime").rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                value = node.value
                if re.fullmatch(r"[a-z][a-z0-9_]*\.png", value):
                    names.add(value)
            elif isinstance(node, ast.JoinedStr):
                parts = [p.value if isinstance(p, ast.Constant) else _field(p)
                         for p in node.values if isinstance(p, ast.Constant | ast.FormattedValue)]
                value = "".join(str(p) for p in parts)
                if value.endswith(".png") and "/" not in value and "*" not in value:
                    names.add(value)
            elif (isinstance(node, ast.Call) and ast.unparse(node.func).endswith("write_report")
                  and len(node.args) > 1 and isinstance(node.args[1], ast.Constant)):
                stems.add(str(node.args[1].value))
    if "STEM.png" in names:  # the benchmark reports: one figure per report, named by its stem
        names.discard("STEM.png")
        names |= {f"{stem}.png" for stem in stems}
    return names


def test_the_gallery_lists_exactly_the_figures_the_commands_write() -> None:
    listed = set(re.findall(r"`([A-Za-z0-9_]+\.png)`", PAGE.read_text(encoding="utf-8")))
    written = figure_names()
    assert written, "no figure names found in runtime/"
    assert not written - listed, f"figures missing from docs/gallery.md: {sorted(written - listed)}"
    assert not listed - written, f"docs/gallery.md lists figures no command writes: " \
                                 f"{sorted(listed - written)}"


def test_every_figure_on_the_page_is_drawn() -> None:
    """A picture for every figure (jointN: one joint's; NAME: one example), each on disk."""
    shown = re.findall(r"!\[[^\]]*\]\(img/gallery/([^)]+)\)", PAGE.read_text(encoding="utf-8"))
    missing = [name for name in shown if not (PICTURES / name).is_file()]
    assert not missing, f"run python docs/gallery/draw.py: {missing}"
    unused = sorted({p.name for p in PICTURES.glob("*.png")} - set(shown))
    assert not unused, f"pictures in docs/img/gallery/ the page does not show: {unused}"
    unmatched = set(shown)
    for name in sorted(figure_names()):
        pattern = re.sub(r"[A-Z]+", lambda m: r"\d+" if m[0] == "N" else r"\w+",
                         re.escape(name))
        if name == "NAME.png":
            continue
        found = {s for s in shown if re.fullmatch(pattern, s)}
        assert found, f"docs/gallery.md shows no picture of {name}"
        unmatched -= found
    assert unmatched, "a picture of a sweep's NAME.png"
    assert all(name.count(".") == 2 for name in unmatched), \
        f"pictures that stand for no figure: {sorted(unmatched)}"  # NAME: e.g. friction.mu
