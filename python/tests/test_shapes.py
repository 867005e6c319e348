"""Parallelepipeds (any three axes) and the named constructors from poses and sizes: each convention
checked on a case where the other reading of the same numbers changes the answer.

Run from the repository root: PYTHONPATH=<build>/python /usr/bin/python3 -m pytest python/tests
"""
import math
import pickle
import re

import numpy as np
import pytest

import boxcyl

C30, S30 = math.cos(math.pi / 6), math.sin(math.pi / 6)
R30 = np.array([[C30, -S30, 0], [S30, C30, 0], [0, 0, 1]])  # 30° about z; columns are the local axes
Y_LOCAL = R30[:, 1]  # where the local y axis points in the world: (-sin 30°, cos 30°, 0)


def dot(cyl_at, radius=0.5):
    """A short vertical cylinder (a disk-like probe) centred at `cyl_at`."""
    return boxcyl.Cylinder(center=tuple(cyl_at), axis=(0, 0, 1), radius=radius, height=0.5)


def raises(message):
    return pytest.raises(ValueError, match="^" + re.escape(message))


# --- Parallelepiped ----------------------------------------------------------------------------------

def test_parallelepiped_with_integer_vertices_touches_exactly():
    # Axes (3,4,0), (-4,3,0), (0,0,5): orthogonal, length 5, not unit: an OrientedBox refuses them.
    axes = ((3, 4, 0), (-4, 3, 0), (0, 0, 5))
    p = boxcyl.Parallelepiped(center=(0, 0, 0), axes=axes, extents=(1, 1, 1))
    with raises("box.axes[0]: is not unit length"):
        boxcyl.OrientedBox(center=(0, 0, 0), axes=axes, extents=(1, 1, 1))
    # The vertex (3,4,0) + (4,-3,0) = (7,1,0) is at distance exactly 1 from (8,1,z).
    assert boxcyl.intersects(p, boxcyl.Cylinder(center=(8, 1, 0), axis=(0, 0, 1), radius=1, height=1))
    assert not boxcyl.intersects(p, boxcyl.Cylinder(center=(math.nextafter(8, 9), 1, 0), axis=(0, 0, 1), radius=1,
                                                    height=1))
    for algorithm in ("oracle", "hull"):
        assert boxcyl.intersects(p, boxcyl.Cylinder(center=(8, 1, 0), axis=(0, 0, 1), radius=1, height=1),
                                 algorithm=algorithm)


def test_flat_parallelepipeds_and_values():
    flat = boxcyl.Parallelepiped(center=(0, 0, 0), axes=((1, 0, 0), (2, 0, 0), (0, 0, 0)), extents=(1, 1, 1))
    assert boxcyl.intersects(flat, boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 1), radius=0, height=0))  # end (3,0,0)
    assert not boxcyl.intersects(flat, boxcyl.Cylinder(center=(3, 1e-300, 0), axis=(0, 0, 1), radius=0, height=0))
    again = eval(repr(flat), {"Parallelepiped": boxcyl.Parallelepiped})
    assert again == flat and pickle.loads(pickle.dumps(flat)) == flat and hash(again) == hash(flat)
    assert flat != boxcyl.OrientedBox(center=(0, 0, 0), axes=np.eye(3), extents=(1, 1, 1))
    with raises("box.extents[2]: is negative"):
        boxcyl.Parallelepiped(center=(0, 0, 0), axes=np.eye(3), extents=(1, 1, -1))
    with raises("box.axes[1][0]: is NaN"):
        boxcyl.Parallelepiped(center=(0, 0, 0), axes=((1, 0, 0), (math.nan, 0, 0), (0, 0, 1)), extents=(1, 1, 1))


