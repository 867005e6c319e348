"""Exact box–cylinder intersection queries.

Does this finite cylinder intersect this box? ``boxcyl`` answers exactly for the float64 values
given (closed solids: touching counts), for axis-aligned boxes, oriented boxes and any
parallelepipeds, one query at a time or over numpy arrays. Boxes and cylinders can also be built
from rotation matrices, quaternions and 4×4 transforms with the size convention named
(``OrientedBox.from_rotation(center, R, size=...)``, ``Cylinder.from_quaternion(center,
xyzw=..., radius=..., half_height=...)``).

>>> import boxcyl
>>> box = boxcyl.AlignedBox(min=(-1, -1, -1), max=(1, 1, 1))
>>> cyl = boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 5), radius=2, height=1)
>>> boxcyl.intersects(box, cyl)  # the side touches the face x = 1
True
>>> cyl
Cylinder(center=(3.0, 0.0, 0.0), axis=(0.0, 0.0, 5.0), radius=2.0, height=1.0)

Batch forms take arrays and return a numpy bool array; see :func:`intersects_aligned`,
:func:`intersects_oriented` and :func:`intersects_parallelepiped`; :mod:`boxcyl.dask` answers
chunked Dask arrays. :func:`grid_cells` lists the cells of a regular grid that a cylinder meets.
:func:`distance` bounds how far apart a box and a cylinder are, proved (and
:func:`distances_aligned` etc. over arrays); :func:`signed_distance` also bounds how deep they
overlap (and :func:`signed_distances_aligned` etc. over arrays).

Input policy: numbers are real numbers, read as float64 (numpy integer and float arrays, Python
ints and floats, and object arrays of real numbers such as ``Fraction`` or ``Decimal``, each
rounded to the nearest float64). Booleans, complex numbers, datetime64/timedelta64, strings, None
and masked arrays are refused, as are invalid values (NaN, ±Inf, a zero axis, negative sizes,
min > max, axes not orthonormal to 1e-4). Every refusal is a ``ValueError`` naming the field, and
the element in a batch: ``"boxes[17].max[0]: is less than boxes[17].min[0]"``.
"""

import decimal as _decimal
import numbers as _numbers
import typing as _typing

import numpy as _np

from . import _core
from ._core import Algorithm, Arithmetic, __version__

__all__ = [
    "AlignedBox",
    "Algorithm",
    "Arithmetic",
    "Cylinder",
    "Distance",
    "Distances",
    "OrientedBox",
    "Parallelepiped",
    "SignedDistance",
    "SignedDistances",
    "distance",
    "distances_aligned",
    "distances_oriented",
    "distances_parallelepiped",
    "grid_cells",
    "intersects",
    "intersects_aligned",
    "intersects_oriented",
    "intersects_parallelepiped",
    "signed_distance",
    "signed_distances_aligned",
    "signed_distances_oriented",
    "signed_distances_parallelepiped",
    "__version__",
]

# ---- Numbers in, float64 out, or a ValueError naming the field. --------------------------------

# dtype kinds numpy would convert to float64 wrongly or not at all: (one value, an array of them).
_REFUSED_KINDS = {
    "b": ("a bool", "an array of booleans"),
    "c": ("a complex number", "an array of complex numbers"),
    "M": ("a datetime64 value", "an array of datetime64 values"),
    "m": ("a timedelta64 value", "an array of timedelta64 values"),
    "U": ("a string", "an array of strings"),
    "S": ("bytes", "an array of bytes"),
    "V": ("a structured value", "an array of structured values"),
}
_REAL_TYPES = (_numbers.Real, _decimal.Decimal)


def _where(name, shape, flat_index):
    """``name`` followed by the element's index, as ``boxes[3][1][2]``."""
    return name + "".join(f"[{i}]" for i in _np.unravel_index(flat_index, shape)) if shape else name


def _is_real_type(t):
    return issubclass(t, _REAL_TYPES) and not issubclass(t, (bool, _np.bool_))


def _from_objects(name, a):
    """An object array whose elements are all real numbers, as float64."""
    flat = a.ravel()
    bad = {t for t in set(map(type, flat)) if not _is_real_type(t)}
    if bad:
        i = next(k for k, x in enumerate(flat) if type(x) in bad)
        x = flat[i]
        what = ("a nested sequence (rows of different lengths?)" if isinstance(x, (list, tuple, _np.ndarray))
                else "None" if x is None else f"a {type(x).__name__} ({x!r})")
        raise ValueError(f"{_where(name, a.shape, i)}: is {what}; expected a real number")
    try:
        return a.astype(_np.float64)
    except OverflowError:
        i = next(k for k, x in enumerate(flat) if not _fits_float(x))
        raise ValueError(f"{_where(name, a.shape, i)}: is too large for float64") from None


def _fits_float(x):
    try:
        float(x)
        return True
    except OverflowError:
        return False


def _hides_refused(seq):
    """What numpy would silently turn into a number inside nested lists: a bool or a masked array."""
    for x in seq:
        if isinstance(x, (bool, _np.bool_)):
            return "booleans"
        if isinstance(x, _np.ma.MaskedArray):
            return "a masked array"
        if isinstance(x, (list, tuple)):
            found = _hides_refused(x)
            if found:
                return found
        elif isinstance(x, _np.ndarray) and x.dtype.kind == "b":
            return "booleans"
    return None


