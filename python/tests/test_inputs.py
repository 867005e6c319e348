"""The package's input policy: what is read as numbers, what is refused and how the refusal reads,
what each form of the batch arguments means, and the shapes as values (equality, pickling, repr).

Run from the repository root: PYTHONPATH=<build>/python /usr/bin/python3 -m pytest python/tests
"""
import copy
import datetime
import pickle
import re
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import boxcyl

UNIT = boxcyl.AlignedBox(min=(-1, -1, -1), max=(1, 1, 1))
TOUCHING = boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 5), radius=2, height=1)  # touches x = 1
NS = {"AlignedBox": boxcyl.AlignedBox, "OrientedBox": boxcyl.OrientedBox, "Cylinder": boxcyl.Cylinder}


def raises(message):
    """pytest.raises(ValueError) whose message starts with `message` exactly."""
    return pytest.raises(ValueError, match="^" + re.escape(message))


# --- Numbers: real numbers in, float64 out; everything else refused by name ---------------------------

def test_object_arrays_of_real_numbers_are_read_as_float64():
    third = Fraction(1, 3)
    cyl = boxcyl.Cylinder(center=[Fraction(3), Decimal("0"), 0], axis=np.array([0, 0, Decimal(5)], dtype=object),
                          radius=Fraction(2), height=Decimal("1.0"))
    assert cyl == TOUCHING
    box = boxcyl.AlignedBox(min=(third, 0, 0), max=(1, 1, 1))
    assert box.min[0] == 1 / 3  # rounded to the nearest float64, as float(Fraction) does
    boxes = np.array([[[-1, -1, -1], [1, 1, 1]], [[Fraction(-1), 2, 2], [Decimal(1), 3, 3]]], dtype=object)
    assert boxcyl.intersects_aligned(boxes, TOUCHING).tolist() == [True, False]
    # numpy integer and float dtypes of every width are numbers too
    for dtype in (np.int8, np.int16, np.int64, np.float16, np.float32, np.longdouble):
        assert boxcyl.intersects_aligned(np.array([[-1, -1, -1], [1, 1, 1]], dtype=dtype), TOUCHING).tolist() == [True]
    assert boxcyl.intersects_aligned(np.array([[1, 0, 0], [2, 1, 1]], dtype=np.uint8), TOUCHING).tolist() == [True]


@pytest.mark.parametrize("value, message", [
    (np.array([True, False, True]), "cylinder.center: is an array of booleans (dtype bool); expected real numbers"),
    (np.array([1 + 0j, 0, 0]), "cylinder.center: is an array of complex numbers (dtype complex128)"),
    (np.array(["2026-01-01"] * 3, dtype="datetime64[D]"), "cylinder.center: is an array of datetime64 values"),
    (np.array([1, 2, 3], dtype="timedelta64[s]"), "cylinder.center: is an array of timedelta64 values"),
    (np.array(["1", "2", "3"]), "cylinder.center: is an array of strings (dtype <U1)"),
    (np.array([b"1", b"2", b"3"]), "cylinder.center: is an array of bytes"),
    (np.ma.masked_array([3, 0, 0], mask=[0, 1, 0]), "cylinder.center: is a masked array"),
    (None, "cylinder.center: is None; expected real numbers"),
    ("3, 0, 0", "cylinder.center: is a string (dtype <U7); expected real numbers"),
    ([3, 0, True], "cylinder.center: contains booleans; expected real numbers"),
    ([3, 0, np.bool_(False)], "cylinder.center: contains booleans"),
    ([3, 0, None], "cylinder.center[2]: is None; expected a real number"),
    ([3, 0, "0"], "cylinder.center: is an array of strings"),
    ([3, 0, 1j], "cylinder.center: is an array of complex numbers"),
    (np.array([3, 0, datetime.date(2026, 1, 1)], dtype=object), "cylinder.center[2]: is a date (datetime.date"),
    (np.array([3, 0, True], dtype=object), "cylinder.center[2]: is a bool (True); expected a real number"),
    ([3, [0, 1], 0], "cylinder.center: is not a regular array (nested sequences of different lengths)"),
    ([3, 0], "cylinder.center: expected 3 numbers, got shape (2,)"),
    ([3, 0, 0, 0], "cylinder.center: expected 3 numbers, got shape (4,)"),
    (3, "cylinder.center: expected 3 numbers, got one number"),
    ([10 ** 400, 0, 0], "cylinder.center[0]: is too large for float64"),
])
def test_refused_numbers_name_the_field(value, message):
    with raises(message):
        boxcyl.Cylinder(center=value, axis=(0, 0, 1), radius=1, height=1)


