"""boxcyl.distance and the batch distances (distances_aligned, distances_oriented,
distances_parallelepiped): proved bounds at most 4 float64 values apart around distances known
exactly, exact zeros for touching solids, float32 and other real inputs, the package's ValueErrors,
and each batch element equal to the scalar answer.

Run from the repository root: PYTHONPATH=<build>/python /usr/bin/python3 -m pytest python/tests
(CTest: ctest -L python).
"""
import math
import struct
import sys
from fractions import Fraction

import numpy as np
import pytest

import boxcyl

SEED = 20261201  # fixed; failures print the case
UNIT = boxcyl.AlignedBox(min=(0, 0, 0), max=(1, 1, 1))


def steps(lo, hi):
    """How many float64 values lie from lo up to hi (both >= 0): their bit patterns' difference."""
    return struct.unpack("<q", struct.pack("<d", hi))[0] - struct.unpack("<q", struct.pack("<d", lo))[0]


def expect_encloses(d, exact):
    assert isinstance(d, boxcyl.Distance)
    assert d.lower <= exact <= d.upper, f"{d} does not enclose {exact!r}"
    assert 0 <= steps(d.lower, d.upper) <= 4, f"{d} is more than 4 doubles wide"


def test_distance_exactly_one_is_enclosed_tightly():
    # The face x = 1 and the cylinder's side at x = 2.
    cyl = boxcyl.Cylinder(center=(3, 0.5, 0.5), axis=(0, 0, 1), radius=1, height=1)
    d = boxcyl.distance(UNIT, cyl)
    expect_encloses(d, 1.0)
    lower, upper, on_box, on_cylinder = d  # a named tuple
    assert (lower, upper) == (d.lower, d.upper)
    assert isinstance(on_box, tuple) and len(on_box) == 3 and all(isinstance(x, float) for x in on_box)
    assert isinstance(on_cylinder, tuple) and len(on_cylinder) == 3
    assert on_box[0] == pytest.approx(1, abs=1e-12) and on_cylinder[0] == pytest.approx(2, abs=1e-12)
    assert math.dist(on_box, on_cylinder) == pytest.approx(1, rel=1e-12)
    # The clearance query agrees, exactly: within 1, not within the double below it.
    assert boxcyl.intersects(UNIT, cyl, margin=1.0)
    assert not boxcyl.intersects(UNIT, cyl, margin=math.nextafter(1.0, 0.0))


def test_touching_is_exactly_zero():
    cyl = boxcyl.Cylinder(center=(2, 0.5, 0.5), axis=(0, 0, 1), radius=1, height=1)  # touches x = 1
    d = boxcyl.distance(UNIT, cyl)
    assert d.lower == 0.0 and d.upper == 0.0
    assert math.copysign(1, d.lower) == 1 and math.copysign(1, d.upper) == 1
    inside = boxcyl.Cylinder(center=(0.5, 0.5, 0.5), axis=(1, 1, 1), radius=0.1, height=0.2)
    assert boxcyl.distance(UNIT, inside)[:2] == (0.0, 0.0)


def test_every_box_kind():
    # An oriented box whose axes permute x, y, z: its x half-extent is 3, so its face is x = 3.
    obox = boxcyl.OrientedBox(center=(0, 0, 0), axes=((0, 1, 0), (0, 0, 1), (1, 0, 0)), extents=(1, 2, 3))
    cyl = boxcyl.Cylinder(center=(10, 0, 0), axis=(0, 0, 1), radius=2, height=1)
    expect_encloses(boxcyl.distance(obox, cyl), 5.0)
    # A cube of half side 5 with integer axes: its face along u = (3, 4, 0)/5 is 5 from the centre; a
    # segment through (9, 12, 0) = 15u, of radius 2, is 8 from it.
    pbox = boxcyl.Parallelepiped(center=(0, 0, 0), axes=((3, 4, 0), (-4, 3, 0), (0, 0, 5)), extents=(1, 1, 1))
    rod = boxcyl.Cylinder(center=(9, 12, 0), axis=(0, 0, 1), radius=2, height=4)
    expect_encloses(boxcyl.distance(pbox, rod), 8.0)