def _real_array(name, value):
    """``value`` as a float64 ndarray (no copy when it is one already), or a ValueError naming ``name``."""
    if isinstance(value, _np.ndarray) and value.dtype == _np.float64 and type(value) is _np.ndarray:
        return value  # the fast path: nothing to check or convert
    if value is None:
        raise ValueError(f"{name}: is None; expected real numbers")
    if isinstance(value, _np.ma.MaskedArray):
        raise ValueError(f"{name}: is a masked array, whose masked entries would be read as numbers; "
                         "pass a plain array of the entries you mean")
    if isinstance(value, (bool, _np.bool_)):
        raise ValueError(f"{name}: is a bool ({value!r}); expected a real number")
    if isinstance(value, (list, tuple)):
        try:
            a = _np.asarray(value)
        except ValueError:  # numpy refuses ragged nesting
            raise ValueError(f"{name}: is not a regular array (nested sequences of different lengths)") from None
        if a.dtype.kind in "iuf":
            hidden = _hides_refused(value)
            if hidden:
                raise ValueError(f"{name}: contains {hidden}; expected real numbers")
    else:
        a = _np.asarray(value)
    kind = a.dtype.kind
    if kind in "iuf":
        return a.astype(_np.float64, copy=False)
    if kind == "O":
        return _from_objects(name, a)
    one, many = _REFUSED_KINDS.get(kind, ("a value", "an array of values"))
    raise ValueError(f"{name}: is {many if a.ndim else one} (dtype {a.dtype}); expected real numbers")


def _vector(name, value):
    a = _real_array(name, value)
    if a.shape != (3,):
        raise ValueError(f"{name}: expected 3 numbers, got {_shape_text(a)}")
    return tuple(a.tolist())


def _scalar(name, value):
    a = _real_array(name, value)
    if a.shape != ():
        raise ValueError(f"{name}: expected one number, got {_shape_text(a)}")
    return float(a)


def _matrix(name, value):
    a = _real_array(name, value)
    if a.shape != (3, 3):
        raise ValueError(f"{name}: expected 3 vectors of 3 numbers (shape (3, 3)), got {_shape_text(a)}")
    return tuple(tuple(row) for row in a.tolist())


def _shape_text(a):
    return "one number" if a.shape == () else f"shape {a.shape}"


def _one_of(what, **named):
    """The one keyword of `named` given (not None), as (name, value); a ValueError naming them otherwise."""
    given = [(k, v) for k, v in named.items() if v is not None]
    if len(given) != 1:
        names = " or ".join(f"{k}=" for k in named)
        raise ValueError(f"{what}: give exactly one of {names}")
    return given[0]


def _quaternion(wxyz, xyzw):
    """(w, x, y, z) from whichever order was named."""
    order, q = _one_of("quaternion", wxyz=wxyz, xyzw=xyzw)
    q = _real_array(order, q)
    if q.shape != (4,):
        raise ValueError(f"{order}: expected 4 numbers, got {_shape_text(q)}")
    w, x, y, z = q.tolist() if order == "wxyz" else _np.roll(q, 1).tolist()
    return (w, x, y, z)


def _transform(value):
    t = _real_array("transform", value)
    if t.shape != (4, 4):
        raise ValueError(f"transform: expected a 4×4 matrix, got {_shape_text(t)}")
    return tuple(tuple(row) for row in t.tolist())


def _box_sizes(half_extents, size):
    name, value = _one_of("box", half_extents=half_extents, size=size)
    return _vector(name, value), name == "size"


def _cylinder_length(height, half_height):
    name, value = _one_of("cylinder", height=height, half_height=half_height)
    return _scalar(name, value), name == "half_height"


_AXES = {"x": 0, "y": 1, "z": 2}


def _along(along):
    if along not in _AXES:
        raise ValueError(f"along: expected 'x', 'y' or 'z', got {along!r}")
    return _AXES[along]


# ---- The shapes: immutable, validated, equal by value, picklable, printed as built. ---------------

class _ByValue:
    """Equality, hashing and pickling by the fields a shape class names in ``_FIELDS`` (its
    constructor's arguments, in order): shapes of the same class with equal fields are equal."""

    __slots__ = ()
    _FIELDS = ()

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if "_FIELDS" in cls.__dict__:
            cls._SHAPE = cls  # the class that named the fields: what equality and pickling go by

    def _key(self):
        return tuple(getattr(self, name) for name in self._FIELDS)

    def __eq__(self, other):
        return self._key() == other._key() if isinstance(other, self._SHAPE) else NotImplemented

    def __hash__(self):
        return hash((self._SHAPE.__name__,) + self._key())

    def __reduce__(self):
        return (self._SHAPE, self._key())


class AlignedBox(_ByValue, _core.AlignedBox):
    """The closed axis-aligned box ``min <= X <= max`` (componentwise); equal bounds give a flat box
    or a point. Immutable; validated when built (``ValueError`` naming the field)."""

    __slots__ = ()
    _FIELDS = ("min", "max")

    def __init__(self, min, max):  # noqa: A002 (the fields' names)
        super().__init__(_vector("box.min", min), _vector("box.max", max))


class OrientedBox(_ByValue, _core.OrientedBox):
    """The closed solid ``{center + x0*axes[0] + x1*axes[1] + x2*axes[2] : |xi| <= extents[i]}``:
    ``axes`` are the box's axes as **rows** (orthonormal to within 1e-4: a rotation rounded to double
    is fine), ``extents`` are **half** side lengths. For a rotation matrix (axes as columns), a
    quaternion or a 4×4 transform, or full side lengths, use the named constructors
    ``OrientedBox.from_rotation`` etc. Immutable; validated when built."""

    __slots__ = ()
    _FIELDS = ("center", "axes", "extents")

    def __init__(self, center, axes, extents):
        super().__init__(_vector("box.center", center), _matrix("box.axes", axes), _vector("box.extents", extents))

    @classmethod
    def from_rotation(cls, center, rotation, *, half_extents=None, size=None):
        """The box at ``center`` whose axes are the **columns** of the 3×3 rotation matrix
        (``x_world = rotation @ x_local + center``: FCL/Coal and Eigen, MuJoCo's ``xmat`` reshaped
        to 3×3, scipy's ``as_matrix()``, trimesh's ``transform[:3, :3]``), with ``half_extents``
        (half side lengths: MuJoCo, Bullet, Jolt) or ``size`` (full side lengths: FCL/Coal,
        trimesh) — exactly one, by name."""
        sizes, full = _box_sizes(half_extents, size)
        b = _core._box_from_rotation(_vector("center", center), _matrix("rotation", rotation), sizes, full)
        return cls(b.center, b.axes, b.extents)

    @classmethod
    def from_quaternion(cls, center, *, wxyz=None, xyzw=None, half_extents=None, size=None):
        """The box at ``center`` rotated by a quaternion given in the order its keyword names:
        ``wxyz`` (scalar first: MuJoCo, trimesh, Eigen's constructor) or ``xyzw`` (scalar last:
        scipy's ``as_quat()``, Bullet, Jolt); it need not be exactly unit length. Sizes as for
        :meth:`from_rotation`."""
        sizes, full = _box_sizes(half_extents, size)
        b = _core._box_from_quaternion(_vector("center", center), _quaternion(wxyz, xyzw), sizes, full)
        return cls(b.center, b.axes, b.extents)

    @classmethod
    def from_transform(cls, transform, *, half_extents=None, size=None):
        """The box posed by a 4×4 rigid transform (rotation in the top-left 3×3 block, columns = axes;
        the centre in the last column; bottom row 0, 0, 0, 1: trimesh, Eigen's ``Isometry3d``).
        Sizes as for :meth:`from_rotation`. A transform with scale or shear is refused (its box is
        a parallelepiped: :meth:`Parallelepiped.from_transform`)."""
        sizes, full = _box_sizes(half_extents, size)
        b = _core._box_from_transform(_transform(transform), sizes, full)
        return cls(b.center, b.axes, b.extents)


