"""boxcyl.signed_distance and the batch signed distances (signed_distances_aligned,
signed_distances_oriented, signed_distances_parallelepiped): minus the penetration depth, enclosed
within 2**-43 times the shapes' size L (the largest of the box centre's offset from the cylinder's
centre, the half axes' components, the radius and the half height), for overlaps known exactly, with the normal and the
witness pair; the distance's bounds and nearest pair for solids apart; the package's ValueErrors;
and each batch element equal to the scalar answer.

Run from the repository root: PYTHONPATH=<build>/python /usr/bin/python3 -m pytest python/tests
(CTest: ctest -L python).
"""
import math

import numpy as np
import pytest

import boxcyl

SEED = 20261202  # fixed; failures print the case
CUBE = boxcyl.AlignedBox(min=(-1, -1, -1), max=(1, 1, 1))
# A tall cylinder of radius 1 whose axis is x = 1.5: it overlaps the cube by 0.5 along x.
DEEP = boxcyl.Cylinder(center=(1.5, 0, 0), axis=(0, 0, 1), radius=1, height=10)


def expect_overlap(d, depth, normal, size):
    """d encloses -depth, at most 2**-43 times `size` (the shapes' size L) wide, with a unit normal near
    `normal` and a witness pair."""
    assert isinstance(d, boxcyl.SignedDistance)
    assert d.lower <= -depth <= d.upper, f"{d} does not enclose {-depth!r}"
    assert d.upper - d.lower <= 2**-43 * size, f"{d} is wider than 2**-43 * {size}"
    assert math.hypot(*d.normal) == pytest.approx(1, abs=1e-12)
    if normal is not None:
        assert d.normal == pytest.approx(normal, abs=1e-9), d
    gap = np.subtract(d.on_cylinder, d.on_box)
    assert gap == pytest.approx(-depth * np.asarray(d.normal), abs=1e-9), d


def test_overlap_by_one_half_along_x():
    d = boxcyl.signed_distance(CUBE, DEEP)
    expect_overlap(d, 0.5, (1, 0, 0), 5)  # L: the half height
    lower, upper, normal, on_box, on_cylinder = d  # a named tuple
    assert (lower, upper, normal) == (d.lower, d.upper, d.normal)
    for point in (normal, on_box, on_cylinder):
        assert isinstance(point, tuple) and len(point) == 3 and all(isinstance(x, float) for x in point)
    # The contact, once the cube is moved 0.5 along -x: the segment x = 0.5, y = 0, |z| <= 1; the witnesses
    # are a point of it, on the cube's face x = 1 and on the post's side.
    assert on_box[:2] == pytest.approx((1, 0), abs=1e-9) and -1 <= on_box[2] <= 1, on_box
    assert on_cylinder == pytest.approx((0.5, 0, on_box[2]), abs=1e-9), on_cylinder
    # The distance only says that they meet.
    assert boxcyl.distance(CUBE, DEEP)[:2] == (0.0, 0.0)


def test_apart_is_the_distance_with_a_normal():
    for cyl in (boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 1), radius=1, height=10),
                boxcyl.Cylinder(center=(4, 5, -6), axis=(1, 2, 3), radius=0.5, height=2)):
        d = boxcyl.signed_distance(CUBE, cyl)
        want = boxcyl.distance(CUBE, cyl)
        assert want.lower > 0
        assert (d.lower, d.upper, d.on_box, d.on_cylinder) == tuple(want)
        gap = np.subtract(d.on_cylinder, d.on_box)
        assert d.normal == pytest.approx(gap / np.linalg.norm(gap), abs=1e-12)
    d = boxcyl.signed_distance(CUBE, boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 1), radius=1, height=10))
    assert d.lower <= 1 <= d.upper and d.normal == pytest.approx((1, 0, 0), abs=1e-12)


def test_touching_is_zero():
    d = boxcyl.signed_distance(CUBE, boxcyl.Cylinder(center=(2, 0, 0), axis=(0, 0, 1), radius=1, height=10))
    assert d.lower <= 0 <= d.upper and d.upper - d.lower <= 2**-43 * 5, d
    assert d.normal == pytest.approx((1, 0, 0), abs=1e-9)