@pytest.mark.parametrize("kwargs, message", [
    ({"radius": True}, "cylinder.radius: is a bool (True); expected a real number"),
    ({"radius": 1j}, "cylinder.radius: is a complex number (dtype complex128)"),
    ({"radius": None}, "cylinder.radius: is None"),
    ({"radius": "1"}, "cylinder.radius: is a string"),
    ({"radius": (1, 2)}, "cylinder.radius: expected one number, got shape (2,)"),
    ({"height": np.float64("nan")}, "cylinder.height: is NaN"),
])
def test_refused_scalars_name_the_field(kwargs, message):
    args = {"center": (0, 0, 0), "axis": (0, 0, 1), "radius": 1, "height": 1}
    args.update(kwargs)
    with raises(message):
        boxcyl.Cylinder(**args)


def test_refusals_in_batches_name_the_argument_and_element():
    with raises("boxes: is an array of booleans"):
        boxcyl.intersects_aligned(np.zeros((4, 2, 3), dtype=bool), TOUCHING)
    with raises("boxes: is an array of complex numbers"):
        boxcyl.intersects_aligned(np.zeros((4, 2, 3), dtype=complex), TOUCHING)
    with raises("boxes.max: is a masked array"):
        boxcyl.intersects_aligned((np.zeros((4, 3)), np.ma.masked_array(np.ones((4, 3)))), TOUCHING)
    boxes = np.zeros((3, 2, 3), dtype=object)
    boxes[2, 1, 0] = "1"
    with raises("boxes[2][1][0]: is a str ('1'); expected a real number"):
        boxcyl.intersects_aligned(boxes, TOUCHING)
    with raises("cylinders.radius: is None"):
        boxcyl.intersects_aligned(UNIT, ((0, 0, 0), (0, 0, 1), None, 1.0))
    with raises("cylinders.height: is an array of datetime64 values"):
        boxcyl.intersects_aligned(UNIT, ((0, 0, 0), (0, 0, 1), 1.0, np.array(["2026-01-01"], dtype="datetime64[D]")))
    with raises("boxes.axes: is an array of booleans"):
        boxcyl.intersects_oriented(((0, 0, 0), np.eye(3, dtype=bool), (1, 1, 1)), TOUCHING)


# --- Wrong kinds of argument: ValueError naming it, never pybind11's TypeError -------------------------

@pytest.mark.parametrize("call, message", [
    (lambda: boxcyl.intersects((UNIT.min, UNIT.max), TOUCHING),
     "box: expected an AlignedBox, an OrientedBox or a Parallelepiped, got tuple (for arrays use "
     "intersects_aligned"),
    (lambda: boxcyl.intersects(UNIT, UNIT), "cylinder: expected a Cylinder, got AlignedBox"),
    (lambda: boxcyl.intersects(UNIT, TOUCHING, algorithm=2), "algorithm: expected a boxcyl.Algorithm or one of"),
    (lambda: boxcyl.intersects(UNIT, TOUCHING, arithmetic=None), "arithmetic: expected a boxcyl.Arithmetic"),
    (lambda: boxcyl.intersects_aligned(UNIT, "cylinder"),
     "cylinders: expected a Cylinder, a list of them, or a tuple (center, axis, radius, height) of arrays; got str"),
    (lambda: boxcyl.intersects_aligned([UNIT, TOUCHING], TOUCHING), "boxes[1]: expected an AlignedBox, got Cylinder"),
    (lambda: boxcyl.intersects_aligned(UNIT, [TOUCHING, UNIT]), "cylinders[1]: expected a Cylinder, got AlignedBox"),
    (lambda: boxcyl.intersects_oriented([UNIT], TOUCHING), "boxes[0]: expected an OrientedBox, got AlignedBox"),
    (lambda: boxcyl.intersects_aligned(UNIT, TOUCHING, threads=-1),
     "threads: expected a non-negative integer (0 or None: all cores); got -1"),
    (lambda: boxcyl.intersects_aligned(UNIT, TOUCHING, threads=True), "threads: expected a non-negative integer"),
    (lambda: boxcyl.intersects_aligned(UNIT, TOUCHING, threads=1.5), "threads: expected a non-negative integer"),
    (lambda: boxcyl.OrientedBox((0, 0, 0), (1, 0, 0), (1, 1, 1)),
     "box.axes: expected 3 vectors of 3 numbers (shape (3, 3)), got shape (3,)"),
    (lambda: boxcyl.AlignedBox((0, 0), (1, 1, 1)), "box.min: expected 3 numbers, got shape (2,)"),
])
def test_wrong_kinds_are_value_errors_naming_the_argument(call, message):
    with raises(message):
        call()


