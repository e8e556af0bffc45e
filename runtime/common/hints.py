"""The "did you mean" hint every error message about a misspelt name ends with."""

from __future__ import annotations

import difflib
from collections.abc import Iterable


def did_you_mean(word: str, choices: Iterable[str], *, cutoff: float = 0.6) -> str:
    """``"; did you mean 'x'?"`` for the closest of ``choices`` to ``word``, or ``""``.

    The match ignores case (``Friction.MU`` finds ``friction.mu``) and the hint names the
    choice as it is spelt.
    """
    spelt = {str(c).lower(): str(c) for c in choices}
    close = difflib.get_close_matches(str(word).lower(), list(spelt), n=1, cutoff=cutoff)
    return f"; did you mean {spelt[close[0]]!r}?" if close else ""
