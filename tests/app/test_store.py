"""The workspace store: the same tests against SQLite (a temporary file) and a real PostgreSQL
server (``AEROSTAT_TEST_DATABASE_URL``, started on loopback by ``.ci/run``).

Without that variable the PostgreSQL half is skipped locally, but fails in CI
(``AEROSTAT_REQUIRE_POSTGRES=1``): it must run there.
"""

from __future__ import annotations

import os
import sqlite3
import threading

import pytest
import sqlalchemy as sa

from aerostat_core import thesis_baseline
from aerostat_core.model.io import inputs_to_dict
from aerostat_core.output.report import thesis_gui_cases
from app_ui import state, store

PG_URL = os.environ.get("AEROSTAT_TEST_DATABASE_URL", "").strip()


def _require_pg() -> None:
    if not PG_URL:
        if os.environ.get("AEROSTAT_REQUIRE_POSTGRES", "").strip() in {"1", "true", "yes"}:
            pytest.fail("AEROSTAT_REQUIRE_POSTGRES=1 but AEROSTAT_TEST_DATABASE_URL is not set")
        pytest.skip("no PostgreSQL server (set AEROSTAT_TEST_DATABASE_URL; .ci/run does)")


@pytest.fixture(params=["sqlite", "postgresql"])
def db(request, tmp_path) -> store.Store:
    if request.param == "sqlite":
        s = store.Store(f"sqlite:///{tmp_path / 'data' / 'aerostat.sqlite3'}")
    else:
        _require_pg()
        s = store.Store(PG_URL)
    yield s
    s.dispose()


def _inputs(payload: float = 10.0) -> dict:
    from dataclasses import replace

    req, cfg = thesis_baseline()
    return inputs_to_dict(replace(req, payload_mass=payload), cfg)


def test_tokens_are_unguessable_and_checked():
    tokens = {store.new_token() for _ in range(200)}
    assert len(tokens) == 200
    assert all(store.valid_token(t) for t in tokens)
    for bad in ["", "abc", "x" * 33, "../../etc/passwd" + "x" * 16, None, 5, "ä" * 32]:
        assert not store.valid_token(bad)


def test_no_listing_of_workspaces():
    public = {n for n in dir(store.Store) if not n.startswith("_")}
    assert not any("list" in n or "all" in n for n in public), public


def test_cases_round_trip_in_order(db):
    ws = store.new_token()
    assert db.load(ws) == (None, {})
    db.put_case(ws, "b", _inputs(20))
    db.put_case(ws, "a", _inputs(10))
    db.put_case(ws, "c ✓ 🎈", _inputs(30))
    current, saved = db.load(ws)
    assert current is None
    assert list(saved) == ["b", "a", "c ✓ 🎈"]
    assert saved["a"] == _inputs(10)
    db.put_case(ws, "b", _inputs(25))  # replace in place keeps the order
    assert list(db.load(ws)[1]) == ["b", "a", "c ✓ 🎈"]
    assert db.load(ws)[1]["b"]["requirement"]["payload_mass"] == 25.0
    db.rename_case(ws, "b", "bee")
    assert list(db.load(ws)[1]) == ["bee", "a", "c ✓ 🎈"]
    db.delete_case(ws, "a")
    db.delete_case(ws, "a")
    assert list(db.load(ws)[1]) == ["bee", "c ✓ 🎈"]
    db.set_current(ws, _inputs(42))
    assert db.load(ws)[0] == _inputs(42)


def test_workspaces_are_isolated(db):
    one, two = store.new_token(), store.new_token()
    db.put_case(one, "mine", _inputs())
    db.set_current(one, _inputs(50))
    assert db.load(two) == (None, {})
    db.replace_cases(two, {"x": _inputs(), "y": _inputs(5)})
    assert list(db.load(one)[1]) == ["mine"]
    assert list(db.load(two)[1]) == ["x", "y"]


def test_replace_is_one_transaction(db):
    ws = store.new_token()
    db.replace_cases(ws, {"keep": _inputs()})
    bad = {"ok": _inputs(), "dup": _inputs()}
    # A failure in the middle (a name longer than the column on PostgreSQL, a non-JSON value
    # everywhere) must leave the old cases in place.
    bad["broken"] = {"x": object()}
    with pytest.raises(TypeError):
        db.replace_cases(ws, bad)
    assert list(db.load(ws)[1]) == ["keep"]


def test_a_malformed_token_is_never_queried(db):
    with pytest.raises(ValueError):
        db.load("' OR 1=1 --")
    with pytest.raises(ValueError):
        db.put_case("short", "x", _inputs())