def test_deep_inside():
    # A small cylinder at the cube's centre: the box moves 1 + 0.25 along x, y or z to let it go.
    d = boxcyl.signed_distance(CUBE, boxcyl.Cylinder(center=(0, 0, 0), axis=(0, 0, 1), radius=0.25, height=0.5))
    expect_overlap(d, 1.25, None, 1)
    assert sorted(abs(x) for x in d.normal) == pytest.approx([0, 0, 1], abs=1e-9)


def test_every_box_kind():
    # The same cube as an oriented box and as a parallelepiped of half axes.
    obox = boxcyl.OrientedBox(center=(0, 0, 0), axes=np.eye(3), extents=(1, 1, 1))
    pbox = boxcyl.Parallelepiped(center=(0, 0, 0), axes=np.eye(3) / 2, extents=(2, 2, 2))
    for box in (obox, pbox):
        expect_overlap(boxcyl.signed_distance(box, DEEP), 0.5, (1, 0, 0), 5)
    # Axes permuting x, y, z (half-extent 3 along x): a cylinder over x in [2.5, 6.5] overlaps by 0.5.
    obox = boxcyl.OrientedBox(center=(0, 0, 0), axes=((0, 1, 0), (0, 0, 1), (1, 0, 0)), extents=(1, 2, 3))
    cyl = boxcyl.Cylinder(center=(4.5, 0, 0), axis=(0, 0, 1), radius=2, height=1)
    expect_overlap(boxcyl.signed_distance(obox, cyl), 0.5, (1, 0, 0), 4.5)
    # A cube of half side 5 with integer axes: its face along u = (3, 4, 0)/5 is 5 from the centre; a
    # segment through 6u = (3.6, 4.8, 0), of radius 2, reaches 4u: 1 deep.
    pbox = boxcyl.Parallelepiped(center=(0, 0, 0), axes=((3, 4, 0), (-4, 3, 0), (0, 0, 5)), extents=(1, 1, 1))
    rod = boxcyl.Cylinder(center=(3.6, 4.8, 0), axis=(0, 0, 1), radius=2, height=4)
    expect_overlap(boxcyl.signed_distance(pbox, rod), 1.0, (0.6, 0.8, 0), 5)


def test_invalid_arguments_raise_value_error():
    with pytest.raises(ValueError, match=r"^cylinder: expected a Cylinder, got AlignedBox"):
        boxcyl.signed_distance(CUBE, CUBE)
    with pytest.raises(ValueError, match=r"^box: expected an AlignedBox, an OrientedBox or a Parallelepiped, got tuple "
                                         r"\(for arrays use signed_distances_aligned"):
        boxcyl.signed_distance(((0, 0, 0), (1, 1, 1)), DEEP)
    with pytest.raises(ValueError, match=r"^cylinder.height: is negative"):
        boxcyl.signed_distance(CUBE, boxcyl.Cylinder(center=(0, 0, 0), axis=(0, 0, 1), radius=1, height=-1))
    with pytest.raises(TypeError):
        boxcyl.signed_distance(CUBE, DEEP, margin=1)  # pylint: disable=unexpected-keyword-arg
    boxes = np.array([[[0, 0, 0], [1, 1, 1]], [[np.nan, 0, 0], [1, 1, 1]], [[2, 0, 0], [1, 1, 1]]])
    with pytest.raises(ValueError, match=r"^boxes\[1\]\.min\[0\]: is NaN"):
        boxcyl.signed_distances_aligned(boxes, DEEP)
    with pytest.raises(ValueError, match=r"^boxes: expected shape \(N, 2, 3\)"):
        boxcyl.signed_distances_aligned(np.zeros((4, 3)), DEEP)
    with pytest.raises(ValueError, match=r"^cylinders\[1\]\.axis: is the zero vector"):
        boxcyl.signed_distances_aligned(CUBE, (np.zeros((2, 3)), np.array([[0, 0, 1], [0, 0, 0]]), 1.0, 1.0))
    with pytest.raises(ValueError, match=r"^threads: expected a non-negative integer"):
        boxcyl.signed_distances_oriented(boxcyl.OrientedBox(center=(0, 0, 0), axes=np.eye(3), extents=(1, 1, 1)), DEEP,
                                         threads=-1)


