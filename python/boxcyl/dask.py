"""Batches past one machine's memory: Dask arrays of boxes against one cylinder.

>>> import dask.array as da
>>> import boxcyl, boxcyl.dask
>>> boxes = da.from_array(np.array([[[-1, -1, -1], [1, 1, 1]]] * 6, dtype=float), chunks=(4, 2, 3))
>>> cyl = boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 5), radius=2, height=1)
>>> boxcyl.dask.intersects_aligned(boxes, cyl).compute().tolist()
[True, True, True, True, True, True]

Each block of boxes is answered by the numpy batch form (:func:`boxcyl.intersects_aligned`,
:func:`boxcyl.intersects_oriented`, :func:`boxcyl.intersects_parallelepiped`) where Dask runs it: in a thread, a process, or a worker of a
``distributed`` cluster. The answer is a lazy Dask array of bools (one byte per box) with the boxes'
chunks along the first axis; reduce it (``.sum()``, ``.nonzero()``) or store it (``.to_zarr``) so that
neither boxes nor answers need to fit in memory at once. The cylinder, the options and the margin
travel with each task (shapes pickle). With ``margin=m`` each answer is whether the box comes within
distance m of the cylinder (the clearance query, exact). The answers equal one call of the numpy form
on the whole array, and the input is refused as the numpy form refuses it (booleans, complex
numbers, strings, NaN, ...), an invalid box named by its index in the whole array.

Within a block, ``threads`` (default 1) threads answer: Dask already runs blocks in parallel; give
more for few large blocks.
"""
import re

import dask.array as da
import numpy as np

import boxcyl

__all__ = ["intersects_aligned", "intersects_oriented", "intersects_parallelepiped"]


def _cylinder(cylinder):
    if not isinstance(cylinder, boxcyl.Cylinder):
        raise ValueError(f"cylinder: expected a boxcyl.Cylinder, got {type(cylinder).__name__}")
    return cylinder


def _rows(name, array, tail):
    """``array`` as a Dask array of shape (N, *tail), chunked along the first axis only."""
    if not isinstance(array, da.Array):
        array = da.asarray(array)
    if array.ndim != len(tail) + 1 or array.shape[1:] != tail:
        expected = ", ".join(["N"] + [str(t) for t in tail])
        raise ValueError(f"{name}: expected a Dask array of shape ({expected}), got {array.shape}")
    if array.numblocks[1:] != (1,) * len(tail):
        array = array.rechunk({k: -1 for k in range(1, array.ndim)})
    return array


def _renamed(error, block_info):
    """A block's ValueError with its element index made global ("boxes[17]" in a block that starts at
    1000 is "boxes[1017]")."""
    start = block_info[0]["array-location"][0][0]
    message = re.sub(r"\bboxes\[(\d+)\]", lambda m: f"boxes[{int(m.group(1)) + start}]", str(error))
    return ValueError(message)


def _aligned_block(block, cylinder, algorithm, arithmetic, threads, margin, block_info=None):
    try:
        return boxcyl.intersects_aligned(block, cylinder, algorithm=algorithm, arithmetic=arithmetic,
                                         threads=threads, margin=margin)
    except ValueError as e:
        raise _renamed(e, block_info) from None


def _frame_block(rows, form, cylinder, algorithm, arithmetic, threads, margin, block_info=None):
    boxes = (rows[:, 0:3], rows[:, 3:12].reshape(-1, 3, 3), rows[:, 12:15])
    try:
        return form(boxes, cylinder, algorithm=algorithm, arithmetic=arithmetic, threads=threads, margin=margin)
    except ValueError as e:
        raise _renamed(e, block_info) from None


def _margin(cylinder, margin):
    """The margin refused now, as the numpy form refuses it, rather than when the graph is computed."""
    if margin is not None:
        boxcyl.intersects_aligned(np.empty((0, 2, 3)), cylinder, margin=margin)
    return margin


def _real_dtype(name, array):
    """What the numpy form refuses by dtype, refused before the fields are joined into one array (a
    join would turn booleans into 0 and 1, or make every field complex)."""
    kind = array.dtype.kind
    if kind not in "iufO":
        _, many = boxcyl._REFUSED_KINDS.get(kind, ("a value", "an array of values"))
        raise ValueError(f"{name}: is {many} (dtype {array.dtype}); expected real numbers")


