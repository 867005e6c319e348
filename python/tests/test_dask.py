"""boxcyl.dask: Dask arrays of boxes against one cylinder, answered block by block by the numpy batch
forms on a local distributed cluster (two worker processes on the loopback interface), giving the
same answers as one call on the whole array.

Needs Debian's python3-dask and python3-distributed (installed by scripts/deps.sh).
"""
import re

import dask.array as da
import numpy as np
import pytest
from distributed import Client, LocalCluster

import boxcyl
import boxcyl.dask

SEED = 20261126
# distributed 2022.12 on tornado 6.2 warns at cluster start; nothing of boxcyl.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")
CYL = boxcyl.Cylinder(center=(0.5, -0.25, 0), axis=(1, 2, 3), radius=1.5, height=4)


@pytest.fixture(scope="module")
def client():
    # Worker processes: the cylinder, the options and each block travel pickled, as on a real cluster.
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster, Client(cluster) as c:
        yield c


def aligned_boxes(rng, n):
    lo = rng.uniform(-5, 5, (n, 3))
    boxes = np.stack([lo, lo + rng.uniform(0, 2, (n, 3))], axis=1)
    boxes[::97, 1, 2] = boxes[::97, 0, 2]  # some flat boxes
    return boxes


def test_aligned_on_a_cluster_equals_one_call(client):
    boxes = aligned_boxes(np.random.default_rng(SEED), 300_000)
    expected = boxcyl.intersects_aligned(boxes, CYL)
    assert 0.05 < expected.mean() < 0.5
    darr = da.from_array(boxes, chunks=(40_000, 2, 3))
    lazy = boxcyl.dask.intersects_aligned(darr, CYL)
    assert lazy.shape == (300_000,) and lazy.dtype == np.bool_ and lazy.chunks[0] == darr.chunks[0]
    got = client.compute(lazy).result()
    assert np.array_equal(got, expected)
    # Chunked along the other axes too (rechunked to whole boxes), other options, threads per block.
    odd = da.from_array(boxes, chunks=(70_000, 1, 2))
    got = client.compute(boxcyl.dask.intersects_aligned(odd, CYL, arithmetic="exact", threads=2)).result()
    assert np.array_equal(got, expected)


def test_a_lazily_generated_array_is_reduced_block_by_block(client):
    """2 million boxes (96 MB as float64) generated on the workers and counted there: the client holds
    neither the boxes nor the answers; the count equals the numpy form's, block by block."""
    rs = da.random.RandomState(SEED)
    lo = rs.uniform(-5, 5, size=(2_000_000, 3), chunks=(250_000, 3))
    boxes = da.stack([lo, lo + 1.0], axis=1)
    hits = boxcyl.dask.intersects_aligned(boxes, CYL)
    count = client.compute(hits.sum()).result()
    expected = sum(int(boxcyl.intersects_aligned(boxes.blocks[i].compute(), CYL).sum())
                   for i in range(boxes.numblocks[0]))
    assert count == expected and 0 < count < 2_000_000


def test_oriented_on_a_cluster_equals_one_call(client):
    rng = np.random.default_rng(SEED + 1)
    n = 50_000
    q, r = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    axes = np.swapaxes(q * np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :], 1, 2).copy()
    center = rng.uniform(-4, 4, (n, 3))
    extents = rng.uniform(0, 1, (n, 3))
    expected = boxcyl.intersects_oriented((center, axes, extents), CYL)
    assert 0.05 < expected.mean() < 0.6
    lazy = boxcyl.dask.intersects_oriented(
        (da.from_array(center, chunks=8_000), da.from_array(axes, chunks=(5_000, 3, 3)), da.from_array(extents)), CYL)
    assert np.array_equal(client.compute(lazy).result(), expected)


