"""boxcyl.grid_cells: the cells of a regular grid that a cylinder meets, exactly as C++'s
boxcyl::cells and `boxcyl grid` define them (closed cells with bounds fma(n, cell_size, origin)),
checked against brute force: every cell of the grid built as an AlignedBox and asked with the exact
default query.
"""
import math
import re
from fractions import Fraction

import numpy as np
import pytest

import boxcyl


def raises(message):
    return pytest.raises(ValueError, match="^" + re.escape(message))


def bound(origin, cell_size, n):
    """fma(n, cell_size, origin): n*cell_size + origin rounded once (Fraction → float rounds correctly)."""
    return float(Fraction(n) * Fraction(cell_size) + Fraction(origin))


def brute_force(origin, cell_size, counts, cylinder):
    """Every cell as a closed box, asked one by one (as a batch) with the exact default query."""
    edges = [[bound(origin[a], cell_size[a], n) for n in range(counts[a] + 1)] for a in range(3)]
    index = np.array([(i, j, k) for i in range(counts[0]) for j in range(counts[1]) for k in range(counts[2])],
                     dtype=np.int64).reshape(-1, 3)
    lo = np.array([[edges[a][c[a]] for a in range(3)] for c in index]).reshape(-1, 3)
    hi = np.array([[edges[a][c[a] + 1] for a in range(3)] for c in index]).reshape(-1, 3)
    return index[boxcyl.intersects_aligned((lo, hi), cylinder)]


def random_cylinder(rng):
    axis = rng.normal(size=3)
    if rng.random() < 0.3:
        axis[rng.integers(3)] = 0  # in a coordinate plane
    if rng.random() < 0.2:
        axis = np.eye(3)[rng.integers(3)]  # along a grid axis: faces touch exactly
    return boxcyl.Cylinder(center=rng.uniform(0, 6, 3), axis=axis, radius=rng.choice([0, rng.uniform(0, 2)]),
                           height=rng.choice([0, rng.uniform(0, 5)]))


@pytest.mark.parametrize("seed", range(8))
def test_random_cylinders_against_brute_force(seed):
    rng = np.random.default_rng(20261127 + seed)
    origin = (-0.3, 0.1, -1.0) if seed % 2 else (0.0, 0.0, 0.0)
    cell_size = (0.1, 0.7, 0.3) if seed % 2 else (1.0, 0.5, 0.75)  # 0.1, 0.7, 0.3: bounds that round
    counts = (13, 9, 11) if seed % 2 else (7, 12, 8)
    for _ in range(6):
        cyl = random_cylinder(rng)
        got = boxcyl.grid_cells(origin, cell_size, counts, cyl)
        assert got.dtype == np.int64 and got.ndim == 2 and got.shape[1] == 3
        assert np.array_equal(got, brute_force(origin, cell_size, counts, cyl)), cyl


def test_touching_cells_count_and_the_order_is_lexicographic():
    # The CLI's example: a segment from (0.5, 2, 2) to (1.5, 2, 2) lies in the faces y = 2 and z = 2.
    seg = boxcyl.Cylinder(center=(1, 2, 2), axis=(1, 0, 0), radius=0, height=1)
    got = boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (4, 4, 4), seg)
    assert got.tolist() == [[0, 1, 1], [0, 1, 2], [0, 2, 1], [0, 2, 2], [1, 1, 1], [1, 1, 2], [1, 2, 1], [1, 2, 2]]
    # A cylinder of radius 1 about x = 2, y = 2 touches the cells' faces x = 1, 3 and y = 1, 3 along lines.
    cyl = boxcyl.Cylinder(center=(2, 2, 0.5), axis=(0, 0, 1), radius=1, height=1)
    got = boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (4, 4, 1), cyl)
    assert np.array_equal(got, brute_force((0, 0, 0), (1, 1, 1), (4, 4, 1), cyl))
    cells = got.tolist()  # (0, 1, 0) = [0, 1] x [1, 2] holds the touching point (1, 2); (0, 0, 0) is √2 away
    assert [0, 1, 0] in cells and [3, 2, 0] in cells and [0, 0, 0] not in cells and len(cells) == 12


