"""Tests of the Python package boxcyl: exact answers at touching, the batch forms against the scalar
query and the exact oracle, validation messages, shapes, dtypes, options and threads.

Run from the repository root: PYTHONPATH=<build>/python /usr/bin/python3 -m pytest python/tests
(CTest does this: ctest -L python), or after `pip install` with the venv's python.
"""
import doctest
import math
import re
import threading
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import boxcyl

SEED = 20261121  # fixed; failures print the case


def unit_box():
    return boxcyl.AlignedBox(min=(-1, -1, -1), max=(1, 1, 1))


def side_cylinder(x):
    """Axis parallel to z at (x, 0), radius 2: it touches the face x = 1 exactly when x == 3."""
    return boxcyl.Cylinder(center=(x, 0, 0), axis=(0, 0, 5), radius=2, height=1)


# --- The scalar query -------------------------------------------------------------------------------

def test_touching_counts_and_one_ulp_away_does_not():
    assert boxcyl.intersects(unit_box(), side_cylinder(3.0)) is True
    assert boxcyl.intersects(unit_box(), side_cylinder(math.nextafter(3.0, 4.0))) is False
    assert boxcyl.intersects(unit_box(), side_cylinder(math.nextafter(3.0, 2.0))) is True


def test_margin_is_the_exact_clearance_query():
    # The box's corner (6, 0, 5) is exactly 5 from the rim point (3, 0, 1) of this cylinder.
    box = boxcyl.AlignedBox(min=(6, 0, 5), max=(7, 1, 6))
    cyl = boxcyl.Cylinder(center=(0, 0, 0), axis=(0, 0, 1), radius=3, height=2)
    assert boxcyl.intersects(box, cyl, margin=5)
    assert not boxcyl.intersects(box, cyl, margin=math.nextafter(5.0, 0.0))
    assert not boxcyl.intersects(box, cyl, margin=0)
    assert boxcyl.intersects(box, cyl, margin=np.float32(5))
    assert boxcyl.intersects(box, cyl, margin=5, arithmetic="float64")  # always exact
    oriented = boxcyl.OrientedBox(center=(6.5, 0.5, 5.5), axes=np.eye(3), extents=(0.5, 0.5, 0.5))
    assert boxcyl.intersects(oriented, cyl, margin=5)
    with pytest.raises(ValueError, match="margin: is negative"):
        boxcyl.intersects(box, cyl, margin=-1)
    with pytest.raises(ValueError, match="margin"):
        boxcyl.intersects(box, cyl, margin=float("nan"))
    with pytest.raises(ValueError, match="margin"):
        boxcyl.intersects(box, cyl, margin="5")


def test_touching_the_end_disk():
    # Axis along x, end disk at x = 1 + 0 exactly: center 1 + h/2 with h = 2.
    cyl = boxcyl.Cylinder(center=(2, 0.5, -0.25), axis=(7, 0, 0), radius=0.5, height=2)
    assert boxcyl.intersects(unit_box(), cyl)
    far = boxcyl.Cylinder(center=(math.nextafter(2.0, 3.0), 0.5, -0.25), axis=(7, 0, 0), radius=0.5, height=2)
    assert not boxcyl.intersects(unit_box(), far)


def test_oriented_box_rotated_45_degrees():
    s = math.sqrt(0.5)  # rounded: the axes are orthonormal to ~1e-16, and taken exactly as given
    box = boxcyl.OrientedBox(center=(0, 0, 0), axes=((s, s, 0), (-s, s, 0), (0, 0, 1)), extents=(1, 1, 1))
    # The box's corner along +x is at distance 2s·1 ≈ 1.414 from the centre.
    near = boxcyl.Cylinder(center=(1.9, 0, 0), axis=(0, 0, 1), radius=0.5, height=1)
    far = boxcyl.Cylinder(center=(1.95, 0, 0), axis=(0, 0, 1), radius=0.5, height=1)
    assert boxcyl.intersects(box, near)
    assert not boxcyl.intersects(box, far)
    for cyl in (near, far):
        assert boxcyl.intersects(box, cyl) == boxcyl.intersects(box, cyl, algorithm="oracle")


def test_options_by_enum_and_by_name():
    box, cyl = unit_box(), side_cylinder(3.0)
    for algorithm in boxcyl.Algorithm.__members__:
        for arithmetic in ("exact", "filtered"):
            assert boxcyl.intersects(box, cyl, algorithm=algorithm, arithmetic=arithmetic), (algorithm, arithmetic)
    assert boxcyl.intersects(box, cyl, algorithm=boxcyl.Algorithm.hull, arithmetic=boxcyl.Arithmetic.float64)
    with pytest.raises(ValueError, match="algorithm: 'simplex' is not one of"):
        boxcyl.intersects(box, cyl, algorithm="simplex")


