"""Exact box–cylinder intersection queries.

Does this finite cylinder intersect this box? ``boxcyl`` answers exactly for the float64 values
given (closed solids: touching counts), for axis-aligned and oriented boxes, one query at a time or
over numpy arrays.

>>> import boxcyl
>>> box = boxcyl.AlignedBox(min=(-1, -1, -1), max=(1, 1, 1))
>>> cyl = boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 5), radius=2, height=1)
>>> boxcyl.intersects(box, cyl)  # the side touches the face x = 1
True

Batch forms take arrays and return a numpy bool array; see :func:`intersects_aligned` and
:func:`intersects_oriented`. Invalid input (NaN, ±Inf, a zero axis, negative sizes, min > max,
axes not orthonormal to 1e-4) raises ``ValueError`` naming the field, and the element in a batch:
``"boxes[17].max[0]: is less than boxes[17].min[0]"``.
"""

import numpy as np

from ._core import (
    AlignedBox,
    Algorithm,
    Arithmetic,
    Cylinder,
    OrientedBox,
    __version__,
)
from . import _core

__all__ = [
    "AlignedBox",
    "Algorithm",
    "Arithmetic",
    "Cylinder",
    "OrientedBox",
    "intersects",
    "intersects_aligned",
    "intersects_oriented",
    "__version__",
]


def _field(name, value, tail):
    """``value`` as a C-contiguous float64 array of shape (M, *tail); single=True if it had no M."""
    a = np.asarray(value, dtype=np.float64)
    if a.shape == tail:
        return np.ascontiguousarray(a.reshape((1,) + tail)), True
    if a.ndim == len(tail) + 1 and a.shape[1:] == tail:
        return np.ascontiguousarray(a), False
    expected = ", ".join(["N"] + [str(t) for t in tail])
    raise ValueError(f"{name}: expected shape ({expected}) or {tail}, got {a.shape}")


def _fields(kind, names, values, tails):
    """Each field through _field; single=True when every field was given without a leading length."""
    if len(values) != len(names):
        raise ValueError(f"{kind}: expected {len(names)} arrays ({', '.join(names)}), got {len(values)}")
    arrays, singles = zip(*(_field(f"{kind}.{n}", v, t) for n, v, t in zip(names, values, tails)))
    return list(arrays), all(singles)


def _cylinder_arrays(cylinders):
    if isinstance(cylinders, Cylinder):
        c = cylinders
        return _fields("cylinder", ("center", "axis", "radius", "height"),
                       (c.center, c.axis, c.radius, c.height), ((3,), (3,), (), ()))
    if not isinstance(cylinders, (tuple, list)):
        raise TypeError("cylinders: expected a Cylinder or a tuple (center, axis, radius, height) of arrays")
    return _fields("cylinders", ("center", "axis", "radius", "height"), cylinders, ((3,), (3,), (), ()))


def _check_lengths(arrays):
    """The common batch length N: every field's leading length must be N or 1."""
    lengths = {a.shape[0] for a in arrays} - {1}
    if len(lengths) > 1:
        raise ValueError(f"boxes and cylinders: leading lengths {sorted(lengths)} differ (each must be N or 1)")


def _option(kind, name, value):
    if isinstance(value, str):
        if value not in kind.__members__:
            raise ValueError(f"{name}: {value!r} is not one of {', '.join(kind.__members__)}")
        return kind.__members__[value]
    return value


def _options(algorithm, arithmetic):
    return _option(Algorithm, "algorithm", algorithm), _option(Arithmetic, "arithmetic", arithmetic)


def intersects(box, cylinder, *, algorithm=Algorithm.inequalities, arithmetic=Arithmetic.filtered):
    """Whether the closed box and the closed cylinder share a point (touching counts).

    Parameters
    ----------
    box : AlignedBox or OrientedBox
    cylinder : Cylinder
    algorithm : Algorithm or its name, optional
        ``"inequalities"`` (the linear-inequalities method, default), ``"hull"`` (the convex-hull
        method), ``"lcp"`` (convex quadratic programming as an LCP) or ``"oracle"`` (the exact
        reference); docs/algorithms.md describes them.
    arithmetic : Arithmetic or its name, optional
        ``"filtered"`` (default: the exact answer, with a fast certified filter), ``"exact"``, or the
        plain rounded ``"float64"`` / ``"float32"``, which may misjudge inputs within a tiny gap of
        touching.

    Returns
    -------
    bool
        With the defaults, the exact answer for the float64 values given.

    Raises
    ------
    ValueError
        For ``arithmetic="exact"`` with algorithm ``"lcp"`` or ``"inequalities"`` on an
        oriented box whose axes are orthonormal only up to rounding, which they cannot treat
        exactly; the default and ``"hull"`` handle any valid box.
    """
    return _core.intersects(box, cylinder, *_options(algorithm, arithmetic))


