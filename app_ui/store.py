"""Persistent workspaces: saved cases and current inputs, keyed by an unguessable token.

SQLAlchemy Core over the standard library's ``sqlite3`` (WAL mode, every change in one
transaction) by default, or any database URL (PostgreSQL via psycopg) for a team deployment
with several app replicas. The same code and the same tests run against both
(tests/app/test_store.py; ``.ci/run`` starts Debian's postgresql on loopback for them).

Where the data lives:

* ``AEROSTAT_DATABASE_URL`` (e.g. ``postgresql+psycopg://user:pw@host/db``) if set; else
* ``AEROSTAT_DATA_DIR/aerostat.sqlite3``; ``AEROSTAT_DATA_DIR`` defaults to
  ``$XDG_DATA_HOME/aerostat`` (``~/.local/share/aerostat``). The Docker image sets it to the
  volume ``/data``.

A workspace is reached only through its token (``secrets.token_urlsafe``, 192 bits), carried in
the page URL so that it can be bookmarked or shared. There is deliberately no function that
lists workspaces. A database that cannot be opened or read (corrupt, locked, unreachable)
raises :class:`StoreUnavailable`; nothing here ever deletes, truncates or recreates a database
file.

Concurrency (several tabs or people on one workspace, several app replicas): every write touches
single rows (insert, update or delete of one case), never the whole list, inside one transaction
that first locks the workspace row, so writers to one workspace queue. Each write takes the next
number of the workspace's counter (``workspaces.seq``): a new case gets it as its ``position`` (so
positions are unique and ordered on every database) and every write as the case's ``version``.
A write made from what a tab saw passes the version it saw (``expect=``); when the row has
changed or gone since, the write is refused with :class:`CaseConflict` and nothing is changed.

Timeouts: every call is bounded by :attr:`Store.timeout_s` (``AEROSTAT_DB_TIMEOUT_S``, default
3 s): the connect timeout, the server's statement and lock timeouts, SQLite's busy timeout, and
a watchdog that cuts the connection of a call that overruns (a server that accepts connections
and then never answers). After such a hang the store answers "unavailable" at once for
:data:`RETRY_AFTER_S` instead of making every page wait again.
"""

from __future__ import annotations

import json
import math
import os
import re
import secrets
import socket
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import sqlalchemy as sa
from sqlalchemy.dialects.postgresql import insert as pg_insert
from sqlalchemy.dialects.sqlite import insert as sqlite_insert
from sqlalchemy.exc import DBAPIError, SQLAlchemyError

#: Workspace tokens: 32 URL-safe characters (24 random bytes).
TOKEN_RE = re.compile(r"^[A-Za-z0-9_-]{32}$")
#: How long a writer waits for a locked SQLite file before giving up [s] (at most the timeout).
SQLITE_BUSY_TIMEOUT_S = 5.0
#: Default bound on one database call [s]; ``AEROSTAT_DB_TIMEOUT_S`` overrides it.
DEFAULT_TIMEOUT_S = 3.0
#: After a call that hung for its whole timeout, answer "unavailable" at once for this long [s].
RETRY_AFTER_S = 2.0
#: Longest case name the store accepts [characters] (the app's limit is shorter).
NAME_CHARS = 400

_meta = sa.MetaData()
workspaces = sa.Table(
    "workspaces",
    _meta,
    sa.Column("token", sa.String(64), primary_key=True),
    sa.Column("created", sa.Float, nullable=False),
    sa.Column("current_inputs", sa.Text, nullable=True),
    sa.Column("seq", sa.Integer, nullable=False, server_default="0"),
)
cases = sa.Table(
    "cases",
    _meta,
    sa.Column("workspace", sa.String(64), sa.ForeignKey("workspaces.token"), primary_key=True),
    sa.Column("name", sa.String(NAME_CHARS), primary_key=True),
    sa.Column("position", sa.Integer, nullable=False),
    sa.Column("inputs", sa.Text, nullable=False),
    sa.Column("version", sa.Integer, nullable=False, server_default="0"),
)
#: Unique, ordered positions within a workspace.
POSITION_INDEX = "cases_workspace_position"


class StoreUnavailable(RuntimeError):
    """The database cannot be used right now; the message says why, for the user."""