def test_objects_are_immutable_and_repr_round_trips():
    cyl = boxcyl.Cylinder(center=(0.1, -2, 3e-300), axis=(1, 2, 3), radius=0.5, height=7)
    assert cyl.center == (0.1, -2.0, 3e-300) and cyl.axis == (1.0, 2.0, 3.0)
    assert (cyl.radius, cyl.height) == (0.5, 7.0)
    with pytest.raises(AttributeError):
        cyl.radius = 1.0
    ns = {k: getattr(boxcyl, k) for k in ("Cylinder", "AlignedBox", "OrientedBox")}
    again = eval(repr(cyl), ns)
    assert (again.center, again.axis, again.radius, again.height) == (cyl.center, cyl.axis, cyl.radius, cyl.height)
    box = boxcyl.OrientedBox(center=(1, 2, 3), axes=((0, 1, 0), (0, 0, 1), (1, 0, 0)), extents=(0.25, 0, 4))
    again = eval(repr(box), ns)
    assert (again.center, again.axes, again.extents) == (box.center, box.axes, box.extents)
    assert eval(repr(unit_box()), ns).max == (1.0, 1.0, 1.0)


def test_module_docstring_example_and_version():
    assert doctest.testmod(boxcyl, raise_on_error=True).attempted >= 2
    header = (Path(__file__).resolve().parents[2] / "include" / "boxcyl" / "version.hpp").read_text()
    assert boxcyl.__version__ == re.search(r'BOXCYL_VERSION_STRING "([^"]+)"', header).group(1)


# --- Validation ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("make, message", [
    (lambda: boxcyl.Cylinder((0, 0, 0), (0, 0, 0), 1, 1), "cylinder.axis: is the zero vector"),
    (lambda: boxcyl.Cylinder((0, 0, 0), (0, 0, 1), -1, 1), "cylinder.radius: is negative"),
    (lambda: boxcyl.Cylinder((0, math.nan, 0), (0, 0, 1), 1, 1), "cylinder.center[1]: is NaN"),
    (lambda: boxcyl.Cylinder((0, 0, 0), (0, 0, 1), 1, math.inf), "cylinder.height: is +Inf"),
    (lambda: boxcyl.AlignedBox((0, 0, 0), (1, -1, 1)), "box.max[1]: is less than box.min[1]"),
    (lambda: boxcyl.OrientedBox((0, 0, 0), ((2, 0, 0), (0, 1, 0), (0, 0, 1)), (1, 1, 1)),
     "box.axes[0]: is not unit length"),
    (lambda: boxcyl.OrientedBox((0, 0, 0), ((1, 0, 0), (0, 1, 0), (0, 0, 1)), (1, -0.5, 1)),
     "box.extents[1]: is negative"),
])
def test_objects_are_validated_when_built(make, message):
    with pytest.raises(ValueError) as e:
        make()
    assert str(e.value).startswith(message)


def test_batch_names_the_first_invalid_element():
    rng = np.random.default_rng(SEED)
    boxes = np.sort(rng.uniform(-1, 1, (40, 2, 3)), axis=1)
    boxes[17, 1, 0] = boxes[17, 0, 0] - 0.5
    boxes[30, 0, 2] = np.nan  # a later error is not the one reported
    with pytest.raises(ValueError, match=re.escape("boxes[17].max[0]: is less than boxes[17].min[0]")):
        boxcyl.intersects_aligned(boxes, side_cylinder(3.0))

    n = 8
    center, axis = rng.uniform(-1, 1, (n, 3)), rng.uniform(-1, 1, (n, 3))
    radius, height = np.full(n, 0.5), np.ones(n)
    radius[3] = -0.0  # negative zero is zero: valid
    radius[5] = -1e-300
    with pytest.raises(ValueError, match=re.escape("cylinders[5].radius: is negative")):
        boxcyl.intersects_aligned(unit_box(), (center, axis, radius, height))
    axis[2] = 0
    with pytest.raises(ValueError, match=re.escape("cylinders[2].axis: is the zero vector")):
        boxcyl.intersects_aligned(unit_box(), (center, axis, radius, height))
    # A field given once is checked under the element index where it is first used.
    with pytest.raises(ValueError, match=re.escape("cylinders[0].height: is NaN")):
        boxcyl.intersects_aligned(unit_box(), (center, (0, 0, 1), 0.5, np.nan))
    # Arrays given without a leading length describe one box, named as such.
    with pytest.raises(ValueError, match=re.escape("box.min[2]: is -Inf")):
        boxcyl.intersects_aligned([[0, 0, -np.inf], [1, 1, 1]], side_cylinder(3.0))