def intersects_aligned(boxes, cylinders, *, algorithm=Algorithm.inequalities,
                       arithmetic=Arithmetic.filtered):
    """Whether each axis-aligned box intersects its cylinder, for arrays of them.

    Parameters
    ----------
    boxes : array_like (N, 2, 3), or a tuple (min, max) of array_like (N, 3), or an AlignedBox
        An array (or nested list) has ``boxes[i] = [min, max]``; a tuple is always (min, max).
        A single box (an AlignedBox, shape (2, 3), or (3,) arrays in the tuple) is used with every
        cylinder.
    cylinders : Cylinder, or a tuple (center, axis, radius, height)
        Arrays of shapes (N, 3), (N, 3), (N,), (N,); any field may be given once (shape (3,) or a
        scalar) for all. A single Cylinder is used with every box.
    algorithm, arithmetic : Algorithm / Arithmetic or their names, optional
        The default (``"inequalities"``, ``"filtered"``) is the exact query.

    Returns
    -------
    numpy.ndarray of bool, shape (N,)

    Raises
    ------
    ValueError
        For a wrong shape, or the first invalid element, named: ``"boxes[3].min[1]: is NaN"``.
        Every element is validated before any is answered.

    Inputs are converted to float64 (as ``numpy.asarray`` does); the answer is exact for those
    values. The loop runs in C++ with the GIL released.
    """
    if isinstance(boxes, AlignedBox):
        (lo, hi), box_single = _fields("box", ("min", "max"), (boxes.min, boxes.max), ((3,), (3,)))
    elif isinstance(boxes, tuple):
        (lo, hi), box_single = _fields("boxes", ("min", "max"), boxes, ((3,), (3,)))
    else:
        b = np.asarray(boxes, dtype=np.float64)
        if b.ndim < 2 or b.shape[-2:] != (2, 3) or b.ndim > 3:
            raise ValueError(f"boxes: expected shape (N, 2, 3) or (2, 3), got {b.shape}")
        (lo, hi), box_single = _fields("boxes", ("min", "max"), (b[..., 0, :], b[..., 1, :]), ((3,), (3,)))
    cyl, cylinder_single = _cylinder_arrays(cylinders)
    _check_lengths([lo, hi] + cyl)
    return _core._intersects_aligned(lo, hi, box_single, *cyl, cylinder_single,
                                     *_options(algorithm, arithmetic))


def intersects_oriented(boxes, cylinders, *, algorithm=Algorithm.inequalities,
                        arithmetic=Arithmetic.filtered):
    """Whether each oriented box intersects its cylinder, for arrays of them.

    Parameters
    ----------
    boxes : a tuple (center, axes, extents), or an OrientedBox
        Arrays of shapes (N, 3), (N, 3, 3) with ``axes[i][k]`` the k-th axis of box i, and (N, 3);
        any field may be given once for all. A single OrientedBox is used with every cylinder.
    cylinders : Cylinder, or a tuple (center, axis, radius, height)
        As for :func:`intersects_aligned`.
    algorithm, arithmetic : Algorithm / Arithmetic or their names, optional
        The default is the exact query.

    Returns
    -------
    numpy.ndarray of bool, shape (N,)

    Raises
    ------
    ValueError
        For a wrong shape, or the first invalid element, named (``"boxes[2].axes[0]: is not unit
        length ..."``). Every element is validated before any is answered.
    """
    if isinstance(boxes, OrientedBox):
        fields = (boxes.center, boxes.axes, boxes.extents)
        kind = "box"
    elif isinstance(boxes, (tuple, list)):
        fields = boxes
        kind = "boxes"
    else:
        raise TypeError("boxes: expected an OrientedBox or a tuple (center, axes, extents) of arrays")
    (center, axes, extents), box_single = _fields(kind, ("center", "axes", "extents"), fields,
                                                  ((3,), (3, 3), (3,)))
    cyl, cylinder_single = _cylinder_arrays(cylinders)
    _check_lengths([center, axes, extents] + cyl)
    return _core._intersects_oriented(center, axes, extents, box_single, *cyl, cylinder_single,
                                      *_options(algorithm, arithmetic))