def test_parallelepiped_batch_matches_scalar_and_oracle():
    rng = np.random.default_rng(23)
    n = 600
    center = rng.uniform(-2, 2, (n, 3))
    axes = rng.normal(size=(n, 3, 3))  # any axes: skewed, of any length
    extents = rng.uniform(0, 1, (n, 3))
    cyl = boxcyl.Cylinder(center=(0.5, 0, 0), axis=(1, 1, 0), radius=0.7, height=3)
    got = boxcyl.intersects_parallelepiped((center, axes, extents), cyl, threads=2)
    assert 0.1 < got.mean() < 0.9
    assert np.array_equal(got, boxcyl.intersects_parallelepiped((center, axes, extents), cyl, algorithm="oracle"))
    for i in range(0, n, 37):
        p = boxcyl.Parallelepiped(center[i], axes[i], extents[i])
        assert boxcyl.intersects(p, cyl) == got[i], repr(p)
    objs = [boxcyl.Parallelepiped(center[i], axes[i], extents[i]) for i in range(5)]
    assert boxcyl.intersects_parallelepiped(objs, cyl).tolist() == got[:5].tolist()
    extents[444, 1] = -1
    with raises("boxes[444].extents[1]: is negative"):
        boxcyl.intersects_parallelepiped((center, axes, extents), cyl)


# --- Poses and sizes, each against the other reading of the same numbers ---------------------------

def test_rotation_matrix_columns_are_the_axes():
    """FCL/Coal, Eigen, scipy as_matrix(), MuJoCo xmat: x_world = R x_local. Reading R's rows as the
    axes (OrientedBox's own `axes`) is the inverse rotation."""
    box = boxcyl.OrientedBox.from_rotation((0, 0, 0), R30, size=(2, 8, 2))  # long along local y
    probe = dot(3.5 * Y_LOCAL, radius=0.1)
    assert boxcyl.intersects(box, probe)
    assert box.axes[1] == tuple(R30[:, 1])
    mistaken = boxcyl.OrientedBox(center=(0, 0, 0), axes=R30, extents=(1, 4, 1))  # rows as axes
    assert not boxcyl.intersects(mistaken, probe)


def test_size_is_full_and_half_extents_half():
    """FCL/Coal Box(x, y, z) and trimesh extents are full side lengths; MuJoCo, Bullet, Jolt halves."""
    probe = dot(5 * Y_LOCAL)  # reaches 4.5 along local y
    assert not boxcyl.intersects(boxcyl.OrientedBox.from_rotation((0, 0, 0), R30, size=(2, 8, 2)), probe)
    assert boxcyl.intersects(boxcyl.OrientedBox.from_rotation((0, 0, 0), R30, half_extents=(2, 8, 2)), probe)
    assert boxcyl.OrientedBox.from_rotation((0, 0, 0), R30, size=(2, 8, 2)).extents == (1.0, 4.0, 1.0)
    with raises("box: give exactly one of half_extents= or size="):
        boxcyl.OrientedBox.from_rotation((0, 0, 0), R30)
    with raises("box: give exactly one of half_extents= or size="):
        boxcyl.OrientedBox.from_rotation((0, 0, 0), R30, size=(1, 1, 1), half_extents=(1, 1, 1))


def test_quaternion_order_is_named():
    """scipy as_quat(), Bullet, Jolt: (x, y, z, w); MuJoCo, trimesh, Eigen's constructor: (w, x, y, z)."""
    s, c = math.sin(math.pi / 12), math.cos(math.pi / 12)  # 30° about z
    from_xyzw = boxcyl.OrientedBox.from_quaternion((0, 0, 0), xyzw=(0, 0, s, c), size=(2, 8, 2))
    from_wxyz = boxcyl.OrientedBox.from_quaternion((0, 0, 0), wxyz=(c, 0, 0, s), size=(2, 8, 2))
    assert from_xyzw == from_wxyz
    assert np.allclose(from_xyzw.axes, R30.T, atol=1e-15)  # axes (rows) are R's columns
    probe = dot(3.5 * Y_LOCAL, radius=0.1)
    assert boxcyl.intersects(from_xyzw, probe)
    # (x, y, z, w) read as (w, x, y, z): a rotation of about 180° about a tilted axis.
    mistaken = boxcyl.OrientedBox.from_quaternion((0, 0, 0), wxyz=(0, 0, s, c), size=(2, 8, 2))
    assert not boxcyl.intersects(mistaken, probe)
    with raises("quaternion: give exactly one of wxyz= or xyzw="):
        boxcyl.OrientedBox.from_quaternion((0, 0, 0), size=(1, 1, 1))
    with raises("boxcyl: quaternion: is zero"):
        boxcyl.OrientedBox.from_quaternion((0, 0, 0), wxyz=(0, 0, 0, 0), size=(1, 1, 1))
    with raises("xyzw: expected 4 numbers, got shape (3,)"):
        boxcyl.OrientedBox.from_quaternion((0, 0, 0), xyzw=(0, 0, 1), size=(1, 1, 1))