def test_oriented_batch_validation():
    axes = np.tile(np.eye(3), (4, 1, 1))
    axes[2, 1] = (0, 1, 1e-3)  # |axes[1]|² = 1 + 1e-6 is fine; axes[1]·axes[2] = 1e-3 is not
    with pytest.raises(ValueError, match=re.escape("boxes[2].axes: are not orthogonal (axes[1]·axes[2]")):
        boxcyl.intersects_oriented((np.zeros((4, 3)), axes, np.ones((4, 3))), side_cylinder(3.0))


def test_shape_errors():
    cyl = side_cylinder(3.0)
    with pytest.raises(ValueError, match=re.escape(r"boxes: expected shape (N, 2, 3) or (2, 3), got (5, 3, 3)")):
        boxcyl.intersects_aligned(np.zeros((5, 3, 3)), cyl)
    with pytest.raises(ValueError, match=re.escape("cylinders.radius: expected shape (N) or (), got (4, 1)")):
        boxcyl.intersects_aligned(unit_box(), (np.zeros((4, 3)), (0, 0, 1), np.ones((4, 1)), 1.0))
    with pytest.raises(ValueError, match=re.escape("leading lengths [4, 5] differ")):
        boxcyl.intersects_aligned((np.zeros((5, 3)), np.ones((5, 3))), (np.zeros((4, 3)), (0, 0, 1), 1.0, 1.0))
    with pytest.raises(ValueError, match=re.escape("cylinders: expected a tuple of 4 arrays (center, axis, radius, "
                                                   "height), got 3")):
        boxcyl.intersects_aligned(unit_box(), ((0, 0, 0), (0, 0, 1), 1.0))
    with pytest.raises(ValueError, match=re.escape("boxes: expected an OrientedBox, a list of them, or a tuple")):
        boxcyl.intersects_oriented(np.zeros((3, 3)), cyl)


# --- The batch forms agree with the scalar query and with the exact oracle ----------------------------

def random_aligned(rng, n):
    """Boxes and cylinders at mixed scales (2^-20..2^20), some boxes flat, cylinders around the box.
    Half of them are then placed near touching: axis ∥ z, centre at x = fl(max.x + radius) nudged by
    -1, 0 or +1 ulp, y and z inside the box. Those intersect exactly when centre.x − max.x ≤ radius,
    decided here in rationals (fractions), independently of boxcyl. Returns boxes, cylinders, the
    near-touching mask and their exact answers."""
    scale = 2.0 ** rng.integers(-20, 21, n)
    lo = rng.uniform(-1, 1, (n, 3)) * scale[:, None]
    hi = lo + rng.uniform(0, 2, (n, 3)) * scale[:, None]
    flat = rng.random(n) < 0.1
    hi[flat, 2] = lo[flat, 2]
    center = lo + rng.uniform(-0.5, 2.5, (n, 3)) * scale[:, None]
    axis = rng.normal(size=(n, 3))
    radius = rng.uniform(0, 1.5, n) * scale
    height = rng.uniform(0, 3, n) * scale

    near = rng.random(n) < 0.5
    x = hi[:, 0] + radius
    nudge = rng.integers(-1, 2, n)
    x = np.where(nudge > 0, np.nextafter(x, np.inf), np.where(nudge < 0, np.nextafter(x, -np.inf), x))
    center[near, 0] = x[near]
    center[near, 1:] = lo[near, 1:] + (hi[near, 1:] - lo[near, 1:]) * rng.uniform(0, 1, (near.sum(), 2))
    axis[near] = (0, 0, 1)
    expected = np.array([Fraction(center[i, 0]) - Fraction(hi[i, 0]) <= Fraction(radius[i]) for i in range(n)])
    return (lo, hi), (center, axis, radius, height), near, expected


def case(boxes, cyls, i):
    return (f"AlignedBox(min={tuple(boxes[0][i].tolist())!r}, max={tuple(boxes[1][i].tolist())!r}), "
            f"Cylinder(center={tuple(cyls[0][i].tolist())!r}, axis={tuple(cyls[1][i].tolist())!r}, "
            f"radius={cyls[2][i]!r}, height={cyls[3][i]!r})")


