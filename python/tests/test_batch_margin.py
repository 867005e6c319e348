"""The batch forms' margin= (intersects_aligned, intersects_oriented, intersects_parallelepiped, and
their Dask forms): each answer equals the scalar boxcyl.intersects(box, cylinder, margin=m), exactly,
at random margins and at boxes exactly at the margin; a bad margin is refused, named.

Run from the repository root: PYTHONPATH=<build>/python /usr/bin/python3 -m pytest python/tests
(CTest: ctest -L python).
"""
import math
import re

import numpy as np
import pytest

import boxcyl

SEED = 20261130  # fixed; failures print the case
CYL = boxcyl.Cylinder(center=(0.5, -0.25, 0), axis=(1, 2, 3), radius=1.5, height=4)


def aligned_boxes(rng, n):
    lo = rng.uniform(-6, 6, (n, 3))
    boxes = np.stack([lo, lo + rng.uniform(0, 2, (n, 3))], axis=1)
    boxes[::37, 1, 2] = boxes[::37, 0, 2]  # some flat boxes
    return boxes


def frames(rng, n):
    q, r = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    axes = np.swapaxes(q * np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :], 1, 2).copy()
    return rng.uniform(-6, 6, (n, 3)), axes, rng.uniform(0, 1, (n, 3))


def expect_scalar(got, boxes, cylinder, margin):
    """Every answer as the scalar query's; the first disagreement printed as a call to paste."""
    assert got.dtype == np.bool_ and got.shape == (len(boxes),)
    for i, box in enumerate(boxes):
        want = boxcyl.intersects(box, cylinder, margin=margin)
        assert got[i] == want, f"box {i}: batch {got[i]}, scalar {want}: boxcyl.intersects({box!r}, {cylinder!r}, margin={margin!r})"


def test_aligned_margin_equals_the_scalar_query():
    rng = np.random.default_rng(SEED)
    boxes = aligned_boxes(rng, 600)
    objects = [boxcyl.AlignedBox(min=b[0], max=b[1]) for b in boxes]
    for margin in (0.0, 0.01, 0.3, 1.0, 2.5, float(rng.uniform(0, 3))):
        got = boxcyl.intersects_aligned(boxes, CYL, margin=margin)
        expect_scalar(got, objects, CYL, margin)
        # The other layouts and options give the same answers: a (min, max) tuple of strided views,
        # one thread, and a rounded arithmetic (a margin is always answered exactly).
        assert np.array_equal(boxcyl.intersects_aligned((boxes[:, 0], boxes[:, 1]), CYL, margin=margin), got)
        assert np.array_equal(boxcyl.intersects_aligned(boxes, CYL, margin=margin, threads=1), got)
        assert np.array_equal(boxcyl.intersects_aligned(boxes, CYL, margin=margin, arithmetic="float64",
                                                        algorithm="hull"), got)
    # Margin 0 is the default query; a larger margin never answers fewer boxes.
    assert np.array_equal(boxcyl.intersects_aligned(boxes, CYL, margin=0), boxcyl.intersects_aligned(boxes, CYL))
    small, large = (boxcyl.intersects_aligned(boxes, CYL, margin=m) for m in (0.1, 0.2))
    assert np.all(large[small]) and large.sum() > small.sum()


def test_oriented_and_parallelepiped_margin_equal_the_scalar_query():
    rng = np.random.default_rng(SEED + 1)
    center, axes, extents = frames(rng, 300)
    oriented = [boxcyl.OrientedBox(center=c, axes=a, extents=e) for c, a, e in zip(center, axes, extents)]
    p_axes = axes * rng.uniform(0.2, 2, (300, 3, 1))  # any lengths
    p_axes[::25, 2] = p_axes[::25, 0]  # some flat ones
    parallelepipeds = [boxcyl.Parallelepiped(center=c, axes=a, extents=e) for c, a, e in zip(center, p_axes, extents)]
    for margin in (0.05, 0.7, 2.0):
        expect_scalar(boxcyl.intersects_oriented((center, axes, extents), CYL, margin=margin), oriented, CYL, margin)
        expect_scalar(boxcyl.intersects_parallelepiped((center, p_axes, extents), CYL, margin=margin), parallelepipeds,
                      CYL, margin)


def test_a_cylinder_per_box_takes_the_scalar_clearance_query():
    rng = np.random.default_rng(SEED + 2)
    boxes = aligned_boxes(rng, 80)
    centers = rng.uniform(-2, 2, (80, 3))
    cylinders = [boxcyl.Cylinder(center=c, axis=(0, 1, 1), radius=1, height=2) for c in centers]
    got = boxcyl.intersects_aligned(boxes, cylinders, margin=0.75)
    for i in range(80):
        box = boxcyl.AlignedBox(min=boxes[i, 0], max=boxes[i, 1])
        assert got[i] == boxcyl.intersects(box, cylinders[i], margin=0.75), i
    # One box against many cylinders, too.
    one = boxcyl.AlignedBox(min=(0, 0, 0), max=(1, 1, 1))
    got = boxcyl.intersects_aligned(one, cylinders, margin=0.75)
    assert got.tolist() == [boxcyl.intersects(one, c, margin=0.75) for c in cylinders]