# --- What each batch form means ---------------------------------------------------------------------

def test_a_tuple_of_two_boxes_is_refused_as_ambiguous():
    a = [[-1, -1, -1], [1, 1, 1]]
    b = [[4.5, -1, -1], [6, 1, 1]]
    with raises("boxes: a tuple of two (2, 3) arrays is ambiguous") as e:
        boxcyl.intersects_aligned((a, b), TOUCHING)
    for hint in ("For one box pass (min, max) with two (3,) vectors", "a list or an array of shape (N, 2, 3)",
                 "np.stack((min, max), axis=1)"):
        assert hint in str(e.value)
    # What the message offers answers each reading: two boxes [min, max] ...
    assert boxcyl.intersects_aligned([a, b], TOUCHING).tolist() == [True, True]
    assert boxcyl.intersects_aligned(np.array([a, b]), TOUCHING).tolist() == [True, True]
    # ... or (min, max) arrays of two boxes: [-1, 4.5]×{-1}×{-1} and [1, 6]×{1}×{1}, below and above the
    # cylinder's z range [-0.5, 0.5].
    assert boxcyl.intersects_aligned(np.stack((a, b), axis=1), TOUCHING).tolist() == [False, False]
    # A tuple of two (3,) vectors is one box either way, and is accepted.
    assert boxcyl.intersects_aligned(((-1, -1, -1), (1, 1, 1)), TOUCHING).tolist() == [True]
    # A tuple of two AlignedBox objects is two boxes.
    far = boxcyl.AlignedBox(min=(5, 5, 5), max=(6, 6, 6))
    assert boxcyl.intersects_aligned((UNIT, far), TOUCHING).tolist() == [True, False]
    with raises("boxes: a tuple is (min, max); got a tuple of 3 items (for a sequence of boxes pass a list"):
        boxcyl.intersects_aligned((a, b, a), TOUCHING)


def test_empty_inputs_answer_empty_arrays():
    for boxes in ([], np.zeros((0, 2, 3)), np.zeros(0), (np.zeros((0, 3)), np.zeros((0, 3)))):
        got = boxcyl.intersects_aligned(boxes, TOUCHING)
        assert got.shape == (0,) and got.dtype == np.bool_
    for boxes in ([], (np.zeros((0, 3)), np.zeros((0, 3, 3)), np.zeros((0, 3)))):
        got = boxcyl.intersects_oriented(boxes, TOUCHING)
        assert got.shape == (0,) and got.dtype == np.bool_
    assert boxcyl.intersects_aligned(UNIT, []).shape == (0,)
    assert boxcyl.intersects_aligned([], []).shape == (0,)
    with raises("boxes: a tuple is (min, max); got a tuple of 0 items"):
        boxcyl.intersects_aligned((), TOUCHING)


def test_sequences_of_shape_objects():
    boxes = [UNIT, boxcyl.AlignedBox(min=(1.5, 0, 0), max=(2, 1, 1)), boxcyl.AlignedBox(min=(9, 9, 9), max=(9, 9, 9))]
    cyls = [TOUCHING, TOUCHING, boxcyl.Cylinder(center=(9, 9, 9), axis=(1, 0, 0), radius=0, height=0)]
    assert boxcyl.intersects_aligned(boxes, TOUCHING).tolist() == [True, True, False]
    assert boxcyl.intersects_aligned(boxes, cyls).tolist() == [True, True, True]
    obox = boxcyl.OrientedBox(center=(0, 0, 0), axes=np.eye(3), extents=(1, 1, 1))
    assert boxcyl.intersects_oriented([obox, obox], cyls[1:]).tolist() == [True, False]


