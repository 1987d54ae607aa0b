"""Two tabs (sessions) on one workspace, database outages and a database that never answers
(issue 20): nothing another tab saved is lost or overwritten, a case saved during an outage is
written when the database returns, and a hung database gives a message instead of a freeze.

The same tests run on SQLite and on a real PostgreSQL server (see tests/app/test_store.py).
"""

from __future__ import annotations

import os
import signal
import socket
import threading
from dataclasses import replace

import pytest
import sqlalchemy as sa

from aerostat_core import thesis_baseline
from aerostat_core.model.io import inputs_to_dict
from aerostat_core.output.report import thesis_gui_cases
from app_ui import state, store
from tests.app.test_store import PG_URL, _require_pg


@pytest.fixture(params=["sqlite", "postgresql"])
def db(request, tmp_path):
    if request.param == "sqlite":
        s = store.Store(f"sqlite:///{tmp_path / 'data' / 'aerostat.sqlite3'}")
    else:
        _require_pg()
        s = store.Store(PG_URL)
    yield s
    s.dispose()


@pytest.fixture
def tabs(db, monkeypatch):
    """Two sessions (tab A and tab B) bound to one new workspace, each loaded once."""
    monkeypatch.setattr(store, "get_store", lambda url=None: db)
    a: dict = {}
    token = state.attach_workspace(a, {})
    b: dict = {}
    state.attach_workspace(b, {"ws": token})
    return a, b, db, token


def _design(payload: float):
    req, cfg = thesis_baseline()
    return replace(req, payload_mass=payload), cfg


def _saved(db, token) -> dict:
    return db.load(token)[1]


def _payload(inputs: dict) -> float:
    return inputs["requirement"]["payload_mass"]


def test_import_in_a_stale_tab_keeps_the_other_tabs_case(tabs):
    a, b, db, token = tabs
    state.save_case("B-case", *_design(20), b)
    names = state.add_cases(thesis_gui_cases(), a)  # A has not seen "B-case"
    assert list(_saved(db, token)) == ["B-case", *names]
    assert list(a["cases"]) == ["B-case", *names]  # and A now shows it


def test_a_stale_tab_never_overwrites_a_same_named_case(tabs):
    a, b, db, token = tabs
    state.save_case("Same", *_design(77), b)
    with pytest.raises(store.CaseConflict, match="exists already") as exc:
        state.save_case("Same", *_design(10), a, on_taken="ask")
    assert exc.value.kind == "taken"
    assert _payload(_saved(db, token)["Same"]) == 77.0
    # "keep both" (the default for callers that do not ask)
    assert state.save_case("Same", *_design(10), a) == "Same (2)"
    saved = _saved(db, token)
    assert _payload(saved["Same"]) == 77.0 and _payload(saved["Same (2)"]) == 10.0
    # "replace", with the version the user was told about
    state.save_case("Same", *_design(11), a, on_taken="replace", version=exc.value.version)
    assert _payload(_saved(db, token)["Same"]) == 11.0


def test_an_update_of_a_stale_version_is_refused(tabs):
    a, b, db, token = tabs
    state.save_case("X", *_design(10), a)
    state.attach_workspace(b, {"ws": token})  # B sees X
    state.save_case("X", *_design(50), b, overwrite=True)
    with pytest.raises(store.CaseConflict, match="changed in another tab") as exc:
        state.save_case("X", *_design(12), a, overwrite=True)
    assert exc.value.kind == "changed"
    assert _payload(_saved(db, token)["X"]) == 50.0
    # a rename or delete from the stale view is refused too; after a reload both work
    with pytest.raises(store.CaseConflict):
        state.rename_case("X", "Y", a)
    with pytest.raises(store.CaseConflict):
        state.delete_case("X", a)
    assert list(_saved(db, token)) == ["X"]
    state.attach_workspace(a, {"ws": token})
    assert state.rename_case("X", "Y", a) == "Y"
    state.delete_case("Y", a)
    assert _saved(db, token) == {}


def test_rename_to_a_name_another_tab_took_says_so(tabs):
    a, b, db, token = tabs
    state.save_case("mine", *_design(10), a)
    state.save_case("theirs", *_design(20), b)
    with pytest.raises(ValueError, match="exists already") as exc:
        state.rename_case("mine", "theirs", a)  # A does not know "theirs" yet
    assert "unavailable" not in str(exc.value)
    assert sorted(_saved(db, token)) == ["mine", "theirs"]


def test_delete_in_a_stale_tab_keeps_the_other_tabs_cases(tabs):
    a, b, db, token = tabs
    state.save_case("one", *_design(10), a)
    state.save_case("two", *_design(20), b)
    state.delete_case("one", a)
    assert list(_saved(db, token)) == ["two"]
    assert list(a["cases"]) == ["two"]