def expect_scalar(got, boxes, cylinders):
    """Every element exactly as the scalar signed distance gives it (bounds, normal, witness pair)."""
    n = len(boxes)
    assert isinstance(got, boxcyl.SignedDistances)
    assert all(a.dtype == np.float64 for a in got)
    assert got.lower.shape == got.upper.shape == (n,)
    assert got.normal.shape == got.on_box.shape == got.on_cylinder.shape == (n, 3)
    for i in range(n):
        cyl = cylinders[i] if isinstance(cylinders, list) else cylinders
        want = boxcyl.signed_distance(boxes[i], cyl)
        have = (float(got.lower[i]), float(got.upper[i]), tuple(got.normal[i].tolist()), tuple(got.on_box[i].tolist()),
                tuple(got.on_cylinder[i].tolist()))
        assert have == tuple(want), f"element {i}: batch {have}, scalar {want}: ({boxes[i]!r}, {cyl!r})"


CYL = boxcyl.Cylinder(center=(0.5, -0.25, 0), axis=(1, 2, 3), radius=1.5, height=4)


def test_aligned_batch_equals_the_scalar_signed_distance():
    rng = np.random.default_rng(SEED)
    lo = rng.uniform(-4, 4, (40, 3))
    boxes = np.stack([lo, lo + rng.uniform(0, 2, (40, 3))], axis=1)
    objects = [boxcyl.AlignedBox(min=b[0], max=b[1]) for b in boxes]
    got = boxcyl.signed_distances_aligned(boxes, CYL)
    expect_scalar(got, objects, CYL)
    assert np.any(got.upper < 0) and np.any(got.lower > 0)  # both kinds of answer
    for other in (boxcyl.signed_distances_aligned(boxes, CYL, threads=1),
                  boxcyl.signed_distances_aligned((boxes[:, 0], boxes[:, 1]), CYL, threads=3),
                  boxcyl.signed_distances_aligned(objects, CYL)):
        for a, b in zip(other, got):
            assert np.array_equal(a, b)
    cylinders = [boxcyl.Cylinder(center=c, axis=(0, 1, 1), radius=0.5, height=2) for c in rng.uniform(-2, 2, (10, 3))]
    expect_scalar(boxcyl.signed_distances_aligned(boxes[:10], cylinders, threads=2), objects[:10], cylinders)


def test_oriented_and_parallelepiped_batches_equal_the_scalar_signed_distance():
    rng = np.random.default_rng(SEED + 1)
    q, r = np.linalg.qr(rng.normal(size=(20, 3, 3)))
    axes = np.swapaxes(q * np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :], 1, 2).copy()
    center, extents = rng.uniform(-3, 3, (20, 3)), rng.uniform(0, 1.5, (20, 3))
    oriented = [boxcyl.OrientedBox(center=c, axes=a, extents=e) for c, a, e in zip(center, axes, extents)]
    expect_scalar(boxcyl.signed_distances_oriented((center, axes, extents), CYL, threads=2), oriented, CYL)
    p_axes = axes * rng.uniform(0.2, 2, (20, 3, 1))  # any lengths
    parallelepipeds = [boxcyl.Parallelepiped(center=c, axes=a, extents=e) for c, a, e in zip(center, p_axes, extents)]
    expect_scalar(boxcyl.signed_distances_parallelepiped((center, p_axes, extents), CYL), parallelepipeds, CYL)
    expect_scalar(boxcyl.signed_distances_parallelepiped(parallelepipeds[:5], CYL, threads=1), parallelepipeds[:5], CYL)


def test_empty_and_single_batches():
    got = boxcyl.signed_distances_aligned(np.zeros((0, 2, 3)), CYL)
    assert got.lower.shape == (0,) and got.normal.shape == (0, 3) and got.on_box.shape == (0, 3)
    one = boxcyl.signed_distances_aligned(CUBE, DEEP)
    assert one.lower.shape == (1,) and one.normal.shape == (1, 3)
    want = boxcyl.signed_distance(CUBE, DEEP)
    assert (one.lower[0], one.upper[0], tuple(one.normal[0])) == (want.lower, want.upper, want.normal)
