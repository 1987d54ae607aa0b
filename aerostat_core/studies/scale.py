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
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

#: ``--dask`` value that starts a 2-worker in-process cluster on this machine.
LOCAL = "local"


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
        return Client(scheduler, timeout=10)
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
    """
    if client is None:
        return [func(*a) for a in args]
    own = isinstance(client, str)
    c = dask_client(client) if own else client
    try:
        futures = [c.submit(func, *a, pure=True) for a in args]
        return c.gather(futures)
    finally:
        if own:
            close_client(c)
