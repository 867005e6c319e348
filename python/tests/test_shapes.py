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