def test_float64_arrays_are_read_in_place_whatever_their_strides():
    rng = np.random.default_rng(7)
    lo = rng.uniform(-3, 3, (500, 3))
    boxes = np.stack([lo, lo + rng.uniform(0, 1, (500, 3))], axis=1)
    expected = boxcyl.intersects_aligned(boxes, TOUCHING)
    # Fortran order, a reversed view, a transposed (2, 3, N) array seen through np.moveaxis, every other row.
    assert np.array_equal(boxcyl.intersects_aligned(np.asfortranarray(boxes), TOUCHING), expected)
    assert np.array_equal(boxcyl.intersects_aligned(boxes[::-1], TOUCHING), expected[::-1])
    soa = np.ascontiguousarray(np.moveaxis(boxes, 0, -1))
    assert np.array_equal(boxcyl.intersects_aligned(np.moveaxis(soa, -1, 0), TOUCHING), expected)
    wide = np.repeat(boxes, 2, axis=0)
    assert np.array_equal(boxcyl.intersects_aligned(wide[::2], TOUCHING), expected)
    assert np.array_equal(boxcyl.intersects_aligned((boxes[:, 0], np.asfortranarray(boxes[:, 1])), TOUCHING), expected)
    # A big-endian array is converted, not misread.
    assert np.array_equal(boxcyl.intersects_aligned(boxes.astype(">f8"), TOUCHING), expected)


def test_invalid_element_found_in_any_chunk_and_thread():
    """Batches run in chunks on several threads; the error names the first invalid element all the same."""
    rng = np.random.default_rng(11)
    n = 200_000
    lo = rng.uniform(-3, 3, (n, 3))
    boxes = np.stack([lo, lo + 1], axis=1)
    boxes[150_001, 0, 2] = np.inf
    boxes[190_000, 1, 1] = np.nan
    for threads in (1, 2, 4):
        with raises("boxes[150001].min[2]: is +Inf"):
            boxcyl.intersects_aligned(boxes, TOUCHING, threads=threads)
    boxes[150_001, 0, 2] = boxes[150_001, 1, 2]  # now a flat box: valid
    with raises("boxes[190000].max[1]: is NaN"):
        boxcyl.intersects_aligned(boxes, TOUCHING, threads=3)
    boxes[190_000, 1, 1] = np.nextafter(boxes[190_000, 0, 1], -np.inf)  # a hair below min
    with raises("boxes[190000].max[1]: is less than boxes[190000].min[1]"):
        boxcyl.intersects_aligned(boxes, TOUCHING)
    # Bounds so far apart that max - min overflows are valid (the cheap check leaves them to validate()).
    boxes[190_000] = [[-1.5e308, -1e308, 0], [1.5e308, 1e308, 1]]
    got = boxcyl.intersects_aligned(boxes, TOUCHING)
    assert got[190_000] and got.shape == (n,)


def test_invalid_oriented_element_found_in_any_chunk_and_thread():
    """Oriented boxes are checked by the batch API as it reads them; the error names the first invalid one."""
    rng = np.random.default_rng(13)
    n = 120_000
    center = rng.uniform(-3, 3, (n, 3))
    axes = np.tile(np.eye(3), (n, 1, 1))
    extents = rng.uniform(0, 1, (n, 3))
    expected = boxcyl.intersects_oriented((center, axes, extents), TOUCHING)
    # A strided view of the same boxes (not adjacent in memory) gives the same answers.
    wide = np.repeat(center, 2, axis=0)[::2]
    assert np.array_equal(boxcyl.intersects_oriented((wide, axes, extents), TOUCHING), expected)
    axes[100_003, 2] = (0, 0, 1.001)  # |axes[2]|² = 1.002: not unit length
    extents[110_000, 0] = np.nan
    for threads in (1, 2, 3):
        with raises("boxes[100003].axes[2]: is not unit length"):
            boxcyl.intersects_oriented((center, axes, extents), TOUCHING, threads=threads)
    axes[100_003, 2] = (0, 0, 1 + 1e-5)  # within the tolerance: valid
    with raises("boxes[110000].extents[0]: is NaN"):
        boxcyl.intersects_oriented((center, axes, extents), TOUCHING)
    extents[110_000, 0] = 0.5
    center[0, 1] = -np.inf
    with raises("boxes[0].center[1]: is -Inf"):
        boxcyl.intersects_oriented((center, axes, extents), TOUCHING)


