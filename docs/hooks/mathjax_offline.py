"""MkDocs hook: serve MathJax from the site itself, so the math renders with no network.

The script comes from the ``django-static-mathjax`` package (a plain copy of MathJax 3, no
Django needed at build time), installed by the ``docs`` extra. ``tex-svg-full.js`` holds every
TeX extension and draws with SVG paths, so it needs no font files beside it. Its licence
(Apache 2.0) is published beside it.
"""

from __future__ import annotations

from importlib.util import find_spec
from pathlib import Path
from typing import Any

from mkdocs.exceptions import PluginError
from mkdocs.structure.files import File, Files

TARGET = "assets/mathjax"
SCRIPTS = {"es5/tex-svg-full.js": "tex-svg-full.js", "LICENSE": "LICENSE.txt"}


def mathjax_folder() -> Path:
    """The installed copy of MathJax, or a build error saying what to install."""
    spec = find_spec("mathjax")
    if spec is None or not spec.submodule_search_locations:
        raise PluginError("MathJax is not installed: pip install -e '.[docs]'")
    folder = Path(next(iter(spec.submodule_search_locations))) / "static" / "mathjax"
    if not (folder / "es5" / "tex-svg-full.js").is_file():
        raise PluginError(f"{folder}: no es5/tex-svg-full.js; "
                          "reinstall it with pip install -e '.[docs]'")
    return folder


def on_files(files: Files, config: Any, **kwargs: Any) -> Files:
    folder = mathjax_folder()
    for source, name in SCRIPTS.items():
        files.append(File.generated(config, f"{TARGET}/{name}", abs_src_path=str(folder / source)))
    return files
