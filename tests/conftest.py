"""Shared test configuration.

Hypothesis: in CI (``CI`` set) examples are derandomized, so a submission is judged on the same
examples every run; locally every run explores new ones (a failure prints its reproducer).
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
settings.register_profile("dev", print_blob=True)
settings.load_profile("ci" if os.environ.get("CI") else "dev")