class Parallelepiped(_ByValue, _core.Parallelepiped):
    """The closed solid ``{center + x0*axes[0] + x1*axes[1] + x2*axes[2] : |xi| <= extents[i]}`` for
    **any** three axes (rows), exactly as given: any lengths and angles, e.g. ``(3, 4, 0), (-4, 3, 0),
    (0, 0, 5)`` (a box with integer vertices); parallel or zero axes give flat solids. Answered exactly
    like the other kinds. Immutable; validated when built (finite numbers, extents >= 0)."""

    __slots__ = ()
    _FIELDS = ("center", "axes", "extents")

    def __init__(self, center, axes, extents):
        super().__init__(_vector("box.center", center), _matrix("box.axes", axes), _vector("box.extents", extents))

    @classmethod
    def from_transform(cls, transform, *, half_extents=None, size=None):
        """The image of the box ``|x_i| <= half_extents[i]`` (or of side lengths ``size``) under a 4×4
        affine transform, exactly: ``center`` = its translation (last column), ``axes`` = the
        **columns** of its top-left 3×3 block as given (any scale, shear or reflection), bottom row
        0, 0, 0, 1 — e.g. a trimesh box whose transform has scale."""
        sizes, full = _box_sizes(half_extents, size)
        b = _core._parallelepiped_from_transform(_transform(transform), sizes, full)
        return cls(b.center, b.axes, b.extents)


class Cylinder(_ByValue, _core.Cylinder):
    """A closed finite cylinder: the points within ``radius`` of the axis segment
    ``center ± (height/2)·axis/|axis|``. ``height`` is the **full** length; ``axis`` need not be unit
    length; radius 0 is a segment, height 0 a disk. Immutable; validated when built."""

    __slots__ = ()
    _FIELDS = ("center", "axis", "radius", "height")

    def __init__(self, center, axis, radius, height):
        super().__init__(_vector("cylinder.center", center), _vector("cylinder.axis", axis),
                         _scalar("cylinder.radius", radius), _scalar("cylinder.height", height))

    @classmethod
    def from_rotation(cls, center, rotation, *, radius, height=None, half_height=None, along="z"):
        """The cylinder centred at ``center`` along the local ``along`` axis (``"z"``: FCL/Coal,
        MuJoCo, trimesh; ``"y"``: Bullet's btCylinderShape, Jolt) of the rotation matrix, i.e. its
        column ``along`` (columns are the local axes, as for :meth:`OrientedBox.from_rotation`), with
        ``height`` (full length: FCL/Coal, trimesh) or ``half_height`` (MuJoCo, Bullet, Jolt) —
        exactly one, by name."""
        length, half = _cylinder_length(height, half_height)
        c = _core._cylinder_from_rotation(_vector("center", center), _matrix("rotation", rotation),
                                          _scalar("radius", radius), length, half, _along(along))
        return cls(c.center, c.axis, c.radius, c.height)

    @classmethod
    def from_quaternion(cls, center, *, wxyz=None, xyzw=None, radius, height=None, half_height=None, along="z"):
        """As :meth:`from_rotation`, the rotation given as a quaternion in the order its keyword
        names (``wxyz`` or ``xyzw``; see :meth:`OrientedBox.from_quaternion`)."""
        length, half = _cylinder_length(height, half_height)
        c = _core._cylinder_from_quaternion(_vector("center", center), _quaternion(wxyz, xyzw),
                                            _scalar("radius", radius), length, half, _along(along))
        return cls(c.center, c.axis, c.radius, c.height)

    @classmethod
    def from_transform(cls, transform, *, radius, height=None, half_height=None, along="z"):
        """As :meth:`from_rotation`, posed by a 4×4 rigid transform (see
        :meth:`OrientedBox.from_transform`); the centre is the transform's translation. A transform
        with scale is refused rather than read as a rotation: scaling changes the radius and the
        height (a non-uniform scale makes an elliptic cylinder), which boxcyl takes as given."""
        length, half = _cylinder_length(height, half_height)
        c = _core._cylinder_from_transform(_transform(transform), _scalar("radius", radius), length, half,
                                           _along(along))
        return cls(c.center, c.axis, c.radius, c.height)

    @classmethod
    def from_endpoints(cls, p0, p1, *, radius):
        """The cylinder whose axis runs from ``p0`` to ``p1`` (MuJoCo's ``fromto``, trimesh's
        ``cylinder(segment=...)``): ``center`` = (p0 + p1)/2 and ``axis`` = p1 − p0, each rounded once
        to the nearest float64 (exact when they are float64 values: coordinates on a common grid),
        and ``height`` = the smallest float64 ≥ |p1 − p0|, exact when the length is a float64. So
        the cylinder's segment contains the segment p0 p1, longer by less than an ulp of the length
        (when center and axis are exact), and is exactly p0 p1 when the length is a float64 too."""
        a, b = _vector("p0", p0), _vector("p1", p1)
        if a == b:
            raise ValueError(f"p0, p1: are the same point {a}; a cylinder between them has no axis")
        c = _core._cylinder_between(a, b, _scalar("radius", radius))
        return cls(c.center, c.axis, c.radius, c.height)