def test_concurrent_writers_lose_nothing(db):
    ws = store.new_token()
    errors: list[BaseException] = []

    def writer(k: int) -> None:
        try:
            for i in range(10):
                db.put_case(ws, f"w{k}-{i}", _inputs(1 + i))
        except BaseException as exc:  # noqa: BLE001 - reported below
            errors.append(exc)

    threads = [threading.Thread(target=writer, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    assert len(db.load(ws)[1]) == 40


def test_sqlite_uses_wal(tmp_path):
    path = tmp_path / "w.sqlite3"
    s = store.Store(f"sqlite:///{path}")
    s.put_case(store.new_token(), "x", _inputs())
    with s.engine.connect() as conn:
        assert conn.exec_driver_sql("PRAGMA journal_mode").scalar() == "wal"
    s.dispose()


def test_corrupt_file_gives_a_message_and_is_not_touched(tmp_path):
    path = tmp_path / "aerostat.sqlite3"
    junk = b"this is not a database\x00" * 200
    path.write_bytes(junk)
    with pytest.raises(store.StoreUnavailable, match="cannot be opened.*Nothing was deleted"):
        store.Store(f"sqlite:///{path}")
    assert path.read_bytes() == junk


def test_locked_database_gives_a_message_and_keeps_the_data(tmp_path, monkeypatch):
    monkeypatch.setattr(store, "SQLITE_BUSY_TIMEOUT_S", 0.2)
    path = tmp_path / "aerostat.sqlite3"
    s = store.Store(f"sqlite:///{path}")
    ws = store.new_token()
    s.put_case(ws, "safe", _inputs())
    locker = sqlite3.connect(path, timeout=0.1)
    locker.execute("BEGIN EXCLUSIVE")
    try:
        with pytest.raises(store.StoreUnavailable, match="Could not save the case"):
            s.put_case(ws, "new", _inputs())
    finally:
        locker.rollback()
        locker.close()
    assert list(s.load(ws)[1]) == ["safe"]
    s.dispose()


def test_default_location_is_configurable(monkeypatch, tmp_path):
    monkeypatch.delenv("AEROSTAT_DATABASE_URL", raising=False)
    monkeypatch.setenv("AEROSTAT_DATA_DIR", str(tmp_path / "d"))
    assert store.default_url() == f"sqlite:///{tmp_path / 'd' / 'aerostat.sqlite3'}"
    monkeypatch.delenv("AEROSTAT_DATA_DIR")
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "xdg"))
    assert store.default_data_dir() == tmp_path / "xdg" / "aerostat"
    monkeypatch.setenv("AEROSTAT_DATABASE_URL", "postgresql+psycopg://u:p@h/db")
    assert store.default_url() == "postgresql+psycopg://u:p@h/db"


# --- the session state writes through to the store -------------------------------------------


@pytest.fixture
def bound(db, monkeypatch):
    """A session dict bound to a fresh workspace of ``db``."""
    monkeypatch.setattr(store, "get_store", lambda url=None: db)
    s: dict = {}
    qp: dict = {}
    token = state.attach_workspace(s, qp)
    assert qp["ws"] == token and store.valid_token(token)
    return s, qp, db


def test_state_changes_survive_a_new_session(bound):
    s, qp, db = bound
    req, cfg = thesis_baseline()
    state.save_case("one", req, cfg, s)
    state.save_case("one", req, cfg, s)  # suffixed, not replaced
    state.add_cases(thesis_gui_cases(), s)
    state.rename_case("one (2)", "two", s)
    state.delete_case(next(iter(thesis_gui_cases())), s)
    from dataclasses import replace

    state.set_current_inputs(replace(req, payload_mass=33.0), cfg, s)
    fresh: dict = {}  # a reload, a new tab or a server restart: only the URL is left
    state.attach_workspace(fresh, dict(qp))
    assert list(fresh["cases"]) == list(s["cases"])
    assert list(fresh["cases"])[:2] == ["one", "two"]
    assert fresh["design_inputs"]["requirement"]["payload_mass"] == 33.0
    other: dict = {}
    state.attach_workspace(other, {})  # no token: a new, empty workspace
    assert other["cases"] == {} and other["_workspace"] != s["_workspace"]


def test_unavailable_store_keeps_the_session_working(monkeypatch):
    def broken(url=None):
        raise store.StoreUnavailable("The saved-cases database cannot be opened (disk I/O).")

    monkeypatch.setattr(store, "get_store", broken)
    s: dict = {}
    state.attach_workspace(s, {"ws": store.new_token()})
    assert "cannot be opened" in s[state.STORE_ERR_KEY]
    state.save_case("kept in memory", *thesis_baseline(), s)
    assert list(s["cases"]) == ["kept in memory"]


def test_postgres_url_is_really_postgres():
    _require_pg()
    engine = sa.create_engine(PG_URL)
    with engine.connect() as conn:
        assert "PostgreSQL" in conn.exec_driver_sql("select version()").scalar()
    engine.dispose()
