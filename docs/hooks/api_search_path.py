"""MkDocs hook: let the API reference find the installed package, not the program.

Run as the ``mkdocs`` script, Python puts the script's folder first on ``sys.path``; that
folder also holds the ``jointplay`` program, which griffe would take for the package. The
package is ``runtime/`` installed as ``jointplay``, found through the installed package's own
import machinery once that folder is out of the way.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

from mkdocs.plugins import event_priority


def _drop_scripts_folder() -> None:
    scripts = Path(sys.executable).parent.resolve()
    sys.path[:] = [p for p in sys.path if not p or Path(p).resolve() != scripts]


@event_priority(100)  # before mkdocstrings copies sys.path in its own on_config
def on_config(config: Any, **kwargs: Any) -> Any:
    _drop_scripts_folder()
    return config