def test_transform_4x4():
    """trimesh primitives' transform, Eigen's Isometry3d::matrix(): rotation block + translation column."""
    t = np.eye(4)
    t[:3, :3] = R30
    t[:3, 3] = (10, -2, 1)
    box = boxcyl.OrientedBox.from_transform(t, size=(2, 8, 2))
    assert box == boxcyl.OrientedBox.from_rotation((10, -2, 1), R30, size=(2, 8, 2))
    assert boxcyl.intersects(box, dot(np.array([10, -2, 1]) + 3.5 * Y_LOCAL, radius=0.1))
    assert not boxcyl.intersects(box, dot(3.5 * Y_LOCAL, radius=0.1))  # the translation is not ignored
    cyl = boxcyl.Cylinder.from_transform(t, radius=0.5, height=4)
    assert cyl.center == (10.0, -2.0, 1.0) and cyl.axis == (0.0, 0.0, 1.0) and cyl.height == 4.0
    t[3] = (0, 0, 1, 1)
    with raises("boxcyl: transform: the bottom row is not (0, 0, 0, 1)"):
        boxcyl.OrientedBox.from_transform(t, size=(1, 1, 1))
    with raises("transform: expected a 4×4 matrix, got shape (3, 3)"):
        boxcyl.OrientedBox.from_transform(np.eye(3), size=(1, 1, 1))


def test_cylinder_height_half_height_and_local_axis():
    """FCL/Coal Cylinder(r, lz) and trimesh take the full height, MuJoCo/Bullet/Jolt half; FCL/Coal,
    MuJoCo and trimesh run along local z, Bullet's btCylinderShape and Jolt's along local y."""
    probe = boxcyl.AlignedBox(min=(-0.1, -0.1, 1.5), max=(0.1, 0.1, 1.6))  # 1.5 above the centre on z
    assert boxcyl.intersects(probe, boxcyl.Cylinder.from_rotation((0, 0, 0), np.eye(3), radius=1, half_height=2))
    assert not boxcyl.intersects(probe, boxcyl.Cylinder.from_rotation((0, 0, 0), np.eye(3), radius=1, height=2))
    assert boxcyl.Cylinder.from_rotation((0, 0, 0), np.eye(3), radius=1, half_height=2).height == 4.0
    on_y = boxcyl.AlignedBox(min=(-0.1, 1.5, -0.1), max=(0.1, 1.6, 0.1))
    along_y = boxcyl.Cylinder.from_rotation((0, 0, 0), np.eye(3), radius=0.5, half_height=2, along="y")
    along_z = boxcyl.Cylinder.from_rotation((0, 0, 0), np.eye(3), radius=0.5, half_height=2)
    assert boxcyl.intersects(on_y, along_y) and not boxcyl.intersects(on_y, along_z)
    # The local axis of a rotated pose is the matrix's column, from a quaternion as from the matrix.
    s, c = math.sin(math.pi / 12), math.cos(math.pi / 12)
    q = boxcyl.Cylinder.from_quaternion((0, 0, 0), xyzw=(0, 0, s, c), radius=0.5, height=1, along="y")
    assert np.allclose(q.axis, Y_LOCAL, atol=1e-15)
    with raises("cylinder: give exactly one of height= or half_height="):
        boxcyl.Cylinder.from_rotation((0, 0, 0), np.eye(3), radius=1)
    with raises("along: expected 'x', 'y' or 'z', got 'w'"):
        boxcyl.Cylinder.from_rotation((0, 0, 0), np.eye(3), radius=1, height=1, along="w")
    with raises("cylinder.radius: is negative"):
        boxcyl.Cylinder.from_rotation((0, 0, 0), np.eye(3), radius=-1, height=1)


