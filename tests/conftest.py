"""Shared test configuration.

Hypothesis profiles (``HYPOTHESIS_PROFILE`` picks one; default "ci" when ``CI`` is set, else
"dev"):

* ``ci``: derandomized, so a submission is judged on the same examples every run and CI cannot
  fail at random;
* ``dev``: every run explores new examples (a failure prints its reproducer and is saved in
  .hypothesis/ to be replayed first next time);
* ``explore``: the longer exploration run for developers (``make explore``): randomized, each
  test's example budget times ``HYPOTHESIS_EXPLORE_FACTOR`` (default 10), no shrinking deadline;
  a failure found there becomes a fixed example or a stated domain limit (issue 22 item 7).
"""

import os
import tempfile

from hypothesis import settings

# Saved workspaces of the tests go to a throw-away folder (the app's default is the user's data
# folder); the browser tests' servers inherit it. AEROSTAT_DATABASE_URL is for deployments only.
if not os.environ.get("AEROSTAT_DATA_DIR"):
    os.environ["AEROSTAT_DATA_DIR"] = tempfile.mkdtemp(prefix="aerostat-test-data-")
os.environ.pop("AEROSTAT_DATABASE_URL", None)

# No per-example deadline: hypothesis' default 200 ms is a wall-clock threshold, and on the shared
# 2-core machine a design() took 279 ms under load (speed belongs in benchmarks/).
settings.register_profile("ci", derandomize=True, print_blob=True, deadline=None)
settings.register_profile("dev", print_blob=True, deadline=None)
settings.register_profile("explore", print_blob=True, deadline=None)
PROFILE = os.environ.get("HYPOTHESIS_PROFILE") or ("ci" if os.environ.get("CI") else "dev")
settings.load_profile(PROFILE)


def pytest_collection_modifyitems(config, items):
    """Under the ``explore`` profile, multiply each hypothesis test's own example budget (a
    test's ``@settings(max_examples=...)`` would otherwise cap the profile's)."""
    if PROFILE != "explore":
        return
    factor = int(os.environ.get("HYPOTHESIS_EXPLORE_FACTOR", "10"))
    for item in items:
        fn = getattr(item, "obj", None)
        inner = getattr(fn, "hypothesis", None)
        if inner is None:
            continue
        test = inner.inner_test
        own = getattr(test, "_hypothesis_internal_use_settings", None) or settings.default
        test._hypothesis_internal_use_settings = settings(
            own, max_examples=own.max_examples * factor, derandomize=False)