def test_margin_lists_the_cells_within_it():
    seg = boxcyl.Cylinder(center=(1, 2, 2), axis=(1, 0, 0), radius=0, height=1)
    got = boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (4, 4, 4), seg, margin=0.5)
    assert got.tolist() == [[i, j, k] for i in range(3) for j in (1, 2) for k in (1, 2)]
    # Every cell asked with intersects(margin=...) agrees, at a margin that reaches (1, 1, 1)'s corner
    # region exactly: the cell [0, 1]³'s nearest point (1, 1, 1) is √2 from the segment's line y = z = 2.
    for margin in (0.25, math.sqrt(2), math.nextafter(math.sqrt(2), 0), 1.5):
        got = boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (3, 4, 4), seg, margin=margin)
        want = [[i, j, k] for i in range(3) for j in range(4) for k in range(4)
                if boxcyl.intersects(boxcyl.AlignedBox(min=(i, j, k), max=(i + 1, j + 1, k + 1)), seg, margin=margin)]
        assert got.tolist() == want, margin
    assert np.array_equal(boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (4, 4, 4), seg, margin=0),
                          boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (4, 4, 4), seg))
    with raises("margin: is negative"):
        boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (4, 4, 4), seg, margin=-1)


def test_empty_grids_and_limits():
    cyl = boxcyl.Cylinder(center=(0, 0, 0), axis=(0, 0, 1), radius=1, height=1)
    assert boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (0, 5, 5), cyl).shape == (0, 3)
    assert boxcyl.grid_cells((10, 10, 10), (1, 1, 1), (5, 5, 5), cyl).shape == (0, 3)  # far away
    assert boxcyl.grid_cells((-1, -1, -1), (1, 1, 1), np.array([2, 2, 2]), cyl, max_cells=8).shape == (8, 3)
    with raises("grid_cells: the answer has more than max_cells = 7 cells"):
        boxcyl.grid_cells((-1, -1, -1), (1, 1, 1), (2, 2, 2), cyl, max_cells=7)
    # A huge grid costs what the cells near the cylinder cost, not its size.
    big = boxcyl.grid_cells((-2.0 ** 40, -2.0 ** 40, -2.0 ** 40), (2.0 ** -3,) * 3, (2 ** 44,) * 3, cyl)
    assert len(big) > 1000


@pytest.mark.parametrize("call, message", [
    (lambda c: boxcyl.grid_cells((0, 0, math.nan), (1, 1, 1), (2, 2, 2), c), "grid.origin[2]: is NaN"),
    (lambda c: boxcyl.grid_cells((0, 0, 0), (1, 0, 1), (2, 2, 2), c), "grid.cell_size[1]: is not positive"),
    (lambda c: boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (2, -1, 2), c), "grid.counts[1]: is negative"),
    (lambda c: boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (2, 2, 2 ** 53 + 1), c), "grid.counts[2]: exceeds 2^53"),
    (lambda c: boxcyl.grid_cells((0, 0, 0), (1e300, 1, 1), (2 ** 40, 2, 2), c),
     "grid.counts[0]: makes the far bound origin + counts*cell_size overflow the double range"),
    (lambda c: boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (2, 2.0, 2), c),
     "grid.counts[1]: is a float (2.0); expected an integer"),
    (lambda c: boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (2, True, 2), c), "grid.counts[1]: is a bool (True)"),
    (lambda c: boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (2, 2), c), "grid.counts: expected 3 integers"),
    (lambda c: boxcyl.grid_cells((0, 0), (1, 1, 1), (2, 2, 2), c), "grid.origin: expected 3 numbers, got shape (2,)"),
    (lambda c: boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (2, 2, 2), "c"), "cylinder: expected a Cylinder, got str"),
    (lambda c: boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (2, 2, 2), c, max_cells=-1), "max_cells: expected a non-negative"),
])
def test_bad_grids_are_named(call, message):
    with raises(message):
        call(boxcyl.Cylinder(center=(0, 0, 0), axis=(0, 0, 1), radius=1, height=1))