def test_aligned_batch_matches_scalar_and_oracle():
    rng = np.random.default_rng(SEED)
    boxes, cyls, near, expected = random_aligned(rng, 3000)
    got = boxcyl.intersects_aligned(boxes, cyls)
    assert got.dtype == np.bool_ and got.shape == (3000,)
    bad = np.flatnonzero(near & (got != expected))
    assert bad.size == 0, "seed %d, wrong near-touching answer: %s" % (SEED, case(boxes, cyls, bad[0]))
    oracle = boxcyl.intersects_aligned(boxes, cyls, algorithm="oracle")
    bad = np.flatnonzero(got != oracle)
    assert bad.size == 0, "seed %d, disagrees with the oracle: %s" % (SEED, case(boxes, cyls, bad[0]))
    # Both answers are common in both groups (the generator is representative).
    assert 0.4 < expected[near].mean() < 0.9 and 0.2 < got[~near].mean() < 0.8
    for i in range(0, 3000, 7):
        box = boxcyl.AlignedBox(boxes[0][i], boxes[1][i])
        cyl = boxcyl.Cylinder(cyls[0][i], cyls[1][i], cyls[2][i], cyls[3][i])
        assert boxcyl.intersects(box, cyl) == got[i], case(boxes, cyls, i)
    # The (N, 2, 3) form and a list of [min, max] pairs are the same boxes.
    stacked = np.stack(boxes, axis=1)
    assert np.array_equal(boxcyl.intersects_aligned(stacked, cyls), got)
    assert np.array_equal(boxcyl.intersects_aligned(stacked[:50].tolist(), tuple(c[:50] for c in cyls)), got[:50])


def test_oriented_batch_matches_scalar_and_oracle():
    rng = np.random.default_rng(SEED + 1)
    n = 400
    # Random rotations (QR of a Gaussian matrix), rounded to double: orthonormal to ~1e-16 only.
    q, r = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    axes = q * np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :]
    axes = np.swapaxes(axes, 1, 2).copy()  # rows are the box axes
    axes[:40] = np.eye(3)[rng.permutation(3)]  # some exactly orthonormal frames
    center = rng.uniform(-1, 1, (n, 3))
    extents = rng.uniform(0, 1, (n, 3))
    cyls = (center + rng.uniform(-1.8, 1.8, (n, 3)), rng.normal(size=(n, 3)), rng.uniform(0, 1, n),
            rng.uniform(0, 2, n))
    got = boxcyl.intersects_oriented((center, axes, extents), cyls)
    oracle = boxcyl.intersects_oriented((center, axes, extents), cyls, algorithm="oracle")
    hull = boxcyl.intersects_oriented((center, axes, extents), cyls, algorithm="hull", arithmetic="exact")
    assert np.array_equal(got, oracle) and np.array_equal(hull, oracle)
    assert 0.2 < got.mean() < 0.8
    for i in range(0, n, 5):
        box = boxcyl.OrientedBox(center[i], axes[i], extents[i])
        cyl = boxcyl.Cylinder(*(c[i] for c in cyls))
        assert boxcyl.intersects(box, cyl) == got[i], (repr(box), repr(cyl))
    # One box against many cylinders, given as an object and as arrays without a leading length.
    box = boxcyl.OrientedBox(center[7], axes[7], extents[7])
    one = boxcyl.intersects_oriented(box, cyls)
    assert np.array_equal(one, boxcyl.intersects_oriented((center[7], axes[7], extents[7]), cyls))
    assert all(one[i] == boxcyl.intersects(box, boxcyl.Cylinder(*(c[i] for c in cyls))) for i in range(0, n, 9))


def test_exact_lcp_refuses_a_rounded_frame_naming_the_box():
    s = math.sqrt(0.5)
    axes = np.array([[[1, 0, 0], [0, 1, 0], [0, 0, 1]], [[s, s, 0], [-s, s, 0], [0, 0, 1]]], dtype=float)
    with pytest.raises(ValueError, match=re.escape("boxes[1]: ")):
        boxcyl.intersects_oriented((np.zeros((2, 3)), axes, np.ones((2, 3))), side_cylinder(3.0),
                                   algorithm="lcp", arithmetic="exact")


