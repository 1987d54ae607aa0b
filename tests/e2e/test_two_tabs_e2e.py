"""Two browser tabs on one workspace, on SQLite and on PostgreSQL (issue 20): import, save,
rename, delete and replace in a stale tab never lose or overwrite what the other tab saved;
a bare address offers the browser's recent workspace back; hostile case names fetch nothing;
a database that never answers gives a message while the app keeps working.

The database is read directly (the same store code) to check what was really saved.
"""

from __future__ import annotations

import json
import os
import re
import socket
import threading
from urllib.parse import parse_qs, urlparse

import pytest
from playwright.sync_api import Browser, Page, expect

from aerostat_core.model.io import cases_to_json
from aerostat_core.output.report import thesis_gui_cases
from app_ui import store
from tests.e2e.conftest import start_streamlit, stop_streamlit
from tests.e2e.helpers import ARTIFACTS_DIR, assert_no_exception, goto_page, wait_for_rerun

pytestmark = pytest.mark.e2e

GUI = list(thesis_gui_cases())
#: A fresh server's first run imports plotly, scipy..., and a run that designs new cases
#: computes them: generous on a loaded machine [ms].
FIRST_RUN_MS = 120_000
PG_URL = os.environ.get("AEROSTAT_TEST_DATABASE_URL", "").strip()


def _require_pg() -> None:
    if not PG_URL:
        if os.environ.get("AEROSTAT_REQUIRE_POSTGRES", "").strip() in {"1", "true", "yes"}:
            pytest.fail("AEROSTAT_REQUIRE_POSTGRES=1 but AEROSTAT_TEST_DATABASE_URL is not set")
        pytest.skip("no PostgreSQL server (set AEROSTAT_TEST_DATABASE_URL; .ci/run does)")


@pytest.fixture(params=["sqlite", "postgresql"])
def server(request, tmp_path):
    """A live app on its own database; yields (url, Store on the same database)."""
    if request.param == "postgresql":
        _require_pg()
        env, url = {"AEROSTAT_DATABASE_URL": PG_URL}, PG_URL
    else:
        data = tmp_path / "data"
        env, url = {"AEROSTAT_DATA_DIR": str(data)}, f"sqlite:///{data / 'aerostat.sqlite3'}"
    srv = start_streamlit(ARTIFACTS_DIR / f"streamlit-two-tabs-{request.param}.log", env)
    db = None
    try:
        db = store.Store(url)
        yield srv.url, db
    finally:
        if db is not None:
            db.dispose()
        stop_streamlit(srv)


def _token(page: Page) -> str:
    expect(page).to_have_url(re.compile(r"[?&]ws=[A-Za-z0-9_-]{32}"))
    return parse_qs(urlparse(page.url).query)["ws"][0]


def _open(browser: Browser, url: str) -> Page:
    page = browser.new_context(viewport={"width": 1400, "height": 1000}).new_page()
    page.goto(url)
    wait_for_rerun(page, timeout=FIRST_RUN_MS)
    assert_no_exception(page, url)
    return page


def _save(page: Page, name: str) -> None:
    page.get_by_role("textbox", name="Save the current design as a case").fill(name)
    page.get_by_role("button", name="Save case").click()
    wait_for_rerun(page, timeout=FIRST_RUN_MS)


def _picker(page: Page):
    return page.get_by_test_id("stMultiSelect").first