def test_an_invalid_box_is_named_by_its_index_in_the_whole_array(client):
    boxes = aligned_boxes(np.random.default_rng(SEED + 2), 100_000)
    boxes[77_777, 1, 0] = np.nan
    lazy = boxcyl.dask.intersects_aligned(da.from_array(boxes, chunks=(10_000, 2, 3)), CYL)
    with pytest.raises(ValueError, match=re.escape("boxes[77777].max[0]: is NaN")):
        client.compute(lazy).result()
    with pytest.raises(ValueError, match=re.escape("boxes: expected a Dask array of shape (N, 2, 3), got (5, 3)")):
        boxcyl.dask.intersects_aligned(da.zeros((5, 3)), CYL)
    with pytest.raises(ValueError, match=re.escape("cylinder: expected a boxcyl.Cylinder, got tuple")):
        boxcyl.dask.intersects_aligned(da.zeros((5, 2, 3)), ((0, 0, 0), (0, 0, 1), 1, 1))


def frames(rng, n):
    q, r = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    axes = np.swapaxes(q * np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :], 1, 2).copy()
    return rng.uniform(-4, 4, (n, 3)), axes, rng.uniform(0, 1, (n, 3))


def test_parallelepipeds_on_a_cluster_equal_one_call(client):
    rng = np.random.default_rng(SEED + 3)
    center, axes, extents = frames(rng, 20_000)
    axes = axes * rng.uniform(0.2, 2, (20_000, 3, 1))  # any lengths
    axes[::50, 2] = axes[::50, 0]  # some flat ones
    expected = boxcyl.intersects_parallelepiped((center, axes, extents), CYL)
    assert 0.05 < expected.mean() < 0.7
    lazy = boxcyl.dask.intersects_parallelepiped(
        (da.from_array(center, chunks=3_000), da.from_array(axes, chunks=(7_000, 3, 3)), da.from_array(extents)), CYL,
        threads=0)
    assert lazy.chunks[0] == (3_000,) * 6 + (2_000,)
    assert np.array_equal(client.compute(lazy).result(), expected)
    extents[12_345, 1] = -1
    bad = boxcyl.dask.intersects_parallelepiped((da.from_array(center, chunks=3_000), da.from_array(axes),
                                                 da.from_array(extents)), CYL)
    with pytest.raises(ValueError, match=re.escape("boxes[12345].extents[1]: is negative")):
        client.compute(bad).result()


@pytest.mark.parametrize("form", [boxcyl.dask.intersects_oriented, boxcyl.dask.intersects_parallelepiped])
def test_frame_forms_refuse_what_the_numpy_forms_refuse(form):
    """The fields are joined into one array per block, which would read booleans as 0 and 1: they are
    refused by dtype first, as the numpy forms refuse them."""
    center, axes, extents = frames(np.random.default_rng(SEED + 4), 10)
    with pytest.raises(ValueError, match=re.escape("boxes.extents: is an array of booleans (dtype bool); "
                                                   "expected real numbers")):
        form((da.from_array(center), da.from_array(axes), da.from_array(extents > 0.5)), CYL)
    with pytest.raises(ValueError, match=re.escape("boxes.axes: is an array of complex numbers (dtype complex128)")):
        form((da.from_array(center), da.from_array(axes + 0j), da.from_array(extents)), CYL)
    with pytest.raises(ValueError, match=re.escape("boxes.center: is an array of strings (dtype <U1)")):
        form((da.from_array(np.full((10, 3), "a")), da.from_array(axes), da.from_array(extents)), CYL)
    numpy_form = boxcyl.intersects_oriented if form is boxcyl.dask.intersects_oriented else boxcyl.intersects_parallelepiped
    with pytest.raises(ValueError, match=re.escape("boxes.extents: is an array of booleans (dtype bool)")):
        numpy_form((center, axes, extents > 0.5), CYL)
    # Integer fields are numbers, as in the numpy form.
    ints = form((da.from_array(np.zeros((10, 3), dtype=np.int32)), da.from_array(axes),
                 da.from_array(np.ones((10, 3), dtype=np.int64))), CYL).compute()
    assert np.array_equal(ints, numpy_form((np.zeros((10, 3), dtype=np.int32), axes, np.ones((10, 3))), CYL))