def test_broadcasting_dtypes_and_layouts():
    cyl = side_cylinder(3.0)
    lo = np.array([[-1, -1, -1], [-1, -1, -1], [-1, -1, -1]], dtype=np.int32)
    hi = np.array([[1, 1, 1], [0.5, 1, 1], [np.nextafter(np.float32(1), np.float32(0)), 1, 1]], dtype=np.float32)
    expected = [True, False, False]
    assert boxcyl.intersects_aligned((lo, hi), cyl).tolist() == expected
    # Non-contiguous views (every other row of a larger array) give the same answers.
    wide = np.zeros((6, 2, 3))
    wide[::2, 0], wide[::2, 1] = lo, hi
    assert boxcyl.intersects_aligned(wide[::2], cyl).tolist() == expected
    # One box, many cylinders; radius and height given once.
    xs = np.array([2.5, 3.0, np.nextafter(3.0, 4.0)])
    centers = np.column_stack([xs, np.zeros(3), np.zeros(3)])
    assert boxcyl.intersects_aligned(unit_box(), (centers, (0, 0, 5), 2, 1)).tolist() == [True, True, False]
    empty = boxcyl.intersects_aligned(np.zeros((0, 2, 3)), cyl)
    assert empty.shape == (0,) and empty.dtype == np.bool_


def test_threads_share_the_module_safely():
    rng = np.random.default_rng(SEED + 2)
    boxes, cyls, _, _ = random_aligned(rng, 2000)
    expected = boxcyl.intersects_aligned(boxes, cyls)
    results = [None] * 4

    def work(k):
        results[k] = boxcyl.intersects_aligned(boxes, cyls)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(r, expected) for r in results)


def test_large_batches_on_threads_equal_the_scalar_path():
    """Batches long enough for the runner thread and the library's threads (threads=0: all cores, as
    the CLI's --threads 0): each layout of aligned boxes (rows read in place, a (min, max) tuple and a
    strided view gathered in chunks), oriented boxes and parallelepipeds against one cylinder (the
    batch API) give the answers of the per-element path (the same cylinder repeated per box)."""
    rng = np.random.default_rng(SEED + 7)
    n = 140_000
    cyl = boxcyl.Cylinder(center=(0.25, -0.5, 1.0), axis=(1.0, 2.0, -0.5), radius=1.5, height=4.0)
    per_box = (np.tile(cyl.center, (n, 1)), cyl.axis, cyl.radius, cyl.height)
    lo = rng.uniform(-4, 4, size=(n, 3))
    aligned = np.stack([lo, lo + rng.uniform(0, 1.5, size=(n, 3))], axis=1)
    expected = boxcyl.intersects_aligned(aligned, per_box, threads=1)
    assert 0.05 < expected.mean() < 0.9
    wide = np.zeros((2 * n, 2, 3))
    wide[::2] = aligned
    for threads in (0, 1, 2, None):
        assert np.array_equal(boxcyl.intersects_aligned(aligned, cyl, threads=threads), expected)
        assert np.array_equal(boxcyl.intersects_aligned((aligned[:, 0], aligned[:, 1]), cyl, threads=threads),
                              expected)
        assert np.array_equal(boxcyl.intersects_aligned(wide[::2], cyl, threads=threads), expected)
        assert np.array_equal(boxcyl.intersects_aligned(aligned, per_box, threads=threads), expected)
    frames = (rng.uniform(-4, 4, size=(n, 3)), _random_rotations(rng, n), rng.uniform(0, 1.0, size=(n, 3)))
    oriented = boxcyl.intersects_oriented(frames, per_box, threads=1)
    skewed = (frames[0], frames[1] * rng.uniform(0.5, 2, size=(n, 3, 1)), frames[2])
    parallelepipeds = boxcyl.intersects_parallelepiped(skewed, per_box, threads=1)
    for threads in (0, 2):
        assert np.array_equal(boxcyl.intersects_oriented(frames, cyl, threads=threads), oriented)
        assert np.array_equal(boxcyl.intersects_parallelepiped(skewed, cyl, threads=threads), parallelepipeds)
    # The first invalid box by index is named, whichever thread finds it.
    aligned[100_003, 1, 2] = np.nan
    aligned[120_000, 0, 0] = np.inf
    for threads in (0, 1, 2):
        with pytest.raises(ValueError, match=re.escape("boxes[100003].max[2]: is NaN")):
            boxcyl.intersects_aligned(aligned, cyl, threads=threads)
        with pytest.raises(ValueError, match=re.escape("boxes[100003].max[2]: is NaN")):
            boxcyl.intersects_aligned((aligned[:, 0], aligned[:, 1]), cyl, threads=threads)