class CaseConflict(ValueError):
    """A write refused because the case is not as the writer saw it; nothing was changed.

    ``kind``: "taken" (a case of that name exists), "changed" (its version is not the one
    expected) or "gone" (it was deleted). ``version`` is the row's version now (None if gone)."""

    def __init__(self, kind: str, name: str, version: int | None = None) -> None:
        self.kind, self.name, self.version = kind, name, version
        super().__init__(
            {
                "taken": f"A case named “{name}” exists already",
                "changed": f"“{name}” was changed in another tab or session since this page "
                "showed it",
                "gone": f"“{name}” was deleted in another tab or session",
            }[kind]
        )


@dataclass(frozen=True)
class Snapshot:
    """One workspace as read in one transaction: the current inputs (or None), the cases
    ``{name: inputs}`` in saved order and their versions ``{name: version}``."""

    current: dict[str, Any] | None
    cases: dict[str, dict[str, Any]]
    versions: dict[str, int] = field(default_factory=dict)


def new_token() -> str:
    """A fresh, unguessable workspace token (URL-safe)."""
    return secrets.token_urlsafe(24)


def valid_token(token: Any) -> bool:
    """Whether ``token`` has the shape of a workspace token (anything else is never queried)."""
    return isinstance(token, str) and bool(TOKEN_RE.match(token))


def default_data_dir() -> Path:
    """``AEROSTAT_DATA_DIR``, else ``$XDG_DATA_HOME/aerostat`` (``~/.local/share/aerostat``)."""
    env = os.environ.get("AEROSTAT_DATA_DIR", "").strip()
    if env:
        return Path(env)
    xdg = os.environ.get("XDG_DATA_HOME", "").strip()
    return (Path(xdg) if xdg else Path.home() / ".local" / "share") / "aerostat"


def default_url() -> str:
    """``AEROSTAT_DATABASE_URL`` or the SQLite file in :func:`default_data_dir`."""
    url = os.environ.get("AEROSTAT_DATABASE_URL", "").strip()
    if url:
        return url
    return f"sqlite:///{default_data_dir() / 'aerostat.sqlite3'}"


def default_timeout() -> float:
    """``AEROSTAT_DB_TIMEOUT_S`` (0.5 to 60 s) or :data:`DEFAULT_TIMEOUT_S`."""
    text = os.environ.get("AEROSTAT_DB_TIMEOUT_S", "").strip()
    try:
        value = float(text) if text else DEFAULT_TIMEOUT_S
    except ValueError:
        return DEFAULT_TIMEOUT_S
    return min(max(value, 0.5), 60.0) if math.isfinite(value) else DEFAULT_TIMEOUT_S


def unique_name(name: str, taken: Any, limit: int = 100) -> str:
    """``name``, or ``name (2)``, ``name (3)``... whichever is not in ``taken``; the suffixed
    name is shortened so that it stays within ``limit`` characters.

    >>> unique_name("a", {"a", "a (2)"})
    'a (3)'
    """
    final, i = name, 2
    while final in taken:
        suffix = f" ({i})"
        final = name[: limit - len(suffix)].rstrip() + suffix
        i += 1
    return final


def _describe(exc: BaseException) -> str:
    text = str(getattr(exc, "orig", None) or exc).splitlines()[0] if str(exc) else ""
    return text[:200]


def _dumps(inputs: dict[str, Any]) -> str:
    return json.dumps(inputs, sort_keys=True)


class _Watchdog:
    """Cuts the database connection of a call that overruns its deadline: the blocked read
    returns with an error instead of waiting for a server that never answers."""

    def __init__(self, seconds: float) -> None:
        self.dbapi: Any = None
        self.fired = False
        self._timer = threading.Timer(seconds, self._fire)
        self._timer.daemon = True

    def __enter__(self) -> _Watchdog:
        self._timer.start()
        return self

    def __exit__(self, *exc: Any) -> None:
        self._timer.cancel()

    def _fire(self) -> None:
        conn = self.dbapi
        if conn is None:
            return
        self.fired = True
        try:
            if hasattr(conn, "interrupt"):  # sqlite3
                conn.interrupt()
                return
            fd = conn.pgconn.socket  # psycopg: shut the socket down under the blocked read
            dup = socket.socket(fileno=os.dup(fd))
            try:
                dup.shutdown(socket.SHUT_RDWR)
            finally:
                dup.close()
        except Exception:  # noqa: BLE001 - best effort: the server timeouts still apply
            pass


