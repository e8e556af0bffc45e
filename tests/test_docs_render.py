"""Every documentation page renders as written: a list or a heading that Python-Markdown (the
site's renderer) would merge into the text around it fails here, with the line to fix.

Python-Markdown nests a list only under four spaces of indentation: a sub-list indented by two
or three spaces becomes items of the outer list (renumbering it), and the outer items after it
run together into one paragraph. The pages are rendered with the site's own Markdown
extensions (read from mkdocs.yml) and the HTML is read back: no paragraph may hold a line that
was meant as a heading or a list item.
"""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path
from typing import Any

import pytest

markdown = pytest.importorskip("markdown", reason="the docs extra is not installed")
yaml = pytest.importorskip("yaml", reason="the docs extra is not installed")

ROOT = Path(__file__).resolve().parents[1]
PAGES = sorted((ROOT / "docs").rglob("*.md"))
_FENCE = re.compile(r"^\s*(```|~~~)")
_MARKER = re.compile(r"^(?P<indent> *)(?:[-*+]|\d+[.)])\s+\S")
_MEANT_AS_BLOCK = re.compile(r"^\s*(?:#{1,6}\s+\S|\d+[.)]\s+\S|[-*+]\s+\S)")


def _site_markdown() -> Any:
    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"))
    names, configs = [], {}
    for entry in config["markdown_extensions"]:
        if isinstance(entry, dict):
            [(name, options)] = entry.items()
            configs[name] = options or {}
        else:
            name = entry
        names.append(name)
    if "pymdownx.snippets" in configs:  # snippets are read from the checkout
        configs["pymdownx.snippets"] = {**configs["pymdownx.snippets"], "base_path": [str(ROOT)]}
    return markdown.Markdown(extensions=names, extension_configs=configs)


class _Paragraphs(HTMLParser):
    """The text of every <p>, outside <pre> and <code>."""

    def __init__(self) -> None:
        super().__init__()
        self.paragraphs: list[str] = []
        self._depth = 0
        self._code = 0

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag == "p":
            self._depth += 1
            self.paragraphs.append("")
        elif tag in ("pre", "code"):
            self._code += 1

    def handle_endtag(self, tag: str) -> None:
        if tag == "p":
            self._depth = max(0, self._depth - 1)
        elif tag in ("pre", "code"):
            self._code = max(0, self._code - 1)

    def handle_data(self, data: str) -> None:
        if self._depth and not self._code:
            self.paragraphs[-1] += data


def misindented_list_items(text: str) -> list[int]:
    """Lines (1-based) of list items nested under a list item by other than a multiple of four
    spaces: Python-Markdown makes them siblings of the outer items, not sub-items."""
    bad, in_fence, in_list = [], False, False
    for number, line in enumerate(text.splitlines(), start=1):
        if _FENCE.match(line):
            in_fence = not in_fence
            continue
        if in_fence:
            continue
        marker = _MARKER.match(line)
        if marker:
            if in_list and len(marker["indent"]) % 4:
                bad.append(number)
            in_list = True
        elif not line.strip():
            continue
        elif not line.startswith(" "):
            in_list = False
    return bad


def merged_blocks(html: str) -> list[str]:
    """Lines of rendered paragraphs that were written as a heading or a list item."""
    parser = _Paragraphs()
    parser.feed(html)
    return [line.strip() for text in parser.paragraphs for line in text.splitlines()[1:]
            if _MEANT_AS_BLOCK.match(line)]


def _page_param(page: Path) -> object:
    return pytest.param(page, id=page.relative_to(ROOT).as_posix())


@pytest.mark.parametrize("page", [_page_param(p) for p in PAGES])
def test_page_renders_its_lists_and_headings(page: Path) -> None:
    text = page.read_text(encoding="utf-8")
    bad = misindented_list_items(text)
    assert not bad, (f"{page.relative_to(ROOT)}: list items on lines {bad} are indented by "
                     "other than 4 spaces under a list item; Python-Markdown will not nest them")
    merged = merged_blocks(_site_markdown().convert(text))
    assert not merged, (f"{page.relative_to(ROOT)}: these lines render inside a paragraph, not as "
                        "headings or list items (a blank line or 4-space indent is missing): "
                        f"{merged[:5]}")


def test_the_checks_catch_a_three_space_sub_list() -> None:
    page = "1. Step one:\n   1. sub-step\n   2. sub-step\n2. Step two\n3. Step three\n"
    assert misindented_list_items(page) == [2, 3]
    html = _site_markdown().convert("Some text:\n- not an item\n2. nor this\n")
    assert merged_blocks(html) == ["- not an item", "2. nor this"]
    good = "1. Step one:\n\n    1. sub-step\n\n2. Step two\n"
    assert misindented_list_items(good) == []
    assert merged_blocks(_site_markdown().convert(good)) == []


# ---- length: pages a reader finishes ----------------------------------------------------------

WORDS_IN_ALL = 45_000
WORDS_PER_PAGE = 3_000
WORDS_PER_HOW_TO = 1_500


def words(page: Path) -> int:
    """Whitespace-separated words, as ``wc -w`` counts them."""
    return len(page.read_text(encoding="utf-8").split())


@pytest.mark.parametrize("page", [_page_param(p) for p in PAGES])
def test_page_length(page: Path) -> None:
    limit = WORDS_PER_HOW_TO if page.parent.name == "how-to" else WORDS_PER_PAGE
    assert words(page) <= limit, f"{page.relative_to(ROOT)}: {words(page)} words (at most {limit})"


def test_docs_length_in_all() -> None:
    total = sum(words(p) for p in PAGES)
    assert total <= WORDS_IN_ALL, f"docs/ holds {total} words (at most {WORDS_IN_ALL})"
