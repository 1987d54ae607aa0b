"""``python -m aerostat_core``: see :mod:`aerostat_core.cli.entry`."""

import sys

from aerostat_core.cli.entry import main

sys.exit(main())
