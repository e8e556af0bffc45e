"""``python -m jointplay.cli``: the ``jointplay`` command."""

import sys

from jointplay.cli import main

sys.exit(main())