# --- Scaled poses, end points, quaternions of any size --------------------------------------------------

def test_a_scaled_transform_gives_a_parallelepiped_not_an_oriented_box():
    """trimesh's box(extents, transform) with a scaled transform is the parallelepiped spanned by the
    transform's columns; OrientedBox.from_transform refuses it and says where to go."""
    t = np.eye(4)
    t[:3, :3] = R30 @ np.diag([3.0, 4.0, 5.0])
    t[:3, 3] = (10, -2, 1)
    p = boxcyl.Parallelepiped.from_transform(t, size=(1, 1, 1))
    assert p == boxcyl.Parallelepiped(center=(10, -2, 1), axes=t[:3, :3].T, extents=(0.5, 0.5, 0.5))
    assert boxcyl.Parallelepiped.from_transform(t, half_extents=(0.5, 0.5, 0.5)) == p
    # Half sizes 1.5, 2, 2.5 along the local axes: 1.9 along local y is inside, 2.1 outside.
    assert boxcyl.intersects(p, dot(np.array([10, -2, 1]) + 1.9 * Y_LOCAL, radius=0.01))
    assert not boxcyl.intersects(p, dot(np.array([10, -2, 1]) + 2.1 * Y_LOCAL, radius=0.01))
    with raises("transform: its top-left 3×3 block is not a rotation (column 0 has squared length 4; its columns "
                "must be orthonormal within 1e-4): a box under a transform with scale or shear is a "
                "parallelepiped: use Parallelepiped.from_transform"):
        boxcyl.OrientedBox.from_transform(np.diag([2.0, 1, 1, 1]), size=(1, 1, 1))
    with raises("rotation: is not a rotation matrix (columns 0 and 1 have dot product 0.5;"):
        boxcyl.OrientedBox.from_rotation((0, 0, 0), [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]], size=(1, 1, 1))
    bottom = np.eye(4)
    bottom[3, 0] = 1
    with raises("boxcyl: transform: the bottom row is not (0, 0, 0, 1)"):
        boxcyl.Parallelepiped.from_transform(bottom, size=(1, 1, 1))
    with raises("box: give exactly one of half_extents= or size="):
        boxcyl.Parallelepiped.from_transform(t)


@pytest.mark.parametrize("scale", [np.diag([2.0, 2.0, 2.0, 1.0]), np.diag([1.0, 1.0, 3.0, 1.0]),
                                   np.diag([1.0, 0.5, 1.0, 1.0])])
def test_a_scaled_transform_is_refused_for_a_cylinder(scale):
    """trimesh reads cylinder(radius, height, transform) with a scaled transform as a scaled solid
    (radius·2, height·2 for a uniform 2, an elliptic cylinder otherwise); boxcyl refuses it rather than
    drop the scale."""
    with raises("transform: its top-left 3×3 block is not a rotation (column "):
        boxcyl.Cylinder.from_transform(scale, radius=1, height=2)
    try:
        boxcyl.Cylinder.from_transform(scale, radius=1, height=2)
    except ValueError as e:
        assert str(e).endswith("a scaled transform changes the cylinder's radius and height (a non-uniform scale "
                               "makes an elliptic cylinder, which is not a cylinder), and boxcyl takes them "
                               "explicitly: pass the unscaled pose with the scaled radius= and height=")
    with raises("rotation: is not a rotation matrix (column "):
        boxcyl.Cylinder.from_rotation((0, 0, 0), scale[:3, :3], radius=1, height=2)


def test_rotations_within_the_tolerance_are_accepted():
    printed = np.round(R30, 5)  # a rotation printed to 5 digits is still one
    assert boxcyl.Cylinder.from_rotation((0, 0, 0), printed, radius=1, height=2).axis == (0.0, 0.0, 1.0)
    assert boxcyl.OrientedBox.from_rotation((0, 0, 0), printed, size=(1, 1, 1)).axes[0] == tuple(printed[:, 0])