class Store:
    """Workspaces in one database. Thread-safe (one engine, one connection per call)."""

    def __init__(self, url: str, *, timeout_s: float | None = None) -> None:
        self.url = url
        self.is_sqlite = url.startswith("sqlite")
        self.timeout_s = default_timeout() if timeout_s is None else float(timeout_s)
        self._down_until = 0.0
        self._down_message = ""
        started = time.monotonic()
        try:
            if self.is_sqlite:
                path = sa.engine.make_url(url).database
                if path and path != ":memory:":
                    Path(path).parent.mkdir(parents=True, exist_ok=True)
                busy = min(SQLITE_BUSY_TIMEOUT_S, self.timeout_s)
                self.engine = sa.create_engine(
                    url, connect_args={"timeout": busy}, pool_pre_ping=False
                )
                sa.event.listen(self.engine, "connect", lambda c, r: _sqlite_pragmas(c, r, busy))
                # BEGIN IMMEDIATE: take the write lock at the start, so two writers queue on the
                # busy timeout instead of one failing at once when it upgrades a read lock.
                sa.event.listen(
                    self.engine, "begin", lambda conn: conn.exec_driver_sql("BEGIN IMMEDIATE")
                )
            else:
                ms = int(self.timeout_s * 1000)
                self.engine = sa.create_engine(
                    url,
                    # No pre-ping: a ping to a hung server would block outside the watchdog. A
                    # dropped connection fails one call, invalidates the pool, and is retried.
                    pool_pre_ping=False,
                    pool_size=5,
                    pool_timeout=self.timeout_s,
                    connect_args={
                        "connect_timeout": max(2, math.ceil(self.timeout_s)),
                        "options": f"-c statement_timeout={ms} -c lock_timeout={ms} "
                        f"-c idle_in_transaction_session_timeout={4 * ms}",
                        "keepalives": 1,
                        "keepalives_idle": 5,
                        "keepalives_interval": 2,
                        "keepalives_count": 2,
                        "tcp_user_timeout": 2 * ms,
                    },
                )
            with _Watchdog(self.timeout_s + 0.5) as watchdog, self.engine.connect() as conn:
                watchdog.dbapi = conn.connection.dbapi_connection
                with conn.begin():
                    # Creates missing tables only; an existing file that is not a database
                    # raises.
                    _meta.create_all(conn)
                    self._migrate(conn)
        except (SQLAlchemyError, OSError) as exc:
            if time.monotonic() - started >= 0.8 * self.timeout_s:
                reason = f"no answer within {self.timeout_s:g} s"
            else:
                reason = _describe(exc)
            raise StoreUnavailable(
                f"The saved-cases database cannot be opened ({reason}). Nothing was "
                "deleted; changes made now are kept in this session and written when it is back."
            ) from exc

    # --- internal ----------------------------------------------------------------------------

    def _migrate(self, conn) -> None:
        """Bring a database made by an older version up to date (adds columns, renumbers
        duplicate positions, adds the unique position index); never drops anything."""
        insp = sa.inspect(conn)
        have = {c["name"] for c in insp.get_columns("workspaces")}
        if "seq" not in have:
            conn.exec_driver_sql("ALTER TABLE workspaces ADD COLUMN seq INTEGER NOT NULL DEFAULT 0")
        have = {c["name"] for c in insp.get_columns("cases")}
        if "version" not in have:
            conn.exec_driver_sql("ALTER TABLE cases ADD COLUMN version INTEGER NOT NULL DEFAULT 0")
        if POSITION_INDEX in {i["name"] for i in insp.get_indexes("cases")}:
            return
        dup = (
            sa.select(cases.c.workspace)
            .group_by(cases.c.workspace, cases.c.position)
            .having(sa.func.count() > 1)
        )
        for ws in {r[0] for r in conn.execute(dup)}:
            rows = conn.execute(
                sa.select(cases.c.name)
                .where(cases.c.workspace == ws)
                .order_by(cases.c.position, cases.c.name)
            ).all()
            top = conn.execute(
                sa.select(sa.func.max(cases.c.position)).where(cases.c.workspace == ws)
            ).scalar()
            for i, (name,) in enumerate(rows):  # two steps: never two rows on one position
                conn.execute(
                    cases.update()
                    .where((cases.c.workspace == ws) & (cases.c.name == name))
                    .values(position=top + 1 + i)
                )
        conn.execute(
            sa.text(
                f"CREATE UNIQUE INDEX IF NOT EXISTS {POSITION_INDEX} ON cases (workspace, position)"
            )
        )

    def _run(self, what: str, fn):
        """``fn(conn)`` in one transaction (all or nothing), bounded by :attr:`timeout_s`; a
        connection dropped since its last use is retried once on a fresh one."""
        now = time.monotonic()
        if now < self._down_until:
            raise StoreUnavailable(self._down_message)
        for attempt in (1, 2):
            started = time.monotonic()
            watchdog = _Watchdog(self.timeout_s + 0.5)
            try:
                with watchdog, self.engine.connect() as conn:
                    watchdog.dbapi = conn.connection.dbapi_connection
                    with conn.begin():
                        return fn(conn)
            except DBAPIError as exc:
                if exc.connection_invalidated and attempt == 1 and not watchdog.fired:
                    continue  # e.g. the server restarted since this pooled connection was used
                self._unavailable(what, exc, started, watchdog.fired)
            except SQLAlchemyError as exc:
                self._unavailable(what, exc, started, watchdog.fired)
        raise AssertionError("unreachable")

    def _unavailable(self, what: str, exc: BaseException, started: float, fired: bool):
        hung = fired or time.monotonic() - started >= 0.8 * self.timeout_s
        reason = f"no answer within {self.timeout_s:g} s" if hung else _describe(exc)
        message = (
            f"Could not {what}: the saved-cases database is unavailable ({reason}). "
            "Nothing was deleted."
        )
        if hung:
            self._down_until = time.monotonic() + RETRY_AFTER_S
            self._down_message = message
        raise StoreUnavailable(message) from exc

    @staticmethod
    def _check(token: str) -> None:
        if not valid_token(token):
            raise ValueError("not a workspace token")

    def _lock(self, conn, token: str) -> int:
        """Create the workspace row if missing, lock it for this transaction (writers to one
        workspace queue here) and return the next number of its counter, now taken."""
        insert = sqlite_insert if self.is_sqlite else pg_insert
        conn.execute(
            insert(workspaces)
            .values(token=token, created=time.time(), seq=0)
            .on_conflict_do_nothing(index_elements=["token"])
        )
        seq = conn.execute(
            sa.select(workspaces.c.seq).where(workspaces.c.token == token).with_for_update()
        ).scalar()
        # a database from before the counter: start above every position already used
        top = conn.execute(
            sa.select(sa.func.max(cases.c.position)).where(cases.c.workspace == token)
        ).scalar()
        nxt = max(seq or 0, top or 0) + 1
        conn.execute(workspaces.update().where(workspaces.c.token == token).values(seq=nxt))
        return nxt

    @staticmethod
    def _where(token: str, name: str):
        return (cases.c.workspace == token) & (cases.c.name == name)

    def _version(self, conn, token: str, name: str) -> int | None:
        return conn.execute(sa.select(cases.c.version).where(self._where(token, name))).scalar()

    def _rows(self, conn, token: str) -> list[tuple[str, str, int]]:
        return conn.execute(
            sa.select(cases.c.name, cases.c.inputs, cases.c.version)
            .where(cases.c.workspace == token)
            .order_by(cases.c.position, cases.c.name)
        ).all()

    def _insert(self, conn, token: str, name: str, text: str, seq: int, k: int = 0) -> None:
        """Insert at the end: position and version ``seq`` (``k`` more for the k-th row of a
        batch, whose counter the caller moves on)."""
        conn.execute(
            cases.insert().values(
                workspace=token, name=name, position=seq + k, inputs=text, version=seq + k
            )
        )

    @staticmethod
    def _advance(conn, token: str, seq: int) -> None:
        conn.execute(workspaces.update().where(workspaces.c.token == token).values(seq=seq))

    # --- reads -------------------------------------------------------------------------------

    def snapshot(self, token: str) -> Snapshot:
        """The workspace's current inputs, cases in saved order and their versions."""
        self._check(token)

        def q(conn):
            row = conn.execute(
                sa.select(workspaces.c.current_inputs).where(workspaces.c.token == token)
            ).first()
            rows = self._rows(conn, token)
            current = json.loads(row[0]) if row is not None and row[0] else None
            return Snapshot(
                current,
                {name: json.loads(text) for name, text, _ in rows},
                {name: version for name, _, version in rows},
            )

        return self._run("read the saved cases", q)

    def load(self, token: str) -> tuple[dict[str, Any] | None, dict[str, dict[str, Any]]]:
        """``(current inputs or None, {name: inputs} in saved order)`` of one workspace."""
        snap = self.snapshot(token)
        return snap.current, snap.cases

    # --- writes ------------------------------------------------------------------------------

    def set_current(self, token: str, inputs: dict[str, Any]) -> None:
        """Remember the workspace's current inputs."""
        self._check(token)
        text = _dumps(inputs)

        def w(conn):
            self._lock(conn, token)
            conn.execute(
                workspaces.update().where(workspaces.c.token == token).values(current_inputs=text)
            )

        self._run("save the current inputs", w)

    def put_case(
        self, token: str, name: str, inputs: dict[str, Any], *, expect: int | None = None
    ) -> int:
        """Write one case and return its new version.

        ``expect=None``: insert at the end, or replace the inputs of an existing case in place.
        ``expect=0``: insert only; a case of that name raises :class:`CaseConflict` ("taken").
        ``expect=v``: replace only the version ``v`` of the case ("changed" or "gone" else)."""
        self._check(token)
        text = _dumps(inputs)

        def w(conn):
            seq = self._lock(conn, token)
            now = self._version(conn, token, name)
            if now is None:
                if expect not in (None, 0):
                    raise CaseConflict("gone", name)
                self._insert(conn, token, name, text, seq)
                return seq
            if expect is not None and expect != now:
                raise CaseConflict("taken" if expect == 0 else "changed", name, now)
            conn.execute(
                cases.update().where(self._where(token, name)).values(inputs=text, version=seq)
            )
            return seq

        return self._run("save the case", w)

    def add_cases(
        self,
        token: str,
        new: dict[str, dict[str, Any]],
        *,
        limit: int = 100,
        max_cases: int | None = None,
    ) -> dict[str, int]:
        """Add cases at the end, in one transaction, never touching the saved ones: a case
        identical to a saved one (name and inputs) is skipped, another whose name is taken is
        added as ``name (2)``... (within ``limit`` characters). Returns ``{name used: version}``
        of the rows added. More than ``max_cases`` cases in all raises ``ValueError`` (nothing
        added)."""
        self._check(token)

        def w(conn):
            seq = self._lock(conn, token)
            saved = {name: text for name, text, _ in self._rows(conn, token)}
            used: dict[str, int] = {}
            for name, inputs in new.items():
                text = _dumps(inputs)
                if saved.get(name) == text:
                    continue
                final = unique_name(name, saved, limit)
                self._insert(conn, token, final, text, seq, len(used))
                used[final] = seq + len(used)
                saved[final] = text
            _check_count(len(saved), max_cases)
            if used:
                self._advance(conn, token, seq + len(used) - 1)
            return used

        return self._run("add the cases", w)

    def replace_cases(
        self,
        token: str,
        new: dict[str, dict[str, Any]],
        *,
        seen: dict[str, int] | None = None,
        limit: int = 100,
        max_cases: int | None = None,
    ) -> dict[str, int]:
        """Make ``new`` (in order) the workspace's cases, in one transaction; returns
        ``{name used: version}`` of the rows added.

        ``seen=None`` removes every saved case first. ``seen={name: version}`` (what the user
        was shown) removes only those rows, and only where the version still matches: a case
        another tab saved or changed since stays, and a new case whose name it holds is added as
        ``name (2)``..."""
        self._check(token)

        def w(conn):
            seq = self._lock(conn, token)
            if seen is None:
                conn.execute(cases.delete().where(cases.c.workspace == token))
            else:
                for name, version in seen.items():
                    conn.execute(
                        cases.delete().where(
                            self._where(token, name) & (cases.c.version == version)
                        )
                    )
            taken = {name for name, _, _ in self._rows(conn, token)}
            used: dict[str, int] = {}
            for name, inputs in new.items():
                final = unique_name(name, taken, limit)
                self._insert(conn, token, final, _dumps(inputs), seq, len(used))
                used[final] = seq + len(used)
                taken.add(final)
            _check_count(len(taken), max_cases)
            if used:
                self._advance(conn, token, seq + len(used) - 1)
            return used

        return self._run("save the cases", w)

    def rename_case(self, token: str, old: str, new: str, *, expect: int | None = None) -> int:
        """Rename a case, keeping its place; returns its new version. Raises
        :class:`CaseConflict`: "taken" when ``new`` exists, "gone" when ``old`` does not,
        "changed" when ``expect`` is given and is not the version of ``old``."""
        self._check(token)

        def w(conn):
            seq = self._lock(conn, token)
            now = self._version(conn, token, old)
            if now is None:
                raise CaseConflict("gone", old)
            if expect is not None and expect != now:
                raise CaseConflict("changed", old, now)
            if new == old:
                return now
            other = self._version(conn, token, new)
            if other is not None:
                raise CaseConflict("taken", new, other)
            conn.execute(
                cases.update().where(self._where(token, old)).values(name=new, version=seq)
            )
            return seq

        return self._run("rename the case", w)

    def delete_case(self, token: str, name: str, *, expect: int | None = None) -> None:
        """Delete one case (no error if it is gone). With ``expect``, only that version: a case
        changed since raises :class:`CaseConflict` ("changed") and stays."""
        self._check(token)

        def w(conn):
            self._lock(conn, token)
            if expect is not None:
                now = self._version(conn, token, name)
                if now is not None and now != expect:
                    raise CaseConflict("changed", name, now)
            conn.execute(cases.delete().where(self._where(token, name)))

        self._run("delete the case", w)

    def dispose(self) -> None:
        self.engine.dispose()