def test_replace_removes_only_what_the_user_saw(tabs):
    a, b, db, token = tabs
    state.save_case("seen 1", *_design(10), a)
    state.save_case("seen 2", *_design(11), a)
    seen = state.case_versions(a)  # what A's page shows when the user confirms
    state.save_case("B-case", *_design(20), b)  # meanwhile in tab B
    used = state.add_cases(thesis_gui_cases(), a, mode="replace", seen=seen)
    assert list(_saved(db, token)) == ["B-case", *used]
    state.clear_cases(a)  # "delete all" is a replace too: B's new case survives it
    state.save_case("late", *_design(30), b)
    assert "late" in _saved(db, token)


def test_positions_are_unique_and_ordered_under_concurrent_writers(db):
    token = store.new_token()
    errors: list[BaseException] = []

    def writer(k: int) -> None:
        try:
            for i in range(8):
                db.put_case(token, f"w{k}-{i}", inputs_to_dict(*_design(1 + i)))
            db.add_cases(
                token, {f"add{k}-{i}": inputs_to_dict(*_design(1 + k + i)) for i in range(3)}
            )
        except BaseException as exc:  # noqa: BLE001 - reported below
            errors.append(exc)

    threads = [threading.Thread(target=writer, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    with db.engine.connect() as conn:
        rows = conn.execute(
            sa.select(store.cases.c.name, store.cases.c.position).where(
                store.cases.c.workspace == token
            )
        ).all()
    positions = [p for _, p in rows]
    assert len(rows) == 44 and len(set(positions)) == 44
    # each writer's cases keep the order it wrote them in
    order = list(db.load(token)[1])
    for k in range(4):
        mine = [n for n in order if n.startswith(f"w{k}-")]
        assert mine == [f"w{k}-{i}" for i in range(8)]


def test_an_old_database_is_migrated_without_losing_order(tmp_path):
    path = tmp_path / "old.sqlite3"
    engine = sa.create_engine(f"sqlite:///{path}")
    token = store.new_token()
    with engine.begin() as conn:  # the schema before versions, with a duplicated position
        conn.exec_driver_sql(
            "CREATE TABLE workspaces (token VARCHAR(64) PRIMARY KEY, created FLOAT NOT NULL, "
            "current_inputs TEXT)"
        )
        conn.exec_driver_sql(
            "CREATE TABLE cases (workspace VARCHAR(64) NOT NULL REFERENCES workspaces(token), "
            "name VARCHAR(400) NOT NULL, position INTEGER NOT NULL, inputs TEXT NOT NULL, "
            "PRIMARY KEY (workspace, name))"
        )
        conn.exec_driver_sql(f"INSERT INTO workspaces VALUES ('{token}', 0, NULL)")
        for name, pos in (("b", 1), ("a", 2), ("c", 2)):
            conn.exec_driver_sql(f"INSERT INTO cases VALUES ('{token}', '{name}', {pos}, '{{}}')")
    engine.dispose()
    db = store.Store(f"sqlite:///{path}")
    assert list(db.load(token)[1]) == ["b", "a", "c"]
    db.put_case(token, "d", inputs_to_dict(*_design(10)))
    assert list(db.load(token)[1]) == ["b", "a", "c", "d"]
    db.dispose()


# --- outages ----------------------------------------------------------------------------------


class _Switch:
    """get_store that fails while ``down`` (as an unreachable database does)."""

    def __init__(self, db) -> None:
        self.db, self.down = db, False

    def __call__(self, url=None):
        if self.down:
            raise store.StoreUnavailable("The saved-cases database cannot be opened (test).")
        return self.db


def test_a_case_saved_during_an_outage_is_written_when_the_database_returns(db, monkeypatch):
    switch = _Switch(db)
    monkeypatch.setattr(store, "get_store", switch)
    a: dict = {}
    token = state.attach_workspace(a, {})
    state.save_case("before", *_design(10), a)
    switch.down = True
    state.attach_workspace(a, {"ws": token})  # a rerun during the outage keeps everything
    assert "cannot be opened" in a[state.STORE_ERR_KEY]
    assert state.save_case("during", *_design(20), a) == "during"
    state.set_current_inputs(*_design(33), a)
    assert list(state.unsaved_cases(a)) == ["during"]
    assert list(a["cases"]) == ["before", "during"]
    state.attach_workspace(a, {"ws": token})
    assert list(a["cases"]) == ["before", "during"]  # still shown, still marked
    # meanwhile another tab (on a working replica) saved a case of the same name
    db.put_case(token, "during", inputs_to_dict(*_design(99)))
    switch.down = False
    state.attach_workspace(a, {"ws": token})  # the first run after the outage
    saved = _saved(db, token)
    assert _payload(saved["during"]) == 99.0 and _payload(saved["during (2)"]) == 20.0
    assert list(a["cases"]) == ["before", "during", "during (2)"]
    assert state.unsaved_cases(a) == {} and state.STORE_ERR_KEY not in a
    assert "during (2)" in state.pop_store_note(a)
    assert db.load(token)[0]["requirement"]["payload_mass"] == 33.0


def test_stored_cases_are_not_renamed_or_deleted_during_an_outage(db, monkeypatch):
    switch = _Switch(db)
    monkeypatch.setattr(store, "get_store", switch)
    a: dict = {}
    token = state.attach_workspace(a, {})
    state.save_case("kept", *_design(10), a)
    switch.down = True
    with pytest.raises(ValueError, match="Nothing was deleted"):
        state.delete_case("kept", a)
    with pytest.raises(ValueError, match="Nothing was renamed"):
        state.rename_case("kept", "other", a)
    with pytest.raises(ValueError, match="Nothing was replaced"):
        state.add_cases(thesis_gui_cases(), a, mode="replace")
    assert list(a["cases"]) == ["kept"]
    switch.down = False
    assert list(_saved(db, token)) == ["kept"]


# --- a database that never answers -------------------------------------------------------------


@pytest.fixture
def silent_server():
    """A loopback TCP listener that accepts connections and never answers."""
    srv = socket.socket()
    srv.bind(("127.0.0.1", 0))
    srv.listen(16)
    accepted: list[socket.socket] = []
    stop = threading.Event()

    def accept() -> None:
        srv.settimeout(0.2)
        while not stop.is_set():
            try:
                accepted.append(srv.accept()[0])
            except OSError:
                continue

    t = threading.Thread(target=accept, daemon=True)
    t.start()
    yield srv.getsockname()[1]
    stop.set()
    t.join()
    for c in accepted:
        c.close()
    srv.close()


def test_a_hung_database_gives_a_message_and_others_carry_on(silent_server, tmp_path):
    hung_url = f"postgresql+psycopg://u:p@127.0.0.1:{silent_server}/db"
    other_url = f"sqlite:///{tmp_path / 'other.sqlite3'}"
    store._failures.pop(hung_url, None)
    outcome: dict = {}

    def session_on_the_hung_database() -> None:
        try:
            store.get_store(hung_url)
        except store.StoreUnavailable as exc:
            outcome["message"] = str(exc)

    t = threading.Thread(target=session_on_the_hung_database)
    t.start()
    # another session, meanwhile: the global lock is not held while connecting
    other = store.get_store(other_url)
    token = store.new_token()
    other.put_case(token, "carry on", inputs_to_dict(*_design(10)))
    assert list(other.load(token)[1]) == ["carry on"]
    assert t.is_alive()  # the hung session is still waiting for its connect timeout
    t.join(timeout=10)  # the bound: a message within 10 s
    assert not t.is_alive()
    assert "no answer within" in outcome["message"]
    # asked again at once: the same message without another wait
    with pytest.raises(store.StoreUnavailable, match="no answer within"):
        store.get_store(hung_url)
    store._failures.pop(hung_url, None)
    with store._lock:
        store._stores.pop(other_url, None)
    other.dispose()


def test_the_timeout_is_configurable(monkeypatch):
    monkeypatch.setenv("AEROSTAT_DB_TIMEOUT_S", "7.5")
    assert store.default_timeout() == 7.5
    for bad, expected in (("abc", store.DEFAULT_TIMEOUT_S), ("0", 0.5), ("1e9", 60.0)):
        monkeypatch.setenv("AEROSTAT_DB_TIMEOUT_S", bad)
        assert store.default_timeout() == expected


def test_a_server_that_stops_answering_mid_session_is_cut_off(monkeypatch):
    """PostgreSQL: the backend of the pooled connection is stopped (SIGSTOP): the next call is
    cut by the watchdog and says so; after SIGCONT the store works again."""
    _require_pg()
    monkeypatch.setattr(store, "RETRY_AFTER_S", 0.0)
    db = store.Store(PG_URL, timeout_s=1.0)
    token = store.new_token()
    db.put_case(token, "before", inputs_to_dict(*_design(10)))
    with db.engine.connect() as conn:
        pid = conn.exec_driver_sql("select pg_backend_pid()").scalar()
    try:
        os.kill(pid, signal.SIGSTOP)
    except PermissionError:
        db.dispose()
        pytest.skip("cannot signal the PostgreSQL backend (not root and not its owner)")
    try:
        with pytest.raises(store.StoreUnavailable, match="no answer within 1 s"):
            db.load(token)
    finally:
        os.kill(pid, signal.SIGCONT)
    assert list(db.load(token)[1]) == ["before"]
    db.dispose()


def test_a_lock_held_elsewhere_times_out_with_a_message(db, monkeypatch):
    """A writer blocked behind another transaction's lock gives up after the timeout."""
    monkeypatch.setattr(store, "RETRY_AFTER_S", 0.0)
    quick = store.Store(db.url, timeout_s=1.0)
    token = store.new_token()
    quick.put_case(token, "safe", inputs_to_dict(*_design(10)))
    with db.engine.connect() as blocker:
        tx = blocker.begin()
        if db.is_sqlite:
            pass  # BEGIN IMMEDIATE took the write lock
        else:
            blocker.exec_driver_sql("LOCK TABLE workspaces IN ACCESS EXCLUSIVE MODE")
        try:
            with pytest.raises(store.StoreUnavailable, match="Could not save the case"):
                quick.put_case(token, "blocked", inputs_to_dict(*_design(20)))
        finally:
            tx.rollback()
    assert list(quick.load(token)[1]) == ["safe"]
    quick.dispose()