def test_two_tabs_on_one_workspace_lose_nothing(browser: Browser, server):
    url, db = server
    a = _open(browser, f"{url}/Compare")  # tab A on /Compare?ws=W
    token = _token(a)
    b = _open(browser, f"{url}/?ws={token}")  # tab B on /?ws=W
    try:
        # save in B, import in the stale A: B's case survives
        _save(b, "B-case")
        expect(b.get_by_text("Saved case “B-case”")).to_be_visible()
        a.get_by_role("button", name="Load the thesis' GUI test cases").click()
        wait_for_rerun(a, timeout=FIRST_RUN_MS)
        assert list(db.load(token)[1]) == ["B-case", *GUI]
        expect(_picker(a)).to_contain_text("B-case")

        # A saves under the name B took: it is asked, and "Keep both" keeps both
        goto_page(a, "Design", timeout=FIRST_RUN_MS)
        _save(a, "B-case")
        expect(a.get_by_text("exists already", exact=False)).to_be_visible()
        a.get_by_role("button", name="Keep both").click()
        wait_for_rerun(a, timeout=FIRST_RUN_MS)
        expect(a.get_by_text("Saved case “B-case (2)”")).to_be_visible()
        assert list(db.load(token)[1]) == ["B-case", *GUI, "B-case (2)"]

        # B saves another case; A (stale) renames a case to that name: "exists already"
        _save(b, "B-two")
        goto_page(a, "Compare", timeout=FIRST_RUN_MS)
        goto_page(b, "Compare", timeout=FIRST_RUN_MS)
        db.put_case(token, "B-three", db.load(token)[1]["B-case"])  # a third tab, meanwhile
        a.get_by_role("tab", name="Manage cases").click()
        wait_for_rerun(a, timeout=FIRST_RUN_MS)
        a.get_by_role("textbox", name="New name").fill("B-three")
        a.get_by_role("button", name="Rename").click()
        wait_for_rerun(a, timeout=FIRST_RUN_MS)
        expect(a.get_by_text("exists already", exact=False)).to_be_visible()
        expect(a.get_by_text("unavailable", exact=False)).to_have_count(0)

        # A deletes one case: only that one goes
        a.get_by_role("tab", name="Manage cases").click()
        wait_for_rerun(a, timeout=FIRST_RUN_MS)
        deleter = a.get_by_test_id("stMultiSelect").filter(has_text="Cases to delete")
        deleter.click()
        a.get_by_role("option", name=GUI[1]).click()
        a.keyboard.press("Escape")
        a.get_by_role("button", name="Delete").click()
        wait_for_rerun(a, timeout=FIRST_RUN_MS)
        saved = list(db.load(token)[1])
        assert GUI[1] not in saved and {"B-case", "B-two", "B-three"} <= set(saved)

        # A replaces by a file (asks first); B adds a case meanwhile, which stays
        a.get_by_text("Cases file: export / import").click()
        a.get_by_text("replaces the saved cases (asks first)").click()
        wait_for_rerun(a, timeout=FIRST_RUN_MS)
        upload = {"From file": thesis_gui_cases()[GUI[0]]}
        a.get_by_test_id("stFileUploaderDropzoneInput").first.set_input_files(
            files=[
                {
                    "name": "replace.json",
                    "mimeType": "application/json",
                    "buffer": cases_to_json(upload).encode(),
                }
            ]
        )
        wait_for_rerun(a, timeout=FIRST_RUN_MS)
        expect(a.get_by_text("Replace the", exact=False)).to_be_visible()
        goto_page(b, "Design", timeout=FIRST_RUN_MS)
        _save(b, "B-late")
        a.get_by_role("button", name="Replace", exact=True).click()
        wait_for_rerun(a, timeout=FIRST_RUN_MS)
        assert list(db.load(token)[1]) == ["B-late", "From file"]
        expect(_picker(a)).to_contain_text("B-late")
        assert_no_exception(a, "tab A")
        assert_no_exception(b, "tab B")
    finally:
        a.context.close()
        b.context.close()


def test_a_bare_address_offers_the_last_workspace(browser: Browser, tmp_path):
    env = {"AEROSTAT_DATA_DIR": str(tmp_path / "data")}
    srv = start_streamlit(ARTIFACTS_DIR / "streamlit-recent.log", env)
    ctx = browser.new_context(viewport={"width": 1400, "height": 1000})
    try:
        page = ctx.new_page()
        page.goto(srv.url + "/")
        wait_for_rerun(page, timeout=FIRST_RUN_MS)
        token = _token(page)
        _save(page, "Yesterday's work")
        page.goto(srv.url + "/")  # the bare address, same browser
        wait_for_rerun(page, timeout=FIRST_RUN_MS)
        assert _token(page) != token
        offer = page.get_by_role("button", name=re.compile("Last used: 1 case"))
        expect(offer).to_be_visible()
        offer.click()
        wait_for_rerun(page, timeout=FIRST_RUN_MS)
        assert _token(page) == token
        expect(_picker_or_text(page, "Yesterday's work")).to_be_visible()
    finally:
        ctx.close()
        stop_streamlit(srv)


