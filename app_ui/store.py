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
"""

from __future__ import annotations

import json
import os
import re
import secrets
import threading
import time
from pathlib import Path
from typing import Any

import sqlalchemy as sa
from sqlalchemy.dialects.postgresql import insert as pg_insert
from sqlalchemy.dialects.sqlite import insert as sqlite_insert
from sqlalchemy.exc import SQLAlchemyError

#: Workspace tokens: 32 URL-safe characters (24 random bytes).
TOKEN_RE = re.compile(r"^[A-Za-z0-9_-]{32}$")
#: How long a writer waits for a locked SQLite file before giving up [s].
SQLITE_BUSY_TIMEOUT_S = 5.0

_meta = sa.MetaData()
workspaces = sa.Table(
    "workspaces",
    _meta,
    sa.Column("token", sa.String(64), primary_key=True),
    sa.Column("created", sa.Float, nullable=False),
    sa.Column("current_inputs", sa.Text, nullable=True),
)
cases = sa.Table(
    "cases",
    _meta,
    sa.Column("workspace", sa.String(64), sa.ForeignKey("workspaces.token"), primary_key=True),
    sa.Column("name", sa.String(400), primary_key=True),
    sa.Column("position", sa.Integer, nullable=False),
    sa.Column("inputs", sa.Text, nullable=False),
)


class StoreUnavailable(RuntimeError):
    """The database cannot be used right now; the message says why, for the user."""


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


def _describe(exc: BaseException) -> str:
    text = str(getattr(exc, "orig", None) or exc).splitlines()[0] if str(exc) else ""
    return text[:200]


class Store:
    """Workspaces in one database. Thread-safe (one engine, one connection per call)."""

    def __init__(self, url: str) -> None:
        self.url = url
        self.is_sqlite = url.startswith("sqlite")
        try:
            if self.is_sqlite:
                path = sa.engine.make_url(url).database
                if path and path != ":memory:":
                    Path(path).parent.mkdir(parents=True, exist_ok=True)
                self.engine = sa.create_engine(
                    url, connect_args={"timeout": SQLITE_BUSY_TIMEOUT_S}, pool_pre_ping=False
                )
                sa.event.listen(self.engine, "connect", _sqlite_pragmas)
                # BEGIN IMMEDIATE: take the write lock at the start, so two writers queue on the
                # busy timeout instead of one failing at once when it upgrades a read lock.
                sa.event.listen(
                    self.engine, "begin", lambda conn: conn.exec_driver_sql("BEGIN IMMEDIATE")
                )
            else:
                self.engine = sa.create_engine(url, pool_pre_ping=True, pool_size=5)
            # Creates missing tables only; an existing file that is not a database raises.
            with self.engine.begin() as conn:
                _meta.create_all(conn)
        except (SQLAlchemyError, OSError) as exc:
            raise StoreUnavailable(
                f"The saved-cases database cannot be opened ({_describe(exc)}). Nothing was "
                "deleted; changes made now are kept only until the page is closed."
            ) from exc

    # --- internal ----------------------------------------------------------------------------

    def _run(self, what: str, fn):
        try:
            with self.engine.begin() as conn:  # one transaction: all or nothing
                return fn(conn)
        except SQLAlchemyError as exc:
            raise StoreUnavailable(
                f"Could not {what}: the saved-cases database is unavailable "
                f"({_describe(exc)}). Nothing was deleted."
            ) from exc

    @staticmethod
    def _check(token: str) -> None:
        if not valid_token(token):
            raise ValueError("not a workspace token")

    def _ensure(self, conn, token: str) -> None:
        """Create the workspace row if missing (safe when two sessions race to create it)."""
        insert = sqlite_insert if self.is_sqlite else pg_insert
        conn.execute(
            insert(workspaces)
            .values(token=token, created=time.time())
            .on_conflict_do_nothing(index_elements=["token"])
        )

    # --- reads -------------------------------------------------------------------------------

    def load(self, token: str) -> tuple[dict[str, Any] | None, dict[str, dict[str, Any]]]:
        """``(current inputs or None, {name: inputs} in saved order)`` of one workspace."""
        self._check(token)

        def q(conn):
            row = conn.execute(
                sa.select(workspaces.c.current_inputs).where(workspaces.c.token == token)
            ).first()
            rows = conn.execute(
                sa.select(cases.c.name, cases.c.inputs)
                .where(cases.c.workspace == token)
                .order_by(cases.c.position, cases.c.name)
            ).all()
            current = json.loads(row[0]) if row is not None and row[0] else None
            return current, {name: json.loads(text) for name, text in rows}

        return self._run("read the saved cases", q)

    # --- writes ------------------------------------------------------------------------------

    def set_current(self, token: str, inputs: dict[str, Any]) -> None:
        """Remember the workspace's current inputs."""
        self._check(token)
        text = json.dumps(inputs, sort_keys=True)

        def w(conn):
            self._ensure(conn, token)
            conn.execute(
                workspaces.update().where(workspaces.c.token == token).values(current_inputs=text)
            )

        self._run("save the current inputs", w)

    def put_case(self, token: str, name: str, inputs: dict[str, Any]) -> None:
        """Insert a case at the end, or replace the inputs of an existing one in place."""
        self._check(token)
        text = json.dumps(inputs, sort_keys=True)

        def w(conn):
            self._ensure(conn, token)
            where = (cases.c.workspace == token) & (cases.c.name == name)
            if conn.execute(sa.select(cases.c.name).where(where)).first() is not None:
                conn.execute(cases.update().where(where).values(inputs=text))
                return
            top = conn.execute(
                sa.select(sa.func.max(cases.c.position)).where(cases.c.workspace == token)
            ).scalar()
            conn.execute(
                cases.insert().values(
                    workspace=token, name=name, position=(top or 0) + 1, inputs=text
                )
            )

        self._run("save the case", w)

    def replace_cases(self, token: str, new: dict[str, dict[str, Any]]) -> None:
        """Make ``new`` (in order) the workspace's cases, in one transaction."""
        self._check(token)

        def w(conn):
            self._ensure(conn, token)
            conn.execute(cases.delete().where(cases.c.workspace == token))
            if new:
                conn.execute(
                    cases.insert(),
                    [
                        dict(
                            workspace=token,
                            name=n,
                            position=i + 1,
                            inputs=json.dumps(v, sort_keys=True),
                        )
                        for i, (n, v) in enumerate(new.items())
                    ],
                )

        self._run("save the cases", w)

    def rename_case(self, token: str, old: str, new: str) -> None:
        """Rename a case, keeping its place."""
        self._check(token)
        where = (cases.c.workspace == token) & (cases.c.name == old)
        self._run(
            "rename the case", lambda c: c.execute(cases.update().where(where).values(name=new))
        )

    def delete_case(self, token: str, name: str) -> None:
        """Delete one case (no error if it is gone)."""
        self._check(token)
        where = (cases.c.workspace == token) & (cases.c.name == name)
        self._run("delete the case", lambda c: c.execute(cases.delete().where(where)))

    def dispose(self) -> None:
        self.engine.dispose()


def _sqlite_pragmas(dbapi_conn, _record) -> None:
    # WAL: readers never block the writer, and a crash mid-write cannot corrupt the file.
    dbapi_conn.isolation_level = None  # transactions are begun by the "begin" listener
    cur = dbapi_conn.cursor()
    cur.execute("PRAGMA journal_mode=WAL")
    cur.execute("PRAGMA synchronous=NORMAL")
    cur.execute("PRAGMA foreign_keys=ON")
    cur.execute(f"PRAGMA busy_timeout={int(SQLITE_BUSY_TIMEOUT_S * 1000)}")
    cur.close()


_stores: dict[str, Store] = {}
_lock = threading.Lock()


def get_store(url: str | None = None) -> Store:
    """The process-wide :class:`Store` for ``url`` (default :func:`default_url`). A failure to
    open is not remembered: the next call tries again (the file may have been repaired)."""
    url = url or default_url()
    with _lock:
        if url not in _stores:
            _stores[url] = Store(url)
        return _stores[url]