def test_float32_and_other_real_inputs_are_their_float64_values():
    tenth = np.float32(0.1)
    box = boxcyl.AlignedBox(min=np.zeros(3, dtype=np.float32), max=np.array([tenth] * 3))
    cyl = boxcyl.Cylinder(center=np.array([3, 0.05, 0.05], dtype=np.float32), axis=(0, 0, 1), radius=np.float32(1),
                          height=Fraction(1, 8))
    # 2 - float32(0.1) is a float64 (28 significant bits): the exact distance.
    exact = 2.0 - float(tenth)
    assert Fraction(exact) == 2 - Fraction(float(tenth))
    expect_encloses(boxcyl.distance(box, cyl), exact)
    # The batch reads float32 arrays as their float64 values too.
    boxes32 = np.array([[[0, 0, 0], [tenth] * 3]], dtype=np.float32)
    got = boxcyl.distances_aligned(boxes32, cyl)
    assert (got.lower[0], got.upper[0]) == boxcyl.distance(box, cyl)[:2]


def test_beyond_the_float64_range_upper_is_inf():
    far = boxcyl.AlignedBox(min=(-1e308, 0, 0), max=(-1e308, 1, 1))
    cyl = boxcyl.Cylinder(center=(1e308, 0.5, 0.5), axis=(0, 0, 1), radius=1, height=1)
    d = boxcyl.distance(far, cyl)
    assert d.lower == sys.float_info.max and d.upper == math.inf


def test_invalid_arguments_raise_value_error():
    cyl = boxcyl.Cylinder(center=(3, 0.5, 0.5), axis=(0, 0, 1), radius=1, height=1)
    with pytest.raises(ValueError, match=r"^cylinder: expected a Cylinder, got AlignedBox"):
        boxcyl.distance(UNIT, UNIT)
    with pytest.raises(ValueError, match=r"^box: expected an AlignedBox, an OrientedBox or a Parallelepiped, got tuple"):
        boxcyl.distance(((0, 0, 0), (1, 1, 1)), cyl)
    with pytest.raises(ValueError, match=r"^cylinder.radius: is negative"):
        boxcyl.Cylinder(center=(3, 0.5, 0.5), axis=(0, 0, 1), radius=-1, height=1)
    with pytest.raises(TypeError):
        boxcyl.distance(UNIT, cyl, margin=1)  # pylint: disable=unexpected-keyword-arg
    boxes = np.array([[[0, 0, 0], [1, 1, 1]], [[np.nan, 0, 0], [1, 1, 1]], [[2, 0, 0], [1, 1, 1]]])
    with pytest.raises(ValueError, match=r"^boxes\[1\]\.min\[0\]: is NaN"):
        boxcyl.distances_aligned(boxes, cyl)
    with pytest.raises(ValueError, match=r"^boxes: expected shape \(N, 2, 3\)"):
        boxcyl.distances_aligned(np.zeros((4, 3)), cyl)
    with pytest.raises(ValueError, match=r"^cylinders\[1\]\.axis: is the zero vector"):
        boxcyl.distances_aligned(UNIT, (np.zeros((2, 3)), np.array([[0, 0, 1], [0, 0, 0]]), 1.0, 1.0))
    with pytest.raises(ValueError, match=r"^threads: expected a non-negative integer"):
        boxcyl.distances_aligned(UNIT, cyl, threads=-1)


def aligned_boxes(rng, n):
    lo = rng.uniform(-4, 4, (n, 3))
    boxes = np.stack([lo, lo + rng.uniform(0, 2, (n, 3))], axis=1)
    boxes[::17, 1, 0] = boxes[::17, 0, 0]  # some flat boxes
    return boxes


def frames(rng, n):
    q, r = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    axes = np.swapaxes(q * np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :], 1, 2).copy()
    return rng.uniform(-4, 4, (n, 3)), axes, rng.uniform(0, 1, (n, 3))