# ---- Options. ------------------------------------------------------------------------------------

def _option(kind, name, value):
    if isinstance(value, kind):
        return value
    if isinstance(value, str) and value in kind.__members__:
        return kind.__members__[value]
    names = ", ".join(repr(k) for k in kind.__members__)
    if isinstance(value, str):
        raise ValueError(f"{name}: {value!r} is not one of {names}")
    raise ValueError(f"{name}: expected a boxcyl.{kind.__name__} or one of {names}; got {value!r}")


def _options(algorithm, arithmetic):
    return _option(Algorithm, "algorithm", algorithm), _option(Arithmetic, "arithmetic", arithmetic)


def _threads(threads):
    """None or 0 → 0 (all cores, as the CLI's --threads 0) for the core; a positive int as is."""
    if threads is None:
        return 0
    if isinstance(threads, (bool, _np.bool_)) or not isinstance(threads, _numbers.Integral) or threads < 0:
        raise ValueError(f"threads: expected a non-negative integer (0 or None: all cores); got {threads!r}")
    return min(int(threads), 1 << 16)


def _type_name(x):
    return type(x).__name__


def _a(noun):
    return ("an " if noun[0] in "AEIOU" else "a ") + noun


def intersects(box, cylinder, *, algorithm=Algorithm.inequalities, arithmetic=Arithmetic.filtered, margin=None):
    """Whether the closed box and the closed cylinder share a point (touching counts), or with
    ``margin``, whether the box comes within that distance of the cylinder.

    Parameters
    ----------
    box : AlignedBox, OrientedBox or Parallelepiped
    cylinder : Cylinder
    algorithm : Algorithm or its name, optional
        ``"inequalities"`` (the linear-inequalities method, default), ``"hull"`` (the convex-hull
        method), ``"lcp"`` (convex quadratic programming as an LCP) or ``"oracle"`` (the exact
        reference); docs/algorithms.md describes them.
    arithmetic : Arithmetic or its name, optional
        ``"filtered"`` (default: the exact answer, with a fast certified filter), ``"exact"``, or the
        plain rounded ``"float64"`` / ``"float32"``, which may misjudge inputs within a tiny gap of
        touching.
    margin : float, optional
        A distance >= 0: the question becomes ``dist(box, cylinder) <= margin`` (the box meets the
        cylinder rounded by the margin), answered exactly whatever ``algorithm`` and ``arithmetic``
        say; ``margin=0`` asks whether they touch.

    Returns
    -------
    bool
        With the defaults, the exact answer for the float64 values given.

    Raises
    ------
    ValueError
        For arguments of the wrong kind (named), an unknown option, or exact ``"lcp"`` /
        ``"inequalities"`` (``arithmetic="exact"``) on an oriented box whose axes are orthonormal
        only up to rounding, which they cannot treat exactly; the default and ``"hull"`` handle any
        valid box.
    """
    if not isinstance(box, (_core.AlignedBox, _core.OrientedBox, _core.Parallelepiped)):
        raise ValueError(f"box: expected an AlignedBox, an OrientedBox or a Parallelepiped, got {_type_name(box)} "
                         "(for arrays use intersects_aligned / intersects_oriented / intersects_parallelepiped)")
    if not isinstance(cylinder, _core.Cylinder):
        raise ValueError(f"cylinder: expected a Cylinder, got {_type_name(cylinder)}")
    options = _options(algorithm, arithmetic)
    if margin is not None:
        return _core.within_distance(box, cylinder, _scalar("margin", margin))
    return _core.intersects(box, cylinder, *options)


# ---- The distance. -----------------------------------------------------------------------------------

class Distance(_typing.NamedTuple):
    """How far apart a box and a cylinder are (:func:`distance`).

    ``lower <= dist(box, cylinder) <= upper`` is proved for the float64 values of the shapes;
    ``lower`` and ``upper`` are at most 4 float64 values apart (``upper - lower`` is at most 4 units
    in the last place of ``upper``), and both are exactly 0.0 when the solids touch or overlap.
    ``upper`` is ``inf`` when the distance exceeds the largest float64. ``on_box`` and
    ``on_cylinder`` are a nearest pair of points, one near each solid: approximate, not proved (for
    solids that meet, near a common point)."""

    lower: float
    upper: float
    on_box: _typing.Tuple[float, float, float]
    on_cylinder: _typing.Tuple[float, float, float]


def _check_shapes(box, cylinder, batch_names):
    if not isinstance(box, (_core.AlignedBox, _core.OrientedBox, _core.Parallelepiped)):
        raise ValueError(f"box: expected an AlignedBox, an OrientedBox or a Parallelepiped, got {_type_name(box)} "
                         f"(for arrays use {batch_names})")
    if not isinstance(cylinder, _core.Cylinder):
        raise ValueError(f"cylinder: expected a Cylinder, got {_type_name(cylinder)}")