def _picker_or_text(page: Page, text: str):
    goto_page(page, "Compare", timeout=FIRST_RUN_MS)
    return _picker(page).get_by_text(text)


HOSTILE = (
    "![t](http://evil.invalid/x.png)",
    "[click](http://evil.invalid/link)",
    "<img src=http://evil.invalid/i.png>",
    "<script>window.__evil=1</script>",
)


def test_hostile_names_fetch_nothing_in_the_browser(browser: Browser, tmp_path):
    data = tmp_path / "data"
    db = store.Store(f"sqlite:///{data / 'aerostat.sqlite3'}")
    token = store.new_token()
    one = thesis_gui_cases()[GUI[0]]
    db.add_cases(token, {n: one for n in HOSTILE})
    db.dispose()
    srv = start_streamlit(ARTIFACTS_DIR / "streamlit-hostile.log", {"AEROSTAT_DATA_DIR": str(data)})
    ctx = browser.new_context(viewport={"width": 1400, "height": 1000})
    fetched: list[str] = []
    ctx.on("request", lambda r: fetched.append(r.url) if "evil" in r.url else None)
    try:
        page = ctx.new_page()
        page.goto(f"{srv.url}/Compare?ws={token}")
        wait_for_rerun(page, timeout=FIRST_RUN_MS)
        expect(_picker(page)).to_contain_text(HOSTILE[0])
        for tab in ("Side by side", "Performance", "Tether profiles", "Manage cases"):
            page.get_by_role("tab", name=tab).click()
            wait_for_rerun(page, timeout=FIRST_RUN_MS)
            assert page.locator("img[src*='evil'], a[href*='evil']").count() == 0, tab
            assert page.evaluate("window.__evil") is None, tab
        expect(page.get_by_text(HOSTILE[0]).first).to_be_attached()  # shown as typed
        for label in ("Design", "Sensitivity", "Optimise", "Dynamics", "Method", "Shapes"):
            goto_page(page, label, timeout=FIRST_RUN_MS)
            assert page.locator("img[src*='evil'], a[href*='evil']").count() == 0, label
        assert fetched == []
        assert page.evaluate("window.__evil") is None
    finally:
        ctx.close()
        stop_streamlit(srv)


@pytest.fixture
def silent_port():
    """A loopback TCP listener that accepts connections and never answers."""
    srv = socket.socket()
    srv.bind(("127.0.0.1", 0))
    srv.listen(64)
    held: list[socket.socket] = []
    stop = threading.Event()

    def accept() -> None:
        srv.settimeout(0.2)
        while not stop.is_set():
            try:
                held.append(srv.accept()[0])
            except OSError:
                continue

    t = threading.Thread(target=accept, daemon=True)
    t.start()
    yield srv.getsockname()[1]
    stop.set()
    t.join()
    for c in held:
        c.close()
    srv.close()


def test_a_hung_database_gives_a_message_and_the_app_works(browser: Browser, silent_port):
    env = {
        "AEROSTAT_DATABASE_URL": f"postgresql+psycopg://u:p@127.0.0.1:{silent_port}/db",
        "AEROSTAT_DB_TIMEOUT_S": "2",
    }
    srv = start_streamlit(ARTIFACTS_DIR / "streamlit-hung-db.log", env)
    ctx = browser.new_context(viewport={"width": 1400, "height": 1000})
    try:
        warm = ctx.new_page()  # the first session pays the imports
        warm.goto(srv.url + "/")
        wait_for_rerun(warm, timeout=FIRST_RUN_MS)
        page = ctx.new_page()
        page.goto(srv.url + "/")
        # within 10 s: the message, and the design computed without the database
        expect(page.get_by_text("no answer within 2 s", exact=False).first).to_be_visible(
            timeout=10_000
        )
        wait_for_rerun(page, timeout=FIRST_RUN_MS)
        expect(page.get_by_test_id("headline").first).to_be_visible()  # the design, computed
        _save(page, "Kept in the session")
        expect(page.get_by_text("in this session only", exact=False).first).to_be_visible()
        with page.expect_download() as info:
            page.get_by_role("button", name="Download the unsaved cases (JSON)").click()
        assert list(json.loads(info.value.path().read_text())["cases"]) == ["Kept in the session"]
        assert_no_exception(page, "hung database")
    finally:
        ctx.close()
        stop_streamlit(srv)