def _check_count(n: int, max_cases: int | None) -> None:
    if max_cases is not None and n > max_cases:
        raise ValueError(f"That would make {n} cases; at most {max_cases} can be saved.")


def _sqlite_pragmas(dbapi_conn, _record, busy_s: float = SQLITE_BUSY_TIMEOUT_S) -> None:
    # WAL: readers never block the writer, and a crash mid-write cannot corrupt the file.
    dbapi_conn.isolation_level = None  # transactions are begun by the "begin" listener
    cur = dbapi_conn.cursor()
    cur.execute("PRAGMA journal_mode=WAL")
    cur.execute("PRAGMA synchronous=NORMAL")
    cur.execute("PRAGMA foreign_keys=ON")
    cur.execute(f"PRAGMA busy_timeout={int(busy_s * 1000)}")
    cur.close()


_stores: dict[str, Store] = {}
_failures: dict[str, tuple[float, str]] = {}
_lock = threading.Lock()


def get_store(url: str | None = None) -> Store:
    """The process-wide :class:`Store` for ``url`` (default :func:`default_url`).

    The lock guards only the dictionary: a store is opened (connected) outside it, so a database
    that does not answer holds up only the sessions that need it, each for at most its timeout.
    A failure to open is remembered for :data:`RETRY_AFTER_S` (answered at once), then the next
    call tries again (the database may be back, the file repaired)."""
    url = url or default_url()
    with _lock:
        found = _stores.get(url)
        failed = _failures.get(url)
    if found is not None:
        return found
    if failed is not None and time.monotonic() < failed[0]:
        raise StoreUnavailable(failed[1])
    try:
        opened = Store(url)
    except StoreUnavailable as exc:
        with _lock:
            _failures[url] = (time.monotonic() + RETRY_AFTER_S, str(exc))
        raise
    with _lock:
        _failures.pop(url, None)
        kept = _stores.setdefault(url, opened)
    if kept is not opened:  # another session opened it meanwhile
        opened.dispose()
    return kept
