"""Every page app.py lists exists, and a missing one is reported, never dropped silently."""

from __future__ import annotations

import ast
import shutil
from pathlib import Path

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
