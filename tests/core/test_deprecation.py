"""Renamed public names (docs/architecture.md §7): each old British spelling still resolves, to
the very same object, with a DeprecationWarning; unknown names still fail; and nothing in the
library, the tests or the benchmarks uses an old name any more."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
MODULES = (
    "aerostat_core",
    "aerostat_core.optimize",
    "aerostat_core.model.budget",
    "aerostat_core.model.presets",
    "aerostat_core.studies.shape_optimize",
)
RENAMED = [
    (m, old, new)
    for m in MODULES
    for old, new in importlib.import_module(m).DEPRECATED_NAMES.items()
]


def test_the_renames_are_the_british_optimise_spellings() -> None:
    olds = {old for _, old, _ in RENAMED}
    assert {"OptimisationProblem", "OptimisationResult", "OptimisationCancelled"} <= olds
    for _, old, new in RENAMED:
        assert re.search("[Oo]ptimis", old) and not re.search("[Oo]ptimis", new)
        assert re.sub("optimiz", "optimis", re.sub("Optimiz", "Optimis", new)) == old


@pytest.mark.parametrize(("module", "old", "new"), RENAMED, ids=[r[1] for r in RENAMED])
def test_old_name_warns_and_returns_the_new_object(module: str, old: str, new: str) -> None:
    mod = importlib.import_module(module)
    with pytest.warns(DeprecationWarning, match=rf"{module}\.{old} is deprecated; use {new}\b"):
        obj = getattr(mod, old)
    assert obj is getattr(mod, new)
    ns: dict = {}
    with pytest.warns(DeprecationWarning):
        exec(f"from {module} import {old} as alias", ns)
    assert ns["alias"] is obj
    if hasattr(mod, "__all__"):
        assert old not in mod.__all__ and new in mod.__all__


@pytest.mark.parametrize("module", MODULES)
def test_unknown_names_still_raise_attribute_error(module: str) -> None:
    with pytest.raises(AttributeError, match="has no attribute 'no_such_name'"):
        importlib.import_module(module).no_such_name  # noqa: B018


def test_library_tests_and_benchmarks_use_the_new_names_only() -> None:
    pattern = re.compile(r"\b(" + "|".join(old for _, old, _ in RENAMED) + r")\b")
    uses = []
    for folder in ("aerostat_core", "tests", "benchmarks"):
        for f in sorted((ROOT / folder).rglob("*.py")):
            if f.resolve() == Path(__file__).resolve():
                continue
            for n, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1):
                if (
                    pattern.search(line)
                    and "DEPRECATED_NAMES" not in line
                    and not re.match(r'\s*"\w+": "\w+",?$', line)
                ):
                    uses.append(f"{f.relative_to(ROOT)}:{n}: {line.strip()}")
    assert not uses, "\n".join(uses)


def test_dynamics_british_names_warn_and_resolve_to_the_us_ones():
    """``linearise``/``Linearisation`` and the ``realise`` methods keep working for one release."""
    from aerostat_core import dynamics
    from aerostat_core.dynamics import linearize as lin
    from aerostat_core.dynamics.wind import WindScenario

    # (``dynamics.linearise`` is also the old module's name, so the package attribute is the shim
    # module once anything imported it: the old function is reached through that module)
    with pytest.warns(DeprecationWarning, match="Linearization"):
        assert dynamics.Linearisation is lin.Linearization
    with pytest.warns(DeprecationWarning, match="linearize"):
        from aerostat_core.dynamics.linearise import linearise
    assert linearise is lin.linearize
    scenario = WindScenario.steady(5.0)
    with pytest.warns(DeprecationWarning, match="realize"):
        old = scenario.realise(300.0, 10.0)
    new = scenario.realize(300.0, 10.0)
    assert (old.convection_speed, old.hull_height) == (new.convection_speed, new.hull_height) == (5.0, 300.0)