def test_threads_keyword_gives_the_same_answers():
    rng = np.random.default_rng(12)
    n = 150_000
    lo = rng.uniform(-4, 4, (n, 3))
    boxes = np.stack([lo, lo + rng.uniform(0, 1, (n, 3))], axis=1)
    one = boxcyl.intersects_aligned(boxes, TOUCHING, threads=1)
    assert 0.01 < one.mean() < 0.5
    for threads in (2, 3, 8, None):
        assert np.array_equal(boxcyl.intersects_aligned(boxes, TOUCHING, threads=threads), one)
    # The scalar path (per-box cylinders, other options) is threaded too.
    cyls = ([TOUCHING.center] * n, TOUCHING.axis, TOUCHING.radius, TOUCHING.height)
    assert np.array_equal(boxcyl.intersects_aligned(boxes, cyls, threads=3), one)
    assert np.array_equal(boxcyl.intersects_aligned(boxes, TOUCHING, arithmetic="exact", threads=2), one)


# --- Shapes as values ------------------------------------------------------------------------------

SHAPES = [
    boxcyl.AlignedBox(min=(-1, -2.5, 0), max=(1, 1e-300, 0)),
    boxcyl.OrientedBox(center=(1, 2, 3), axes=((0, 1, 0), (0, 0, 1), (1, 0, 0)), extents=(0.25, 0, 4)),
    boxcyl.Cylinder(center=(0.1, -2, 3e-300), axis=(1, 2, 3), radius=0.5, height=7),
    boxcyl.Cylinder(center=(-0.0, 0, 0), axis=(0, 0, -1), radius=0, height=0),
]


@pytest.mark.parametrize("shape", SHAPES, ids=lambda s: type(s).__name__)
def test_shapes_compare_by_value_pickle_and_repr_as_built(shape):
    again = eval(repr(shape), NS)
    assert again == shape and hash(again) == hash(shape) and again is not shape
    assert repr(again) == repr(shape)
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        back = pickle.loads(pickle.dumps(shape, protocol))
        assert back == shape and type(back) is type(shape)
    assert copy.deepcopy(shape) == shape and copy.copy(shape) == shape
    assert shape != UNIT or shape is UNIT
    assert (shape == "a string") is False
    with pytest.raises(AttributeError):
        shape.anything = 1


def test_equality_is_by_value_and_kind():
    assert boxcyl.AlignedBox((0, 0, 0), (1, 1, 1)) == boxcyl.AlignedBox(min=[0.0, 0, 0], max=np.ones(3))
    assert boxcyl.AlignedBox((0, 0, 0), (1, 1, 1)) != boxcyl.AlignedBox((0, 0, 0), (1, 1, 2))
    assert boxcyl.Cylinder((0, 0, 0), (0, 0, 1), 1, 1) != boxcyl.Cylinder((0, 0, 0), (0, 0, 2), 1, 1)  # same solid,
    # different values: equality compares what was given, not the point sets
    assert len({boxcyl.AlignedBox((0, 0, 0), (1, 1, 1)), boxcyl.AlignedBox((0, 0, 0), (1, 1, 1))}) == 1
    assert repr(boxcyl.AlignedBox((0, 0, 0), (1, 1, 1))) == "AlignedBox(min=(0.0, 0.0, 0.0), max=(1.0, 1.0, 1.0))"
    assert repr(SHAPES[1]) == ("OrientedBox(center=(1.0, 2.0, 3.0), axes=((0.0, 1.0, 0.0), (0.0, 0.0, 1.0), "
                               "(1.0, 0.0, 0.0)), extents=(0.25, 0.0, 4.0))")
