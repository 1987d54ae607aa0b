"""Every page app.py lists exists, and a missing one is reported, never dropped silently."""

from __future__ import annotations

import ast
import shutil
from pathlib import Path

import pytest
from streamlit.testing.v1 import AppTest

ROOT = Path(__file__).resolve().parents[2]


def _pages(app: Path) -> list[tuple[str, str, str]]:
    tree = ast.parse(app.read_text())
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == "PAGES" for t in node.targets
        ):
            return list(ast.literal_eval(node.value))
    raise AssertionError("app.py has no PAGES")


def test_every_listed_page_file_exists():
    pages = _pages(ROOT / "app.py")
    assert len(pages) >= 7
    missing = [p for p, _, _ in pages if not (ROOT / p).is_file()]
    assert not missing, f"app.py lists page files that do not exist: {missing}"


def test_a_missing_page_is_an_error_on_screen(tmp_path):
    """A copy of the app without one page file shows an error naming it."""
    for name in ("app.py", "app_ui", "aerostat_core"):
        src = ROOT / name
        (shutil.copytree if src.is_dir() else shutil.copy)(src, tmp_path / name)
    (tmp_path / "pages").mkdir()
    pages = _pages(ROOT / "app.py")
    for path, _, _ in pages[:-1]:  # the last page is left out
        shutil.copy(ROOT / path, tmp_path / path)
    at = AppTest.from_file(str(tmp_path / "app.py"), default_timeout=60)
    at.run()
    errors = [e.value for e in at.error]
    assert any(pages[-1][0] in e for e in errors), errors


def test_every_page_first_makes_sure_it_runs_inside_the_app():
    """Each page calls app_ui.shell.run_inside_the_app before it draws anything, so a page
    reached by its own address on a fresh server runs inside app.py (the browser test of a
    restart, tests/e2e/test_persistence_e2e.py, shows what it fixes); every page of the folder
    is listed in PAGES, so none can be reached by the folder's own navigation alone."""
    listed = {p for p, _, _ in _pages(ROOT / "app.py")}
    assert listed == {f"pages/{f.name}" for f in (ROOT / "pages").glob("*.py")}
    for path in listed:
        body = ast.parse((ROOT / path).read_text()).body
        # the first statement after the docstring and the imports, whatever its kind
        first = next(n for n in body[1:] if not isinstance(n, (ast.Import, ast.ImportFrom)))
        assert (isinstance(first, ast.Expr) and isinstance(first.value, ast.Call)
                and isinstance(first.value.func, ast.Name)
                and first.value.func.id == "run_inside_the_app"), (path, ast.unparse(first))


def test_the_guard_runs_the_app_only_outside_it(monkeypatch):
    """Outside app.py the guard ends Streamlit's folder mode, runs app.py in the same run (so
    a pressed button is not lost to a rerun) and ends the bare page with StopException itself
    (st.stop would also drop a queued fragment rerun); under app.py (one of its frames on the
    stack) it does nothing, whatever the process-wide flag says; outside a script run, or when
    the page file is itself the entry script, neither."""
    from streamlit.runtime.pages_manager import PagesManager
    from streamlit.runtime.scriptrunner_utils.exceptions import StopException

    from app_ui import shell

    assert shell.APP.name == "app.py" and (shell.APP.parent / "pages").is_dir()
    ran = []
    monkeypatch.setattr(shell, "_run_app", lambda ctx: ran.append(
        (ctx, PagesManager.uses_pages_directory)))
    monkeypatch.setattr(PagesManager, "uses_pages_directory", True)
    monkeypatch.setattr(shell, "get_script_run_ctx", lambda: None)
    shell.run_inside_the_app()  # no script run: nothing to run inside
    assert ran == [] and PagesManager.uses_pages_directory is True

    from types import SimpleNamespace

    page_as_entry = SimpleNamespace(pages_manager=SimpleNamespace(
        main_script_path=str(shell.APP.parent / "pages" / "6_Method.py")))
    monkeypatch.setattr(shell, "get_script_run_ctx", lambda: page_as_entry)
    shell.run_inside_the_app()  # a page file run as the entry script: no app around it
    assert ran == [] and PagesManager.uses_pages_directory is True

    ctx = SimpleNamespace(pages_manager=SimpleNamespace(main_script_path=str(shell.APP)))
    monkeypatch.setattr(shell, "get_script_run_ctx", lambda: ctx)
    assert not shell.inside_the_app()
    with pytest.raises(StopException):
        shell.run_inside_the_app()
    assert ran == [(ctx, False)]

    # the same call from code compiled as app.py: nothing happens, even with the flag set
    monkeypatch.setattr(PagesManager, "uses_pages_directory", True)
    under_app = {}
    exec(compile("inside = shell.inside_the_app(); shell.run_inside_the_app()",
                 str(shell.APP), "exec"), {"shell": shell}, under_app)
    assert under_app["inside"] and len(ran) == 1
    assert PagesManager.uses_pages_directory is True