def distance(box, cylinder):
    """The Euclidean distance between the closed box and the closed cylinder, as proved bounds.

    Parameters
    ----------
    box : AlignedBox, OrientedBox or Parallelepiped
    cylinder : Cylinder

    Returns
    -------
    Distance
        ``(lower, upper, on_box, on_cylinder)``: ``lower <= distance <= upper``, proved, at most 4
        float64 values apart, both exactly 0.0 when the solids touch or overlap (``upper`` is
        ``inf`` beyond the largest float64); ``on_box`` and ``on_cylinder`` a nearest pair of
        points (approximate). See :class:`Distance`.

    Raises
    ------
    ValueError
        For arguments of the wrong kind (named).

    There are no ``algorithm`` or ``arithmetic`` options: the bounds are certified whatever the
    rounding (exact arithmetic decides what double-double arithmetic leaves open). The query runs
    with the GIL released. ``intersects(box, cylinder, margin=m)`` is ``True`` exactly when the
    distance is at most ``m``.
    """
    _check_shapes(box, cylinder, "distances_aligned / distances_oriented / distances_parallelepiped")
    return Distance(*_core.distance(box, cylinder))


class SignedDistance(_typing.NamedTuple):
    """How far apart a box and a cylinder are, or how deep they overlap (:func:`signed_distance`).

    ``lower <= sd(box, cylinder) <= upper`` is proved for the float64 values of the shapes, where
    ``sd`` is the distance when the solids are apart, minus the penetration depth (the length of the
    shortest translation of the box that separates them) when they overlap, and 0 when they touch.
    Apart, the bounds are :func:`distance`'s; overlapping, ``upper - lower`` is at most 2**-43 times
    the largest of the box centre's offset from the cylinder's centre (each coordinate), the
    components of the box's half axes, the radius and the half height. ``normal`` is a unit
    vector from the box towards the cylinder (the box moves along ``-normal`` to separate);
    ``on_box`` and ``on_cylinder`` a witness pair, ``on_cylinder - on_box`` about ``sd * normal``:
    approximate, not proved."""

    lower: float
    upper: float
    normal: _typing.Tuple[float, float, float]
    on_box: _typing.Tuple[float, float, float]
    on_cylinder: _typing.Tuple[float, float, float]


def signed_distance(box, cylinder):
    """The signed distance between the closed box and the closed cylinder, as proved bounds: the
    distance when they are apart, minus the penetration depth when they overlap.

    Parameters
    ----------
    box : AlignedBox, OrientedBox or Parallelepiped
    cylinder : Cylinder

    Returns
    -------
    SignedDistance
        ``(lower, upper, normal, on_box, on_cylinder)``: ``lower <= signed distance <= upper``,
        proved (apart: :func:`distance`'s bounds; overlapping: at most 2**-43 of the shapes' size
        apart, as :class:`SignedDistance` says); ``normal`` a unit vector from the box towards the cylinder;
        ``on_box`` and ``on_cylinder`` a witness pair (approximate). See :class:`SignedDistance`.

    Raises
    ------
    ValueError
        For arguments of the wrong kind (named).

    There are no ``algorithm`` or ``arithmetic`` options: the bounds are certified whatever the
    rounding. The query runs with the GIL released.
    """
    _check_shapes(box, cylinder,
                  "signed_distances_aligned / signed_distances_oriented / signed_distances_parallelepiped")
    return SignedDistance(*_core.signed_distance(box, cylinder))


# ---- Batch arguments: float64 arrays of shape (M, *tail), M = N or 1, never copied when float64. ---

def _field(name, value, tail):
    """``value`` as a float64 array of shape (M, *tail); single=True if it had no leading length."""
    a = _real_array(name, value)
    if a.shape == tail:
        return a.reshape((1,) + tail), True
    if a.ndim == len(tail) + 1 and a.shape[1:] == tail:
        return a, False
    expected = ", ".join(["N"] + [str(t) for t in tail])
    raise ValueError(f"{name}: expected shape ({expected}) or {tail}, got {a.shape}")


def _fields(kind, names, values, tails):
    """Each field through _field; single=True when every field was given without a leading length."""
    if len(values) != len(names):
        raise ValueError(f"{kind}: expected a tuple of {len(names)} arrays ({', '.join(names)}), got {len(values)}")
    arrays, singles = zip(*(_field(f"{kind}.{n}", v, t) for n, v, t in zip(names, values, tails)))
    return list(arrays), all(singles)


def _objects(name, seq, cls):
    """Whether ``seq`` is a list/tuple of ``cls`` objects (or an empty list); a ValueError naming the
    first element of another kind in a sequence that mixes them."""
    if not isinstance(seq, (list, tuple)):
        return False
    if isinstance(seq, list) and not seq:
        return True
    shapes = (_core.AlignedBox, _core.OrientedBox, _core.Parallelepiped, _core.Cylinder)
    if not any(isinstance(x, shapes) for x in seq):
        return False
    for i, x in enumerate(seq):
        if not isinstance(x, cls):
            raise ValueError(f"{name}[{i}]: expected {_a(cls.__name__)}, got {_type_name(x)}")
    return True


def _rows(values, tail):
    return _np.array(values, dtype=_np.float64).reshape((len(values),) + tail)


_SHAPES_AS_SEQUENCE = ("for a sequence of boxes pass a list, or an array of shape (N, 2, 3) with boxes[i] = "
                       "[min, max]")


def _aligned_boxes(boxes):
    """(min, max) float64 arrays of shape (M, 3), and whether they are one box for all."""
    if isinstance(boxes, _core.AlignedBox):
        return [_np.array([boxes.min]), _np.array([boxes.max])], True
    if _objects("boxes", boxes, _core.AlignedBox):
        return [_rows([b.min for b in boxes], (3,)), _rows([b.max for b in boxes], (3,))], False
    if isinstance(boxes, tuple):
        if len(boxes) != 2:
            raise ValueError(f"boxes: a tuple is (min, max); got a tuple of {len(boxes)} items ({_SHAPES_AS_SEQUENCE})")
        lo, hi = _real_array("boxes.min", boxes[0]), _real_array("boxes.max", boxes[1])
        if lo.shape == (2, 3) and hi.shape == (2, 3):
            raise ValueError(
                "boxes: a tuple of two (2, 3) arrays is ambiguous: as (min, max) it is two boxes with "
                "min = its first item, as a sequence it is two boxes [min, max]. For one box pass "
                "(min, max) with two (3,) vectors; for [min, max] pairs pass a list or an array of shape "
                "(N, 2, 3); for (N, 3) arrays min and max pass np.stack((min, max), axis=1)")
        return _fields("boxes", ("min", "max"), (lo, hi), ((3,), (3,)))
    b = _real_array("boxes", boxes)
    if b.shape == (0,):  # an empty list: no boxes
        b = b.reshape(0, 2, 3)
    if b.ndim < 2 or b.shape[-2:] != (2, 3) or b.ndim > 3:
        raise ValueError(f"boxes: expected shape (N, 2, 3) or (2, 3), got {b.shape}")
    single = b.ndim == 2
    if single:
        b = b[_np.newaxis]
    return [b[:, 0, :], b[:, 1, :]], single  # views: the core reads any strides


