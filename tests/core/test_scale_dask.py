"""Scale-out: the Monte Carlo and the envelope on a 2-worker Dask LocalCluster equal the
single-process results for the same seed (dask is a dev requirement: never skipped)."""

from __future__ import annotations

import numpy as np
import pytest
from dask.distributed import Client, LocalCluster

from aerostat_core import Requirement, design
from aerostat_core.studies.envelope import operating_envelope
from aerostat_core.studies.scale import map_blocks
from aerostat_core.studies.uncertainty import monte_carlo


@pytest.fixture(scope="module")
def client():
    cluster = LocalCluster(
        n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None
    )
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture(scope="module")
def d():
    return design(Requirement(payload_mass=10.0, altitude=300.0))


def test_monte_carlo_on_a_cluster_equals_one_process(client, d):
    kw = dict(n=3000, seed=21, chunk=700, speeds=[4.0, 8.0, 12.0])
    here = monte_carlo(d, **kw)
    there = monte_carlo(d, client=client, **kw)
    assert len(client.scheduler_info()["workers"]) == 2
    for k in here.samples:
        assert np.array_equal(here.samples[k], there.samples[k]), k
    assert np.array_equal(here.blow_by, there.blow_by)
    assert here.summary() == there.summary()


def test_envelope_on_a_cluster_equals_one_process(client, d):
    kw = dict(wind=np.linspace(0, 25, 11), altitude=np.linspace(100, 500, 9), chunk=2)
    a = operating_envelope(d, **kw)
    b = operating_envelope(d, client=client, **kw)
    assert np.array_equal(a.g, b.g) and np.array_equal(a.margin, b.margin)


def test_map_blocks_keeps_order(client):
    assert map_blocks(pow, [(2, k) for k in range(6)], client=client) == [2**k for k in range(6)]
    assert map_blocks(pow, [(3, 2)]) == [9]


def test_histogram_mode_on_a_cluster_equals_one_process(client, d):
    kw = dict(n=2500, seed=4, chunk=600, speeds=[9.0], keep_samples=False)
    assert monte_carlo(d, **kw).summary() == monte_carlo(d, client=client, **kw).summary()


def _slow_square(x):
    import time

    time.sleep(0.3)
    return x * x


def test_a_cluster_that_loses_every_worker_gives_an_error_not_a_hang(monkeypatch):
    """Every worker gone mid-run: map_reduce stops with ClusterLostError after LOST_AFTER
    (shortened here) saying how many blocks were done; it never waits forever (the guard thread
    below fails the test instead of hanging the suite)."""
    import threading

    from aerostat_core.studies import scale

    monkeypatch.setattr(scale, "LOST_AFTER", 2.0)
    monkeypatch.setattr(scale, "POLL", 0.2)
    cluster = LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                           dashboard_address=None)
    c = Client(cluster)
    outcome: dict = {}

    def run():
        try:
            outcome["result"] = scale.map_blocks(_slow_square, [(k,) for k in range(200)], c)
        except Exception as exc:  # noqa: BLE001 - recorded for the assertion
            outcome["error"] = exc

    t = threading.Thread(target=run, daemon=True)
    t.start()
    try:
        import time

        time.sleep(1.5)
        for w in list(cluster.workers.values()):  # lose the only worker
            c.sync(w.close)
        t.join(timeout=120)
        assert not t.is_alive(), "map_blocks hung on a cluster without workers"
    finally:
        c.close()
        cluster.close()
    err = outcome.get("error")
    assert isinstance(err, scale.ClusterLostError), outcome
    assert "no worker" in str(err) and "block(s) were done" in str(err)


def test_map_reduce_folds_as_blocks_arrive_with_a_bounded_window(client):
    """At most ``window`` blocks are in flight: the fold sees every block once, in any order."""
    from aerostat_core.studies.scale import map_reduce

    seen = []
    total = map_reduce(pow, [(2, k) for k in range(20)],
                       lambda acc, item: (seen.append(item[0]), acc + item[1])[1], 0,
                       client=client, window=3)
    assert total == sum(2**k for k in range(20))
    assert sorted(seen) == list(range(20))


def test_the_cli_with_a_local_cluster_runs_past_the_in_process_budget(capsys):
    """--dask lifts the in-process Monte Carlo budget (the cluster supplies the compute)."""
    import json

    from aerostat_core.cli.entry import main
    from aerostat_core.model import budget

    n = budget.MAX_MONTE_CARLO_UNITS // (50 * 12) + 1
    assert main(["design", "--monte-carlo", str(n), "--json"]) == 2
    capsys.readouterr()
    assert main(["design", "--monte-carlo", str(n), "--dask", "local", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["monte_carlo_samples"] == n
