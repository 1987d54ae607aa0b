"""How many times each page evaluates designs per rerun: prints a table of call counts.

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_evaluations`` (or copy it
into another checkout to count that one: it only uses names that have long existed).

Every engine entry point below is wrapped with a counter in every loaded module that holds it
(``from x import f`` copies the name), then each page runs headless in Streamlit's AppTest with
empty caches: "cold" is the first run of the page (nothing cached), "warm" a plain rerun after it
(everything the page needs is cached, so it should evaluate nothing). Counted:

- ``design``: :func:`aerostat_core.model.design.design` (one sized or given design with its sweep);
- ``size_volume``: :func:`aerostat_core.model.sizing.size_volume` (a batch of sizings);
- ``constraint_state``: :func:`aerostat_core.model.constraints.constraint_state` (the table at two
  winds for a batch);
- ``evaluate``: :func:`aerostat_core.model.performance.evaluate` (one vectorised trim + tether solve
  of a batch: the evaluation every other entry point ends in);
- ``evaluate_designs``: the optimiser's batch evaluator.

A design given twice the same inputs in one rerun shows as a repeat of ``design``.
"""

from __future__ import annotations

import importlib
import os
import pkgutil
import sys
import threading
import time
from collections import Counter
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

ROOT = Path(__file__).resolve().parents[1]
APP = ROOT / "app.py"

#: (module, function) of the counted entry points.
TARGETS = (
    ("aerostat_core.model.design", "design"),
    ("aerostat_core.model.sizing", "size_volume"),
    ("aerostat_core.model.constraints", "constraint_state"),
    ("aerostat_core.model.performance", "evaluate"),
    ("aerostat_core.optimize", "evaluate_designs"),
)
COUNTS: Counter = Counter()
_LOCK = threading.Lock()


def _import_all() -> None:
    for pkg_name in ("aerostat_core", "app_ui"):
        pkg = importlib.import_module(pkg_name)
        for info in pkgutil.walk_packages(pkg.__path__, pkg_name + "."):
            if info.name.endswith("__main__"):  # the CLI: runs on import
                continue
            try:
                importlib.import_module(info.name)
            except Exception:  # noqa: BLE001 - an optional module that fails to import is skipped
                pass


def _counted(name: str, fn):
    def wrapper(*args, **kwargs):
        with _LOCK:
            COUNTS[name] += 1
        return fn(*args, **kwargs)

    wrapper.__wrapped__ = fn
    wrapper.__name__ = getattr(fn, "__name__", name)
    wrapper.__doc__ = fn.__doc__
    return wrapper


def install_counters() -> list[str]:
    """Wrap every target wherever a loaded module holds it; returns the targets found."""
    _import_all()
    found = []
    for mod_name, fn_name in TARGETS:
        try:
            fn = getattr(importlib.import_module(mod_name), fn_name)
        except (ImportError, AttributeError):
            continue
        found.append(fn_name)
        wrapped = _counted(fn_name, fn)
        for name, mod in list(sys.modules.items()):
            if mod is None or not name.startswith(("aerostat_core", "app_ui")):
                continue
            for attr, value in list(vars(mod).items()):
                if value is fn:
                    setattr(mod, attr, wrapped)
    return found


def _clear_caches() -> None:
    import streamlit as st

    st.cache_data.clear()
    st.cache_resource.clear()


def _button(at, label_start: str):
    for b in at.button:
        if str(b.label).startswith(label_start):
            return b
    raise KeyError(label_start)


def _set(at, key, value) -> None:
    for kind in ("radio", "checkbox", "multiselect", "number_input", "selectbox", "text_input"):
        for el in getattr(at, kind):
            if getattr(el, "key", None) == key:
                el.set_value(value)
                return
    raise KeyError(key)


def _check(at, page: str) -> None:
    if at.exception:
        raise RuntimeError(f"{page}: {[e.value for e in at.exception]}")


def _measure(at, action) -> tuple[Counter, float]:
    COUNTS.clear()
    t0 = time.perf_counter()
    action()
    return Counter(COUNTS), time.perf_counter() - t0


def run_pages() -> list[tuple[str, str, Counter, float]]:
    from streamlit.testing.v1 import AppTest

    out = []

    def fresh():
        _clear_caches()
        return AppTest.from_file(str(APP), default_timeout=600)

    # Design: the app opens on it (practice default, volume sized)
    at = fresh()
    c, t = _measure(at, at.run)
    _check(at, "Design")
    out.append(("Design", "cold", c, t))
    c, t = _measure(at, at.run)
    out.append(("Design", "warm", c, t))

    def page(name: str, path: str, prepare=None, act=None) -> None:
        at = fresh()
        at.run()  # the Design page first, as a user arrives
        _check(at, "Design")
        if prepare is not None:
            prepare(at)
        at.switch_page(path)

        def first():
            at.run()
            if act is not None:
                act(at)

        c, t = _measure(at, first)
        _check(at, name)
        out.append((name, "cold", c, t))
        c, t = _measure(at, at.run)
        _check(at, name)
        out.append((name, "warm", c, t))

    def load_cases(at):
        at.switch_page("pages/2_Compare.py")
        at.run()
        _button(at, "Load the thesis").click()
        at.run()
        _check(at, "Compare")
        at.switch_page("pages/1_Design.py")
        at.run()
        _clear_caches()

    page("Compare (4 GUI cases)", "pages/2_Compare.py", prepare=load_cases)

    def sens_run(at):
        _set(at, "sens_level", "Quick")
        at.button(key="sens_run").click()
        at.run()

    page("Sensitivity (Quick)", "pages/3_Sensitivity.py", act=sens_run)

    def opt_run(at):
        _set(at, "opt_level", "Quick")
        _set(at, "opt_pareto_on", False)
        at.button(key="opt_run").click()
        at.run()

    page("Optimise (Quick, no Pareto)", "pages/4_Optimise.py", act=opt_run)
    page("Shapes", "pages/7_Shapes.py")
    return out


def main() -> None:
    from streamlit import logger

    logger.set_log_level("error")  # "No runtime found" etc. of the headless runs
    found = install_counters()
    rows = run_pages()
    names = [n for _, n in TARGETS if n in found]
    width = max(len(r[0]) for r in rows)
    head = f"{'page':{width}s} {'run':5s} " + " ".join(f"{n:>16s}" for n in names)
    print(f"evaluation calls per page run (root {ROOT})")
    print(head + f" {'time':>8s}")
    for page, kind, counts, t in rows:
        cells = " ".join(f"{counts.get(n, 0):16d}" for n in names)
        print(f"{page:{width}s} {kind:5s} {cells} {t:7.1f}s")


if __name__ == "__main__":
    main()