def _frame_boxes(boxes, cls=_core.OrientedBox):
    """(center, axes, extents) float64 arrays of shapes (M, 3), (M, 3, 3), (M, 3), and whether single."""
    if isinstance(boxes, cls):
        return [_np.array([boxes.center]), _np.array([boxes.axes]), _np.array([boxes.extents])], True
    if _objects("boxes", boxes, cls):
        return [_rows([b.center for b in boxes], (3,)), _rows([b.axes for b in boxes], (3, 3)),
                _rows([b.extents for b in boxes], (3,))], False
    if not isinstance(boxes, (tuple, list)):
        raise ValueError(f"boxes: expected {_a(cls.__name__)}, a list of them, or a tuple (center, axes, extents) of "
                         f"arrays; got {_type_name(boxes)}")
    return _fields("boxes", ("center", "axes", "extents"), boxes, ((3,), (3, 3), (3,)))


def _cylinders(cylinders):
    """(center, axis, radius, height) float64 arrays of shapes (M, 3), (M, 3), (M,), (M,); single."""
    if isinstance(cylinders, _core.Cylinder):
        c = cylinders
        return [_np.array([c.center]), _np.array([c.axis]), _np.array([c.radius]), _np.array([c.height])], True
    if _objects("cylinders", cylinders, _core.Cylinder):
        return [_rows([c.center for c in cylinders], (3,)), _rows([c.axis for c in cylinders], (3,)),
                _rows([c.radius for c in cylinders], ()), _rows([c.height for c in cylinders], ())], False
    if not isinstance(cylinders, (tuple, list)):
        raise ValueError(f"cylinders: expected a Cylinder, a list of them, or a tuple (center, axis, radius, "
                         f"height) of arrays; got {_type_name(cylinders)}")
    return _fields("cylinders", ("center", "axis", "radius", "height"), cylinders, ((3,), (3,), (), ()))


def _margin(margin):
    """None, or the margin as a float (the core refuses a negative, NaN or infinite one, named)."""
    return None if margin is None else _scalar("margin", margin)


def _check_lengths(arrays):
    """The common batch length N: every field's leading length must be N or 1."""
    lengths = {a.shape[0] for a in arrays} - {1}
    if len(lengths) > 1:
        raise ValueError(f"boxes and cylinders: leading lengths {sorted(lengths)} differ (each must be N or 1)")


def intersects_aligned(boxes, cylinders, *, algorithm=Algorithm.inequalities, arithmetic=Arithmetic.filtered,
                       threads=None, margin=None):
    """Whether each axis-aligned box intersects its cylinder, for arrays of them.

    Parameters
    ----------
    boxes : array_like (N, 2, 3), a tuple (min, max) of array_like (N, 3), an AlignedBox, or a list of them
        An array (or nested list) has ``boxes[i] = [min, max]``; a tuple is always (min, max) (a
        tuple of two (2, 3) arrays, which could be read either way, is refused). A single box (an
        AlignedBox, shape (2, 3), or (3,) vectors in the tuple) is used with every cylinder. An
        empty list is no boxes.
    cylinders : Cylinder, a list of them, or a tuple (center, axis, radius, height)
        Arrays of shapes (N, 3), (N, 3), (N,), (N,); any field may be given once (shape (3,) or a
        scalar) for all. A single Cylinder is used with every box.
    algorithm, arithmetic : Algorithm / Arithmetic or their names, optional
        The default (``"inequalities"``, ``"filtered"``) is the exact query.
    threads : int or None, optional
        How many threads answer (None or 0, the default: all cores; small batches use fewer).
    margin : float, optional
        A distance >= 0: each answer becomes ``dist(box, cylinder) <= margin``, exactly, as
        ``intersects(box, cylinder, margin=margin)`` answers it (whatever ``algorithm`` and
        ``arithmetic`` say); None (the default) asks whether they touch.

    Returns
    -------
    numpy.ndarray of bool, shape (N,)

    Raises
    ------
    ValueError
        For a wrong shape or kind of input, or the first invalid element, named:
        ``"boxes[3].min[1]: is NaN"``; a negative, NaN or infinite margin (``"margin: is negative"``).
        No answer is returned unless every element is valid.
    KeyboardInterrupt
        Ctrl-C stops a running batch within milliseconds.

    Inputs follow the package's input policy (see ``help(boxcyl)``); float64 arrays are read in
    place, whatever their strides. One cylinder against many boxes with the default query (or a
    margin) runs the C++ batch API (SIMD filter, exact fallback); the loop runs with the GIL released.
    """
    box_arrays, box_single = _aligned_boxes(boxes)
    cyl, cylinder_single = _cylinders(cylinders)
    _check_lengths(box_arrays + cyl)
    return _core._intersects_aligned(*box_arrays, box_single, *cyl, cylinder_single,
                                     *_options(algorithm, arithmetic), _threads(threads), _margin(margin))


