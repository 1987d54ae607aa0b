"""``python -m aerostat_core``: see :mod:`aerostat_core.cli`."""

import sys

from .cli import main

sys.exit(main())