def expect_scalar(got, boxes, cylinders):
    """Every element exactly as the scalar distance gives it (bounds and nearest pair)."""
    n = len(boxes)
    assert isinstance(got, boxcyl.Distances)
    assert got.lower.dtype == got.upper.dtype == got.on_box.dtype == got.on_cylinder.dtype == np.float64
    assert got.lower.shape == got.upper.shape == (n,) and got.on_box.shape == got.on_cylinder.shape == (n, 3)
    for i in range(n):
        cyl = cylinders[i] if isinstance(cylinders, list) else cylinders
        want = boxcyl.distance(boxes[i], cyl)
        have = (float(got.lower[i]), float(got.upper[i]), tuple(got.on_box[i].tolist()), tuple(got.on_cylinder[i].tolist()))
        assert have == tuple(want), f"element {i}: batch {have}, scalar {want}: boxcyl.distance({boxes[i]!r}, {cyl!r})"


CYL = boxcyl.Cylinder(center=(0.5, -0.25, 0), axis=(1, 2, 3), radius=1.5, height=4)


def test_aligned_batch_equals_the_scalar_distance():
    rng = np.random.default_rng(SEED)
    boxes = aligned_boxes(rng, 300)
    objects = [boxcyl.AlignedBox(min=b[0], max=b[1]) for b in boxes]
    got = boxcyl.distances_aligned(boxes, CYL)
    expect_scalar(got, objects, CYL)
    assert np.any(got.upper == 0) and np.any(got.lower > 0)  # both kinds of answer
    # Threads, layouts and a list of boxes give the same arrays.
    for other in (boxcyl.distances_aligned(boxes, CYL, threads=1), boxcyl.distances_aligned(boxes, CYL, threads=3),
                  boxcyl.distances_aligned((boxes[:, 0], boxes[:, 1]), CYL), boxcyl.distances_aligned(objects, CYL)):
        for a, b in zip(other, got):
            assert np.array_equal(a, b)
    # A cylinder per box.
    centers = rng.uniform(-2, 2, (40, 3))
    cylinders = [boxcyl.Cylinder(center=c, axis=(0, 1, 1), radius=0.5, height=2) for c in centers]
    expect_scalar(boxcyl.distances_aligned(boxes[:40], cylinders, threads=2), objects[:40], cylinders)


def test_oriented_and_parallelepiped_batches_equal_the_scalar_distance():
    rng = np.random.default_rng(SEED + 1)
    center, axes, extents = frames(rng, 150)
    oriented = [boxcyl.OrientedBox(center=c, axes=a, extents=e) for c, a, e in zip(center, axes, extents)]
    expect_scalar(boxcyl.distances_oriented((center, axes, extents), CYL, threads=2), oriented, CYL)
    p_axes = axes * rng.uniform(0.2, 2, (150, 3, 1))  # any lengths
    p_axes[::25, 2] = p_axes[::25, 0]  # some flat ones
    parallelepipeds = [boxcyl.Parallelepiped(center=c, axes=a, extents=e) for c, a, e in zip(center, p_axes, extents)]
    expect_scalar(boxcyl.distances_parallelepiped((center, p_axes, extents), CYL), parallelepipeds, CYL)
    expect_scalar(boxcyl.distances_parallelepiped(parallelepipeds[:10], CYL, threads=1), parallelepipeds[:10], CYL)


def test_empty_and_single_batches():
    got = boxcyl.distances_aligned(np.zeros((0, 2, 3)), CYL)
    assert got.lower.shape == (0,) and got.on_box.shape == (0, 3)
    got = boxcyl.distances_aligned([], CYL)
    assert got.upper.shape == (0,)
    one = boxcyl.distances_oriented(boxcyl.OrientedBox(center=(5, 5, 5), axes=np.eye(3), extents=(1, 1, 1)), CYL)
    assert one.lower.shape == (1,)
    want = boxcyl.distance(boxcyl.OrientedBox(center=(5, 5, 5), axes=np.eye(3), extents=(1, 1, 1)), CYL)
    assert (one.lower[0], one.upper[0]) == want[:2]