def intersects_oriented(boxes, cylinders, *, algorithm=Algorithm.inequalities, arithmetic=Arithmetic.filtered,
                        threads=None, margin=None):
    """Whether each oriented box intersects its cylinder, for arrays of them.

    Parameters
    ----------
    boxes : a tuple (center, axes, extents), an OrientedBox, or a list of them
        Arrays of shapes (N, 3), (N, 3, 3) with ``axes[i][k]`` the k-th axis of box i (rows), and
        (N, 3) half side lengths; any field may be given once for all. A single OrientedBox is used
        with every cylinder. An empty list is no boxes.
    cylinders : Cylinder, a list of them, or a tuple (center, axis, radius, height)
        As for :func:`intersects_aligned`.
    algorithm, arithmetic : Algorithm / Arithmetic or their names, optional
        The default is the exact query.
    threads, margin : optional
        As for :func:`intersects_aligned`.

    Returns
    -------
    numpy.ndarray of bool, shape (N,)

    Raises
    ------
    ValueError
        For a wrong shape or kind of input, or the first invalid element, named (``"boxes[2].axes[0]:
        is not unit length ..."``). No answer is returned unless every element is valid.
    KeyboardInterrupt
        Ctrl-C stops a running batch within milliseconds.
    """
    box_arrays, box_single = _frame_boxes(boxes)
    cyl, cylinder_single = _cylinders(cylinders)
    _check_lengths(box_arrays + cyl)
    return _core._intersects_oriented(*box_arrays, box_single, *cyl, cylinder_single,
                                      *_options(algorithm, arithmetic), _threads(threads), _margin(margin))


def intersects_parallelepiped(boxes, cylinders, *, algorithm=Algorithm.inequalities, arithmetic=Arithmetic.filtered,
                              threads=None, margin=None):
    """Whether each parallelepiped intersects its cylinder, for arrays of them.

    Parameters
    ----------
    boxes : a tuple (center, axes, extents), a Parallelepiped, or a list of them
        As for :func:`intersects_oriented`, with any axes (rows).
    cylinders, algorithm, arithmetic, threads, margin :
        As for :func:`intersects_aligned`.

    Returns
    -------
    numpy.ndarray of bool, shape (N,)

    Each pair is answered by the scalar query (exact by default), on ``threads`` threads with the GIL
    released; Ctrl-C stops it.
    """
    box_arrays, box_single = _frame_boxes(boxes, _core.Parallelepiped)
    cyl, cylinder_single = _cylinders(cylinders)
    _check_lengths(box_arrays + cyl)
    return _core._intersects_parallelepiped(*box_arrays, box_single, *cyl, cylinder_single,
                                            *_options(algorithm, arithmetic), _threads(threads), _margin(margin))


# ---- The batch distances. ----------------------------------------------------------------------------

class Distances(_typing.NamedTuple):
    """The distances of a batch (:func:`distances_aligned` etc.): float64 arrays, element i as
    :func:`distance` gives it for pair i — ``lower`` and ``upper`` of shape (N,), ``on_box`` and
    ``on_cylinder`` of shape (N, 3)."""

    lower: _np.ndarray
    upper: _np.ndarray
    on_box: _np.ndarray
    on_cylinder: _np.ndarray


def distances_aligned(boxes, cylinders, *, threads=None):
    """The distance of each axis-aligned box to its cylinder, for arrays of them.

    Parameters
    ----------
    boxes, cylinders :
        As for :func:`intersects_aligned` (one box or one cylinder is used with every element).
    threads : int or None, optional
        How many threads answer (None or 0, the default: all cores; small batches use fewer).

    Returns
    -------
    Distances
        ``(lower, upper, on_box, on_cylinder)`` arrays of shapes (N,), (N,), (N, 3), (N, 3); element
        i is :func:`distance` of pair i, exactly.

    Raises
    ------
    ValueError
        For a wrong shape or kind of input, or the first invalid element, named
        (``"boxes[3].min[1]: is NaN"``). No answer is returned unless every element is valid.
    KeyboardInterrupt
        Ctrl-C stops a running batch.

    Each pair is answered by the scalar :func:`distance` (tens of microseconds each; no SIMD
    filter), on ``threads`` threads with the GIL released.
    """
    box_arrays, box_single = _aligned_boxes(boxes)
    cyl, cylinder_single = _cylinders(cylinders)
    _check_lengths(box_arrays + cyl)
    return Distances(*_core._distances_aligned(*box_arrays, box_single, *cyl, cylinder_single, _threads(threads)))


def distances_oriented(boxes, cylinders, *, threads=None):
    """The distance of each oriented box to its cylinder, for arrays of them.

    ``boxes`` as for :func:`intersects_oriented`; ``cylinders``, ``threads``, the result and the
    errors as for :func:`distances_aligned`.
    """
    box_arrays, box_single = _frame_boxes(boxes)
    cyl, cylinder_single = _cylinders(cylinders)
    _check_lengths(box_arrays + cyl)
    return Distances(*_core._distances_oriented(*box_arrays, box_single, *cyl, cylinder_single, _threads(threads)))


def distances_parallelepiped(boxes, cylinders, *, threads=None):
    """The distance of each parallelepiped to its cylinder, for arrays of them.

    ``boxes`` as for :func:`intersects_parallelepiped`; ``cylinders``, ``threads``, the result and
    the errors as for :func:`distances_aligned`.
    """
    box_arrays, box_single = _frame_boxes(boxes, _core.Parallelepiped)
    cyl, cylinder_single = _cylinders(cylinders)
    _check_lengths(box_arrays + cyl)
    return Distances(*_core._distances_parallelepiped(*box_arrays, box_single, *cyl, cylinder_single,
                                                     _threads(threads)))


class SignedDistances(_typing.NamedTuple):
    """The signed distances of a batch (:func:`signed_distances_aligned` etc.): float64 arrays,
    element i as :func:`signed_distance` gives it for pair i — ``lower`` and ``upper`` of shape (N,),
    ``normal``, ``on_box`` and ``on_cylinder`` of shape (N, 3)."""

    lower: _np.ndarray
    upper: _np.ndarray
    normal: _np.ndarray
    on_box: _np.ndarray
    on_cylinder: _np.ndarray


