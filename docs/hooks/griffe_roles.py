"""Griffe extension: Sphinx roles in the docstrings read as code in the API reference.

The package's docstrings name other objects the Sphinx way (``:class:`Scene```,
``:func:`simulate```, ``:mod:`jointplay.derive```); Markdown would show the role itself. Each
role becomes its target in backticks, as a reader of the source sees it.
"""

from __future__ import annotations

import re
from typing import Any

import griffe

_ROLE = re.compile(r":(?:py:)?(?:class|func|meth|mod|attr|data|obj|exc|const):`~?([^`]+)`")


class SphinxRoles(griffe.Extension):
    def on_instance(self, *, obj: griffe.Object, **kwargs: Any) -> None:
        if obj.docstring is not None:
            obj.docstring.value = _ROLE.sub(r"`\1`", obj.docstring.value)
