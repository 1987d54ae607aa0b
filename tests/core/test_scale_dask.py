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