def signed_distances_aligned(boxes, cylinders, *, threads=None):
    """The signed distance of each axis-aligned box to its cylinder, for arrays of them.

    Parameters
    ----------
    boxes, cylinders :
        As for :func:`intersects_aligned` (one box or one cylinder is used with every element).
    threads : int or None, optional
        How many threads answer (None or 0, the default: all cores; small batches use fewer).

    Returns
    -------
    SignedDistances
        ``(lower, upper, normal, on_box, on_cylinder)`` arrays of shapes (N,), (N,), (N, 3), (N, 3),
        (N, 3); element i is :func:`signed_distance` of pair i, exactly.

    Raises
    ------
    ValueError
        For a wrong shape or kind of input, or the first invalid element, named
        (``"boxes[3].min[1]: is NaN"``). No answer is returned unless every element is valid.
    KeyboardInterrupt
        Ctrl-C stops a running batch.

    Each pair is answered by the scalar :func:`signed_distance` (no SIMD filter), on ``threads``
    threads with the GIL released.
    """
    box_arrays, box_single = _aligned_boxes(boxes)
    cyl, cylinder_single = _cylinders(cylinders)
    _check_lengths(box_arrays + cyl)
    return SignedDistances(*_core._signed_distances_aligned(*box_arrays, box_single, *cyl, cylinder_single,
                                                            _threads(threads)))


def signed_distances_oriented(boxes, cylinders, *, threads=None):
    """The signed distance of each oriented box to its cylinder, for arrays of them.

    ``boxes`` as for :func:`intersects_oriented`; ``cylinders``, ``threads``, the result and the
    errors as for :func:`signed_distances_aligned`.
    """
    box_arrays, box_single = _frame_boxes(boxes)
    cyl, cylinder_single = _cylinders(cylinders)
    _check_lengths(box_arrays + cyl)
    return SignedDistances(*_core._signed_distances_oriented(*box_arrays, box_single, *cyl, cylinder_single,
                                                             _threads(threads)))


def signed_distances_parallelepiped(boxes, cylinders, *, threads=None):
    """The signed distance of each parallelepiped to its cylinder, for arrays of them.

    ``boxes`` as for :func:`intersects_parallelepiped`; ``cylinders``, ``threads``, the result and
    the errors as for :func:`signed_distances_aligned`.
    """
    box_arrays, box_single = _frame_boxes(boxes, _core.Parallelepiped)
    cyl, cylinder_single = _cylinders(cylinders)
    _check_lengths(box_arrays + cyl)
    return SignedDistances(*_core._signed_distances_parallelepiped(*box_arrays, box_single, *cyl, cylinder_single,
                                                                   _threads(threads)))


# ---- The grid query. ---------------------------------------------------------------------------------

def _counts(value):
    """Three cell counts as Python ints, or a ValueError naming grid.counts."""
    if isinstance(value, _np.ndarray):
        items = value.tolist() if value.ndim == 1 else None
    elif isinstance(value, (list, tuple)):
        items = list(value)
    else:
        items = None
    if items is None or len(items) != 3:
        raise ValueError(f"grid.counts: expected 3 integers, got {value!r}")
    for k, x in enumerate(items):
        if isinstance(x, (bool, _np.bool_)) or not isinstance(x, _numbers.Integral):
            raise ValueError(f"grid.counts[{k}]: is {_a(type(x).__name__)} ({x!r}); expected an integer")
        if x > 1 << 53:
            raise ValueError(f"grid.counts[{k}]: exceeds 2^53")
        if x < 0:
            raise ValueError(f"grid.counts[{k}]: is negative")
    return tuple(int(x) for x in items)


def grid_cells(origin, cell_size, counts, cylinder, *, max_cells=None, margin=None):
    """The cells of a regular axis-aligned grid that the cylinder intersects, exactly (or, with
    ``margin``, the cells within that distance of it).

    Cell ``(i, j, k)``, ``0 <= i < counts[0]`` etc., is the closed box whose bounds along each axis
    are ``fma(n, cell_size, origin)`` — ``origin + n*cell_size`` rounded once to the nearest float64
    — for ``n = i`` and ``i + 1`` (``j``, ``j + 1`` along y; ``k``, ``k + 1`` along z). Adjacent
    cells share their faces exactly and tile the grid's box. A cell is listed if and only if
    :func:`intersects` (the exact default: closed solids, touching counts) is true for that box —
    the cells of C++'s ``boxcyl::cells(grid, cylinder)`` and of ``boxcyl grid``.

    Parameters
    ----------
    origin, cell_size : array_like (3,)
        The grid's corner and its cells' sides (> 0 each).
    counts : 3 integers
        Cells per axis, 0 to 2^53 (0: no cells); the far bound ``origin + counts*cell_size`` must
        stay within the float64 range.
    cylinder : Cylinder
    max_cells : int or None, optional
        Refuse (``ValueError``) an answer of more cells than this, found without listing them all.
    margin : float, optional
        A distance >= 0: list the cells for which ``intersects(cell, cylinder, margin=margin)`` is
        true (C++'s ``boxcyl::cells_within``), exactly.

    Returns
    -------
    numpy.ndarray of int64, shape (M, 3)
        The cells' indices, in lexicographic order of (i, j, k).

    The walk discards blocks of cells that miss the cylinder with one exact query each, so its cost
    grows with the cells near the cylinder's surface, not with the grid's size; it runs with the GIL
    released, and Ctrl-C stops it.
    """
    if not isinstance(cylinder, _core.Cylinder):
        raise ValueError(f"cylinder: expected a Cylinder, got {_type_name(cylinder)}")
    if max_cells is None:
        limit = -1
    elif isinstance(max_cells, (bool, _np.bool_)) or not isinstance(max_cells, _numbers.Integral) or max_cells < 0:
        raise ValueError(f"max_cells: expected a non-negative integer or None; got {max_cells!r}")
    else:
        limit = min(int(max_cells), (1 << 63) - 1)
    m = 0.0 if margin is None else _scalar("margin", margin)
    return _core._grid_cells(_vector("grid.origin", origin), _vector("grid.cell_size", cell_size), _counts(counts),
                             cylinder, m, limit)
