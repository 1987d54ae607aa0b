"""Helpers for the real-browser tests (Playwright driving Debian chromium).

Import them by full name: ``from tests.e2e.helpers import goto_page, screenshot, wait_for_rerun``.
Rules of thumb (docs/architecture.md §6): wait for the rerun, then use auto-retrying ``expect(...)``;
never sleep; switch pages by clicking the sidebar (``page.goto`` starts a new session).
"""

from __future__ import annotations

import re
from pathlib import Path

from playwright.sync_api import ConsoleMessage, Error, Locator, Page, expect

REPO_ROOT = Path(__file__).resolve().parents[2]
ARTIFACTS_DIR = REPO_ROOT / "artifacts"
SCREENSHOT_DIR = ARTIFACTS_DIR / "screenshots"

#: Default time a rerun may take [ms]; optimisation/simulation pages can pass a longer one.
RERUN_TIMEOUT_MS = 30_000

_APP = "[data-testid='stApp']"
CONNECTED = f"{_APP}[data-test-connection-state='CONNECTED']"
NOT_RUNNING = f"{_APP}[data-test-script-state='notRunning']"
SKELETON = "[data-testid='stSkeleton']"


def wait_for_rerun(page: Page, timeout: float = RERUN_TIMEOUT_MS) -> None:
    """Wait until the script run triggered by the last action has finished rendering.

    The short pause first lets the frontend register the interaction and flip the script state to
    ``running``; without it the ``notRunning`` check could pass on the state *before* the rerun.
    """
    page.wait_for_timeout(200)
    expect(page.locator(CONNECTED)).to_be_attached(timeout=timeout)
    expect(page.locator(NOT_RUNNING)).to_be_attached(timeout=timeout)
    expect(page.locator(SKELETON)).to_have_count(0, timeout=timeout)


def sidebar_nav_link(page: Page, label: str) -> Locator:
    """The sidebar navigation link whose accessible name is exactly ``label``.

    A page icon does not get in the way: Streamlit marks the Material icon ``aria-hidden``.
    """
    nav = page.get_by_test_id("stSidebarNav")
    return nav.get_by_role("link", name=label, exact=True)


def nav_link_label(link: Locator) -> str:
    """The visible label of a sidebar navigation link (without its icon's ligature text)."""
    label = link.get_by_test_id("stMarkdownContainer")
    text = label.first.inner_text() if label.count() else link.inner_text()
    return text.strip()


def assert_no_exception(page: Page, where: str = "") -> None:
    """Fail with the message(s) of any ``st.exception`` box shown on the page."""
    boxes = page.get_by_test_id("stException")
    if boxes.count():
        details = "\n---\n".join(text.strip() for text in boxes.all_inner_texts())
        place = f" on {where}" if where else ""
        raise AssertionError(f"Streamlit exception{place}:\n{details}")


def goto_page(page: Page, label: str, timeout: float = RERUN_TIMEOUT_MS) -> None:
    """Switch to another page of the app by clicking its sidebar link, then wait for the rerun.

    Keeps the same session (saved cases, persisted widget values), unlike ``page.goto``.
    """
    # the pointer leaves what it last pressed, as a user's does on the way to the sidebar: a
    # button's help tooltip stays open while the pointer rests on it and can cover the links
    page.mouse.move(0, 0)
    link = sidebar_nav_link(page, label)
    if not link.is_visible():
        # Streamlit folds long page lists behind a "View more" button.
        more = page.get_by_test_id("stSidebarNavViewButton")
        if more.is_visible() and "more" in (more.text_content() or "").lower():
            more.click()
    link.click(timeout=timeout)
    wait_for_rerun(page, timeout=timeout)


def screenshot(page: Page, name: str, *, full_page: bool = True) -> Path:
    """Save a PNG of the page to ``artifacts/screenshots/<name>.png`` and return its path."""
    SCREENSHOT_DIR.mkdir(parents=True, exist_ok=True)
    path = SCREENSHOT_DIR / f"{name}.png"
    page.screenshot(path=str(path), full_page=full_page)
    return path


# Offline, the Material Symbols / Google web-font requests fail; Chromium then logs
# "Failed to load resource" and font-face errors that say nothing about the app.
_IGNORED_CONSOLE = (
    re.compile(r"material[ -_]?(symbols|icons)", re.IGNORECASE),
    re.compile(r"fonts\.(googleapis|gstatic)\.com", re.IGNORECASE),
    re.compile(r"\.(woff2?|ttf|otf)(\?|$|\b)", re.IGNORECASE),
    re.compile(r"Failed to decode downloaded font", re.IGNORECASE),
    re.compile(r"OTS parsing error", re.IGNORECASE),
)


def is_ignored_console_error(text: str, url: str = "") -> bool:
    """True for console errors that come from icon/web-font requests failing offline.

    >>> is_ignored_console_error("Failed to load resource: net::ERR_NAME_NOT_RESOLVED",
    ...                          "https://fonts.gstatic.com/s/materialsymbolsrounded/v1/x.woff2")
    True
    >>> is_ignored_console_error("TypeError: x is undefined")
    False
    """
    haystack = f"{text} {url}"
    return any(pattern.search(haystack) for pattern in _IGNORED_CONSOLE)


def watch_console_errors(page: Page) -> list[str]:
    """Start collecting the page's console errors and uncaught exceptions.

    Returns a list that fills up as the page runs; icon/font failures (offline) are left out.
    Call it before ``page.goto`` to catch errors during the first render.
    """
    errors: list[str] = []

    def on_console(msg: ConsoleMessage) -> None:
        if msg.type != "error":
            return
        url = (msg.location or {}).get("url", "")
        if not is_ignored_console_error(msg.text, url):
            errors.append(f"console: {msg.text} ({url})" if url else f"console: {msg.text}")

    def on_page_error(exc: Error) -> None:
        errors.append(f"pageerror: {exc}")

    page.on("console", on_console)
    page.on("pageerror", on_page_error)
    return errors
