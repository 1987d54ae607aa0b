"""Scale-out: map independent blocks of a batch evaluation over a Dask cluster.

The batch evaluators (:func:`aerostat_core.studies.envelope.envelope_block`,
:func:`aerostat_core.studies.uncertainty.sample_block`) are pure functions of their arguments (arrays and
frozen dataclasses, random numbers drawn from a seed given to each block), so a block gives the
same numbers wherever it runs: the result on a cluster equals the single-process one.

``dask`` is an optional extra (``pip install .[dask]``); without it only ``client=None`` works.

Usage with a real cluster::

    from dask.distributed import Client
    client = Client("tcp://scheduler-host:8786")   # or the CLI: --dask tcp://scheduler-host:8786
    mc = monte_carlo(d, 100_000_000, seed=1, client=client)  # blocks of 2000: ~160 MB each

Every call to the cluster is bounded: connecting waits :data:`CONNECT_TIMEOUT`, and a map whose
cluster has no worker (or whose scheduler does not answer) for :data:`LOST_AFTER` seconds stops
with :class:`ClusterLostError` saying how many blocks were done, instead of waiting forever for
futures no worker will compute. :func:`map_reduce` keeps at most ``window`` blocks in flight and
folds each result as it arrives, so the client's memory does not grow with the number of blocks.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Sequence
from typing import Any

#: ``--dask`` value that starts a 2-worker in-process cluster on this machine.
LOCAL = "local"
#: Seconds to wait for a scheduler to accept the connection.
CONNECT_TIMEOUT = 10.0
#: A map stops when the cluster has had no worker, or its scheduler has not answered, for this
#: long [s] (a lost cluster gives an error within a minute, never a hang).
LOST_AFTER = 30.0
#: Seconds between checks of the cluster while blocks are pending.
POLL = 2.0
#: Blocks in flight per worker in :func:`map_reduce` (at least 4 in all).
WINDOW_PER_WORKER = 2


class ClusterLostError(ValueError):
    """The Dask cluster had no worker, or did not answer, for :data:`LOST_AFTER` seconds."""


def dask_client(scheduler: str):
    """A ``dask.distributed.Client`` for ``scheduler``: ``"local"`` starts a 2-worker
    ``LocalCluster`` (threads, one process), anything else is a scheduler address
    (``tcp://host:8786``). ``ValueError`` with an install hint when dask is missing."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise ValueError(
            "--dask needs the optional dask extra: pip install .[dask] "
            "(dask and distributed, pinned in requirements-dev.txt)"
        ) from None
    if scheduler == LOCAL:
        cluster = LocalCluster(
            n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None
        )
        return Client(cluster)
    try:
        return Client(scheduler, timeout=CONNECT_TIMEOUT)
    except (OSError, TimeoutError, ValueError) as exc:
        raise ValueError(f"--dask {scheduler}: cannot reach the scheduler ({exc})") from None


def close_client(client) -> None:
    """Close a client made by :func:`dask_client` (and its local cluster, if any)."""
    cluster = getattr(client, "cluster", None)
    client.close()
    if cluster is not None:
        cluster.close()


def map_blocks(func: Callable, args: Sequence[tuple], client: Any = None) -> list:
    """``[func(*a) for a in args]``, on a Dask cluster when ``client`` is given.

    Parameters
    ----------
    func : callable
        A pure function (same arguments, same result).
    args : sequence of tuple
        Arguments of each block.
    client : dask.distributed.Client, str or None
        A client, a scheduler address / ``"local"`` (a client is made and closed), or ``None``
        (run here).

    Returns
    -------
    list
        The block results, in the order of ``args``.

    Raises
    ------
    ClusterLostError
        No worker (or no answer from the scheduler) for :data:`LOST_AFTER` seconds.
    """
    out: dict[int, Any] = {}

    def keep(acc, item):
        acc[item[0]] = item[1]
        return acc

    map_reduce(func, args, keep, out, client=client)
    return [out[i] for i in range(len(out))]


def map_reduce(
    func: Callable,
    args: Iterable[tuple],
    fold: Callable[[Any, tuple[int, Any]], Any],
    initial: Any,
    client: Any = None,
    window: int | None = None,
) -> Any:
    """Fold ``(index, func(*a))`` of every block into ``initial`` as the blocks finish.

    Here (``client=None``) the blocks run in order, one at a time. On a cluster at most
    ``window`` blocks are in flight (default :data:`WINDOW_PER_WORKER` per worker, at least 4)
    and each result is folded and released as it arrives (in any order: ``fold`` gets the
    block's index), so the client holds one accumulator, never every block's result.

    Raises
    ------
    ClusterLostError
        No worker, or no answer from the scheduler, for :data:`LOST_AFTER` seconds.
    """
    acc = initial
    if client is None:
        for i, a in enumerate(args):
            acc = fold(acc, (i, func(*a)))
        return acc
    from dask.distributed import wait

    own = isinstance(client, str)
    c = dask_client(client) if own else client
    try:
        todo = iter(enumerate(args))
        if window is None:
            window = max(4, WINDOW_PER_WORKER * _workers(c, default=2))
        pending: dict = {}
        done = 0
        last_seen = time.monotonic()
        while True:
            while len(pending) < window:
                nxt = next(todo, None)
                if nxt is None:
                    break
                i, a = nxt
                pending[c.submit(func, *a, pure=True)] = i
            if not pending:
                return acc
            try:
                finished = wait(list(pending), timeout=POLL, return_when="FIRST_COMPLETED").done
            except TimeoutError:
                finished = set()
            for f in finished:
                i = pending.pop(f)
                acc = fold(acc, (i, f.result(timeout=POLL)))
                f.release()
                done += 1
            if finished or _workers(c, default=0) > 0:
                last_seen = time.monotonic()
            elif time.monotonic() - last_seen > LOST_AFTER:
                for f in pending:
                    f.cancel()
                raise ClusterLostError(
                    f"the Dask cluster has had no worker (or its scheduler has not answered) "
                    f"for {LOST_AFTER:g} s; {done} block(s) were done, {len(pending)} pending: "
                    "check the cluster and run again"
                )
    finally:
        if own:
            close_client(c)


def _workers(c, default: int) -> int:
    """Workers the scheduler has now (``default`` when it does not answer within POLL s)."""
    try:
        return len(c.ncores(callback_timeout=POLL))
    except Exception:  # noqa: BLE001 - an unreachable scheduler counts as none
        return default