def test_quaternions_of_any_magnitude():
    s, c = math.sin(math.pi / 12), math.cos(math.pi / 12)
    unit = boxcyl.OrientedBox.from_quaternion((0, 0, 0), xyzw=(0, 0, s, c), size=(2, 8, 2))
    for scale in (2.0 ** -1000, 1e-300, 1e300, 2.0 ** 1000):
        scaled = boxcyl.OrientedBox.from_quaternion((0, 0, 0), xyzw=(0, 0, s * scale, c * scale), size=(2, 8, 2))
        assert np.allclose(scaled.axes, unit.axes, rtol=0, atol=4e-16), scale
    assert boxcyl.OrientedBox.from_quaternion((0, 0, 0), xyzw=(0, 0, s * 2.0 ** 1000, c * 2.0 ** 1000),
                                              size=(2, 8, 2)) == unit
    with raises("boxcyl: quaternion: is NaN"):
        boxcyl.OrientedBox.from_quaternion((0, 0, 0), wxyz=(1, math.nan, 0, 0), size=(1, 1, 1))
    with raises("boxcyl: quaternion: is infinite"):
        boxcyl.Cylinder.from_quaternion((0, 0, 0), wxyz=(1, 0, math.inf, 0), radius=1, height=1)


def test_cylinder_between_two_points():
    """MuJoCo's <geom type="cylinder" fromto="1 2 3 1 2 7" size="0.5">, trimesh's cylinder(radius,
    segment=...): the axis segment is the segment given."""
    c = boxcyl.Cylinder.from_endpoints((1, 2, 3), (1, 2, 7), radius=0.5)
    assert c == boxcyl.Cylinder(center=(1, 2, 5), axis=(0, 0, 4), radius=0.5, height=4)
    assert boxcyl.intersects(boxcyl.AlignedBox(min=(0.9, 1.9, 7), max=(1.1, 2.1, 7.1)), c)  # touches the end at p1
    assert not boxcyl.intersects(boxcyl.AlignedBox(min=(0.9, 1.9, math.nextafter(7, 8)), max=(1.1, 2.1, 7.1)), c)
    integer = boxcyl.Cylinder.from_endpoints((-1, -1, -1), (2, 3, 11), radius=0.25)  # length 13, exact
    assert (integer.center, integer.axis, integer.height) == ((0.5, 1.0, 5.0), (3.0, 4.0, 12.0), 13.0)
    # A length that is no float64 is rounded up: the smallest float64 whose square is >= |p1 - p0|².
    from fractions import Fraction
    rng = np.random.default_rng(41)
    for p0, p1 in [((0, 0, 0), (1, 1, 1)), ((0, 0, 0), (1, 1, 0))] + [
            (tuple(rng.normal(size=3) * 10.0 ** rng.integers(-5, 5)), tuple(rng.normal(size=3))) for _ in range(200)]:
        cyl = boxcyl.Cylinder.from_endpoints(p0, p1, radius=1)
        squared = sum(Fraction(a) ** 2 for a in cyl.axis)
        assert Fraction(cyl.height) ** 2 >= squared > Fraction(math.nextafter(cyl.height, 0)) ** 2
        assert cyl.axis == tuple(float(b) - float(a) for a, b in zip(p0, p1))
    assert boxcyl.Cylinder.from_endpoints((0, 0, 0), (1, 1, 1), radius=1).height == math.nextafter(math.sqrt(3), 2)
    with raises("p0, p1: are the same point (1.0, 2.0, 3.0); a cylinder between them has no axis"):
        boxcyl.Cylinder.from_endpoints((1, 2, 3), [1, 2, 3], radius=1)
    with raises("cylinder.radius: is negative"):
        boxcyl.Cylinder.from_endpoints((0, 0, 0), (0, 0, 1), radius=-1)
    with raises("p1: expected 3 numbers, got shape (2,)"):
        boxcyl.Cylinder.from_endpoints((0, 0, 0), (0, 1), radius=1)