def test_readme_examples_run():
    """python/README.md's examples, in order, in one scope (later ones use earlier names)."""
    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert len(blocks) == 3
    scope = {}
    for block in blocks:
        exec(compile(block, "python/README.md", "exec"), scope)
    assert scope["hits"].dtype == np.bool_ and scope["hits"].shape == (100_000,)
    original = scope["boxes"][::10].compute()  # the Dask example repeats each box ten times
    assert scope["count"] == 10 * boxcyl.intersects_aligned(original, scope["cyl"]).sum() > 0


def _random_rotations(rng, n):
    """Rotation matrices (rows = box axes, rounded to float64) from random unit quaternions."""
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    w, x, y, z = q.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)], axis=1),
        np.stack([2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)], axis=1),
        np.stack([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)], axis=1),
    ], axis=1)


def test_one_cylinder_batch_equals_scalar():
    """One cylinder against 3000 boxes goes through the C++ batch API (SIMD filter, threads); the
    answers must equal the scalar loop's (the same cylinder repeated per box) and the scalar query's."""
    rng = np.random.default_rng(SEED + 5)
    n = 3000
    cyl = boxcyl.Cylinder(center=(0.25, -0.5, 1.0), axis=(1.0, 2.0, -0.5), radius=1.5, height=4.0)
    per_box = (np.tile(cyl.center, (n, 1)), np.tile(cyl.axis, (n, 1)), np.full(n, cyl.radius), np.full(n, cyl.height))
    lo = rng.uniform(-4, 4, size=(n, 3))
    size = rng.uniform(0, 1.5, size=(n, 3)) * (rng.uniform(size=(n, 3)) > 0.1)  # 10% flat sides
    aligned = np.stack([lo, lo + size], axis=1)
    batch = boxcyl.intersects_aligned(aligned, cyl)
    assert 0.1 < batch.mean() < 0.9, "the set should mix hits and misses"
    assert np.array_equal(batch, boxcyl.intersects_aligned(aligned, per_box))
    for i in range(0, n, 97):
        box = boxcyl.AlignedBox(min=aligned[i, 0], max=aligned[i, 1])
        assert batch[i] == boxcyl.intersects(box, cyl), (i, box, cyl)

    centers = rng.uniform(-4, 4, size=(n, 3))
    axes = _random_rotations(rng, n)
    extents = rng.uniform(0, 1.0, size=(n, 3))
    obatch = boxcyl.intersects_oriented((centers, axes, extents), cyl)
    assert 0.1 < obatch.mean() < 0.9
    assert np.array_equal(obatch, boxcyl.intersects_oriented((centers, axes, extents), per_box))
    for i in range(0, n, 97):
        box = boxcyl.OrientedBox(center=centers[i], axes=axes[i], extents=extents[i])
        assert obatch[i] == boxcyl.intersects(box, cyl), (i, box, cyl)


def test_the_package_exports_only_its_api():
    """Module imports are private (numpy as _np, ...): the public names are __all__ (and submodules)."""
    assert not any(hasattr(boxcyl, name) for name in ("np", "numbers", "decimal"))
    public = {name for name in dir(boxcyl) if not name.startswith("_")} - {"dask"}
    assert public == set(boxcyl.__all__) - {"__version__"}


def test_equality_hash_and_pickling_by_value_for_every_shape():
    import pickle

    shapes = [unit_box(), boxcyl.OrientedBox(center=(1, 2, 3), axes=np.eye(3), extents=(1, 2, 3)),
              boxcyl.Parallelepiped(center=(1, 2, 3), axes=np.eye(3), extents=(1, 2, 3)),
              boxcyl.Cylinder(center=(1, 2, 3), axis=(0, 0, 2), radius=1, height=2)]
    for shape in shapes:
        again = pickle.loads(pickle.dumps(shape))
        assert type(again) is type(shape) and again == shape and hash(again) == hash(shape)
        assert eval(repr(shape), vars(boxcyl)) == shape
    # Same fields, another kind: not equal (an OrientedBox is no Parallelepiped), hashes apart.
    assert shapes[1] != shapes[2] and len({hash(s) for s in shapes}) == 4
    assert (shapes[0] == (unit_box().min, unit_box().max)) is False

    class Named(boxcyl.AlignedBox):  # a user's subclass compares and pickles as the box it is
        __slots__ = ()

    assert Named(min=(-1, -1, -1), max=(1, 1, 1)) == unit_box()
    assert pickle.loads(pickle.dumps(Named(min=(-1, -1, -1), max=(1, 1, 1)))) == unit_box()
