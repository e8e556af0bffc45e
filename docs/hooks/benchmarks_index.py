"""MkDocs hook: the list of benchmark scripts, read from benchmarks/README.md at build time.

The scripts live beside their list in ``benchmarks/``; the site shows that list as it stands
(page ``results/benchmarks.md``), so it never drifts from the folder's own index.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from mkdocs.structure.files import File, Files

PAGE = "results/benchmarks.md"


def on_files(files: Files, config: Any, **kwargs: Any) -> Files:
    source = Path(config["config_file_path"]).parent / "benchmarks" / "README.md"
    text = source.read_text(encoding="utf-8")
    text = text.replace("# Benchmarks\n", "# Benchmark scripts\n\nFrom `benchmarks/README.md`. "
                        "What they measured, with dates: the other pages of "
                        "[Results](index.md).\n", 1)
    files.append(File.generated(config, PAGE, content=text))
    return files