def _frames(boxes, cylinder, form, algorithm, arithmetic, threads, margin):
    """The oriented and parallelepiped forms: (center, axes, extents) joined into (N, 15) rows whose
    blocks hold whole boxes, each block split again and answered by `form`."""
    if not isinstance(boxes, tuple) or len(boxes) != 3:
        raise ValueError("boxes: expected a tuple (center, axes, extents) of Dask arrays")
    center = _rows("boxes.center", boxes[0], (3,))
    axes = _rows("boxes.axes", boxes[1], (3, 3))
    extents = _rows("boxes.extents", boxes[2], (3,))
    if not axes.shape[0] == extents.shape[0] == center.shape[0]:
        raise ValueError(f"boxes: lengths {center.shape[0]}, {axes.shape[0]}, {extents.shape[0]} differ")
    for name, array in (("boxes.center", center), ("boxes.axes", axes), ("boxes.extents", extents)):
        _real_dtype(name, array)
    # One (N, 15) array: center, axes (row by row), extents; each block holds whole boxes.
    rows = da.concatenate([center, axes.reshape(-1, 9), extents], axis=1).rechunk({0: center.chunks[0], 1: -1})
    cylinder = _cylinder(cylinder)
    return da.map_blocks(_frame_block, rows, form, cylinder, algorithm, arithmetic, threads, _margin(cylinder, margin),
                         drop_axis=[1], dtype=np.bool_, meta=np.empty((0,), dtype=np.bool_))


def intersects_aligned(boxes, cylinder, *, algorithm="inequalities", arithmetic="filtered", threads=1,
                       margin=None):
    """Whether each axis-aligned box of a Dask array intersects one cylinder.

    Parameters
    ----------
    boxes : dask.array.Array of shape (N, 2, 3), ``boxes[i] = [min, max]``
        Any dtype :func:`boxcyl.intersects_aligned` accepts; chunked along the first axis (other
        chunkings are rechunked so that each block holds whole boxes).
    cylinder : boxcyl.Cylinder
    algorithm, arithmetic, threads, margin :
        As for :func:`boxcyl.intersects_aligned`; ``threads`` is per block (default 1). With
        ``margin``, each answer is ``dist(box, cylinder) <= margin``, exactly; a bad margin is
        refused at once (ValueError naming ``margin``).

    Returns
    -------
    dask.array.Array of bool, shape (N,), chunks those of ``boxes`` along the first axis
        Lazy; an invalid box raises ValueError when computed, naming it by its index in ``boxes``.
    """
    boxes = _rows("boxes", boxes, (2, 3))
    cylinder = _cylinder(cylinder)
    return da.map_blocks(_aligned_block, boxes, cylinder, algorithm, arithmetic, threads, _margin(cylinder, margin),
                         drop_axis=[1, 2], dtype=np.bool_, meta=np.empty((0,), dtype=np.bool_))


def intersects_oriented(boxes, cylinder, *, algorithm="inequalities", arithmetic="filtered", threads=1,
                        margin=None):
    """Whether each oriented box of Dask arrays intersects one cylinder.

    Parameters
    ----------
    boxes : a tuple (center, axes, extents) of dask.array.Array
        Shapes (N, 3), (N, 3, 3) (rows are the box axes) and (N, 3) (half side lengths), as for
        :func:`boxcyl.intersects_oriented`; rechunked to the chunks of ``center`` along the first axis.
    cylinder : boxcyl.Cylinder
    algorithm, arithmetic, threads, margin :
        As for :func:`intersects_aligned`.

    Returns
    -------
    dask.array.Array of bool, shape (N,), chunks those of ``center`` along the first axis
    """
    return _frames(boxes, cylinder, boxcyl.intersects_oriented, algorithm, arithmetic, threads, margin)


def intersects_parallelepiped(boxes, cylinder, *, algorithm="inequalities", arithmetic="filtered", threads=1,
                              margin=None):
    """Whether each parallelepiped of Dask arrays intersects one cylinder.

    Parameters
    ----------
    boxes : a tuple (center, axes, extents) of dask.array.Array
        As for :func:`intersects_oriented`, with any axes (rows), as for
        :func:`boxcyl.intersects_parallelepiped`.
    cylinder : boxcyl.Cylinder
    algorithm, arithmetic, threads, margin :
        As for :func:`intersects_aligned`.

    Returns
    -------
    dask.array.Array of bool, shape (N,), chunks those of ``center`` along the first axis
    """
    return _frames(boxes, cylinder, boxcyl.intersects_parallelepiped, algorithm, arithmetic, threads, margin)
