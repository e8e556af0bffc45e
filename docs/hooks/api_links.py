"""MkDocs hook: names of the public API in the prose link to their entries in the reference.

In every page but the API reference itself, an inline code span that names a public name of
``jointplay`` (those in ``jointplay.__all__``) becomes a cross-reference that mkdocs-autorefs
resolves to the name's entry: ``jointplay.simulate(...)``, ``jp.read``, ``jointplay.Stepper``,
a class written alone (``Robot``, ``SimulationResult``) and a function called
(``simulate(scene)``). Code blocks, headings and spans
already inside a link are left as they are. The names are read from ``runtime/__init__.py``
without importing the package.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path
from typing import Any

from mkdocs.structure.files import Files
from mkdocs.structure.pages import Page

SKIP_PAGES = ("reference/api.md",)
_FENCE = re.compile(r"^(\s*)(```|~~~)")
_names: set[str] = set()


def public_names(package_init: Path) -> set[str]:
    tree = ast.parse(package_init.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign) and any(
                isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets):
            elements = node.value.elts if isinstance(node.value, ast.List | ast.Tuple) else []
            return {str(e.value) for e in elements
                    if isinstance(e, ast.Constant) and not str(e.value).startswith("_")}
    raise ValueError(f"{package_init}: no __all__")


def _span_pattern(names: set[str]) -> re.Pattern[str]:
    qualified = "|".join(sorted(names, key=len, reverse=True))
    classes = "|".join(sorted((n for n in names if n[:1].isupper()), key=len, reverse=True))
    functions = "|".join(sorted((n for n in names if n[:1].islower()), key=len, reverse=True))
    return re.compile(
        r"(?<![\[\w])`(?:(?:jointplay|jp)\.(?P<q>" + qualified + r")\b(?:\([^`]*\))?"
        r"|(?P<c>" + classes + r")|(?P<f>" + functions + r")\([^`]*\))`(?!\]|\()")


def link_names(markdown: str, names: set[str]) -> str:
    """``markdown`` with the API's names in inline code linked to their entries."""
    if not names:
        return markdown
    pattern = _span_pattern(names)
    out, in_fence = [], False
    for line in markdown.splitlines(keepends=True):
        if _FENCE.match(line):
            in_fence = not in_fence
        if in_fence or _FENCE.match(line) or line.lstrip().startswith("#"):
            out.append(line)
            continue
        out.append(pattern.sub(
            lambda m: f"[{m.group(0)}][jointplay.{m.group('q') or m.group('c') or m.group('f')}]",
            line))
    return "".join(out)


def on_config(config: Any, **kwargs: Any) -> Any:
    _names.clear()
    _names.update(public_names(Path(config["config_file_path"]).parent / "runtime" /
                               "__init__.py"))
    return config


def on_page_markdown(markdown: str, page: Page, config: Any, files: Files,
                     **kwargs: Any) -> str:
    if page.file.src_uri in SKIP_PAGES:
        return markdown
    return link_names(markdown, _names)