def test_boxes_exactly_at_the_margin():
    # The corner (6, 0, 5) is exactly 5 from the rim point (3, 0, 1); the face x = 1.25 exactly 0.25 from
    # the side of the unit cylinder. Within at the margin, not one ulp below, among far boxes.
    cases = [
        (boxcyl.Cylinder(center=(0, 0, 0), axis=(0, 0, 1), radius=3, height=2), ((6, 0, 5), (7, 1, 6)), 5.0),
        (boxcyl.Cylinder(center=(0, 0, 0), axis=(0, 0, 1), radius=1, height=2), ((1.25, -0.5, -0.5), (2, 0.5, 0.5)), 0.25),
    ]
    far = np.array([[[100, 100, 100], [101, 101, 101]]] * 9, dtype=float)
    for cyl, (lo, hi), dist in cases:
        boxes = np.concatenate([far, np.array([[lo, hi]], dtype=float), far])
        center = (boxes[:, 0] + boxes[:, 1]) / 2
        extents = (boxes[:, 1] - boxes[:, 0]) / 2
        axes = np.broadcast_to(np.eye(3), (len(boxes), 3, 3))
        for margin, want in ((dist, True), (math.nextafter(dist, 0), False)):
            expected = [False] * 9 + [want] + [False] * 9
            assert boxcyl.intersects_aligned(boxes, cyl, margin=margin).tolist() == expected, (dist, margin)
            assert boxcyl.intersects_oriented((center, axes, extents), cyl, margin=margin).tolist() == expected
            assert boxcyl.intersects_parallelepiped((center, axes, extents), cyl, margin=margin).tolist() == expected


@pytest.mark.parametrize("form", ["aligned", "oriented", "parallelepiped"])
def test_a_bad_margin_is_refused_by_name(form):
    call = {
        "aligned": lambda m: boxcyl.intersects_aligned(np.zeros((3, 2, 3)), CYL, margin=m),
        "oriented": lambda m: boxcyl.intersects_oriented((np.zeros((3, 3)), np.eye(3), np.ones(3)), CYL, margin=m),
        "parallelepiped": lambda m: boxcyl.intersects_parallelepiped((np.zeros((3, 3)), np.eye(3), np.ones(3)), CYL,
                                                                     margin=m),
    }[form]
    with pytest.raises(ValueError, match=re.escape("margin: is negative")):
        call(-1)
    with pytest.raises(ValueError, match=re.escape("margin: is NaN")):
        call(float("nan"))
    with pytest.raises(ValueError, match=re.escape("margin: is +Inf")):
        call(float("inf"))
    with pytest.raises(ValueError, match="margin"):
        call("0.5")
    with pytest.raises(ValueError, match="margin"):
        call([0.5, 1.0])
    assert call(np.float32(0.5)).dtype == np.bool_


def test_dask_margin_equals_the_numpy_form():
    da = pytest.importorskip("dask.array")
    import boxcyl.dask

    rng = np.random.default_rng(SEED + 3)
    boxes = aligned_boxes(rng, 2_000)
    for margin in (0.2, 1.5):
        expected = boxcyl.intersects_aligned(boxes, CYL, margin=margin)
        lazy = boxcyl.dask.intersects_aligned(da.from_array(boxes, chunks=(300, 2, 3)), CYL, margin=margin)
        got = lazy.compute(scheduler="synchronous")
        assert np.array_equal(got, expected)
        for i in range(0, len(boxes), 97):  # and the scalar query, on a sample
            assert got[i] == boxcyl.intersects(boxcyl.AlignedBox(min=boxes[i, 0], max=boxes[i, 1]), CYL, margin=margin)
    center, axes, extents = frames(rng, 500)
    for form, numpy_form in ((boxcyl.dask.intersects_oriented, boxcyl.intersects_oriented),
                             (boxcyl.dask.intersects_parallelepiped, boxcyl.intersects_parallelepiped)):
        lazy = form((da.from_array(center, chunks=120), da.from_array(axes), da.from_array(extents)), CYL, margin=0.6)
        assert np.array_equal(lazy.compute(scheduler="synchronous"), numpy_form((center, axes, extents), CYL, margin=0.6))
    # A bad margin is refused when the graph is built, named as the numpy form names it.
    with pytest.raises(ValueError, match=re.escape("margin: is negative")):
        boxcyl.dask.intersects_aligned(da.from_array(boxes), CYL, margin=-0.5)
    with pytest.raises(ValueError, match=re.escape("margin: is NaN")):
        boxcyl.dask.intersects_oriented((da.from_array(center), da.from_array(axes), da.from_array(extents)), CYL,
                                        margin=float("nan"))
