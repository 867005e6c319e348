"""The type stubs (boxcyl/__init__.pyi, boxcyl/dask.pyi, py.typed): mypy --strict accepts code that
uses the package as documented and rejects misuse, and mypy's stubtest finds the stubs consistent with
the module they describe (names, signatures, defaults).

Needs mypy (Debian's python3-mypy, installed by scripts/deps.sh).
"""
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import boxcyl

HERE = Path(__file__).resolve().parent
PACKAGE_PARENT = Path(boxcyl.__file__).resolve().parent.parent

GOOD = textwrap.dedent("""
    from fractions import Fraction
    import numpy as np
    import numpy.typing as npt
    import boxcyl
    import boxcyl.dask

    box = boxcyl.AlignedBox(min=(-1, -1, -1), max=np.ones(3))
    obox = boxcyl.OrientedBox(center=(0, 0, 0), axes=np.eye(3), extents=[1, 2, 3])
    cyl = boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 5), radius=Fraction(2), height=1.0)
    hit: bool = boxcyl.intersects(box, cyl, algorithm="hull", arithmetic=boxcyl.Arithmetic.exact)
    hit = boxcyl.intersects(obox, cyl)
    lo: float = box.min[0] + cyl.radius + obox.axes[2][1]
    hits: npt.NDArray[np.bool_] = boxcyl.intersects_aligned(np.zeros((4, 2, 3)), cyl, threads=2)
    hits = boxcyl.intersects_aligned((np.zeros((4, 3)), np.ones((4, 3))), (np.zeros((4, 3)), (0, 0, 1), 1.0, 2.0))
    hits = boxcyl.intersects_aligned([box, box], [cyl, cyl], threads=None)
    hits = boxcyl.intersects_oriented((np.zeros((4, 3)), np.tile(np.eye(3), (4, 1, 1)), np.ones((4, 3))), cyl)
    lazy = boxcyl.dask.intersects_aligned(np.zeros((4, 2, 3)), cyl, threads=1)
    pbox = boxcyl.Parallelepiped(center=(0, 0, 0), axes=((3, 4, 0), (-4, 3, 0), (0, 0, 5)), extents=(1, 1, 1))
    hit = boxcyl.intersects(pbox, cyl)
    hits = boxcyl.intersects_parallelepiped([pbox], cyl)
    posed: boxcyl.OrientedBox = boxcyl.OrientedBox.from_quaternion((0, 0, 0), xyzw=(0, 0, 0, 1), size=(2, 2, 2))
    posed = boxcyl.OrientedBox.from_transform(np.eye(4), half_extents=(1, 1, 1))
    tube: boxcyl.Cylinder = boxcyl.Cylinder.from_rotation((0, 0, 0), np.eye(3), radius=1, half_height=2, along="y")
    same: bool = box == boxcyl.AlignedBox((-1, -1, -1), (1, 1, 1))
    rod: boxcyl.Cylinder = boxcyl.Cylinder.from_endpoints((0, 0, 0), [0, 0, 2], radius=0.5)
    sheared: boxcyl.Parallelepiped = boxcyl.Parallelepiped.from_transform(np.diag([2.0, 1, 1, 1]), size=(1, 1, 1))
    cells: npt.NDArray[np.int64] = boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (4, 4, 4), rod, max_cells=100)
    hits = boxcyl.intersects_parallelepiped([sheared], rod, threads=0)
    lazy = boxcyl.dask.intersects_parallelepiped((np.zeros((4, 3)), np.zeros((4, 3, 3)), np.ones((4, 3))), rod)
    gap: boxcyl.Distance = boxcyl.distance(pbox, cyl)
    lo = gap.lower + gap.upper + gap.on_box[0] + gap.on_cylinder[2]
    gaps: boxcyl.Distances = boxcyl.distances_aligned(np.zeros((4, 2, 3)), cyl, threads=2)
    bounds: npt.NDArray[np.float64] = gaps.lower
    gaps = boxcyl.distances_oriented([obox], [cyl])
    gaps = boxcyl.distances_parallelepiped((np.zeros((4, 3)), np.zeros((4, 3, 3)), np.ones((4, 3))), rod, threads=None)
    depth: boxcyl.SignedDistance = boxcyl.signed_distance(obox, rod)
    lo = depth.lower + depth.upper + depth.normal[0] + depth.on_box[1] + depth.on_cylinder[2]
    depths: boxcyl.SignedDistances = boxcyl.signed_distances_aligned([box], cyl, threads=1)
    bounds = depths.normal
    depths = boxcyl.signed_distances_oriented((np.zeros((4, 3)), np.tile(np.eye(3), (4, 1, 1)), np.ones((4, 3))), rod)
    depths = boxcyl.signed_distances_parallelepiped([pbox], cyl, threads=None)
    print(boxcyl.__version__, boxcyl.Algorithm.oracle.name, hash(cyl))
""")

BAD = textwrap.dedent("""
    import boxcyl

    box = boxcyl.AlignedBox(min=(-1, -1, -1), max=(1, 1, 1))
    cyl = boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 5), radius="2", height=1)
    boxcyl.intersects(box, cyl, algorithm="simplex")
    boxcyl.intersects(box, box)
    boxcyl.intersects_aligned(box, cyl, threads=1.5)
    n: int = box.min
    boxcyl.Cylinder.from_rotation((0, 0, 0), ((1, 0, 0), (0, 1, 0), (0, 0, 1)), radius=1, height=1, along="w")
    boxcyl.grid_cells((0, 0, 0), (1, 1, 1), (4, 4, 4), box)
    boxcyl.distance(box, cyl, margin=1.0)
    far: str = boxcyl.distance(box, cyl).upper
""")


def mypy(tmp_path, source, *args):
    path = tmp_path / "sample.py"
    path.write_text(source)
    env = dict(os.environ)
    if PACKAGE_PARENT.name not in ("site-packages", "dist-packages"):
        env["MYPYPATH"] = str(PACKAGE_PARENT)  # a build tree or a --target directory
    return subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-error-summary", "--python-executable",
                           sys.executable, "--cache-dir", str(tmp_path / "cache"), *args, str(path)],
                          capture_output=True, text=True, env=env, cwd=tmp_path)


def test_mypy_strict_accepts_documented_use(tmp_path):
    done = mypy(tmp_path, GOOD)
    assert done.returncode == 0, done.stdout + done.stderr


def test_mypy_rejects_misuse_line_by_line(tmp_path):
    done = mypy(tmp_path, BAD)
    lines = sorted({int(line.split(":")[1]) for line in done.stdout.splitlines() if ": error:" in line})
    assert lines == [5, 6, 7, 8, 9, 10, 11, 12, 13], done.stdout


def test_stubtest_finds_the_stubs_consistent_with_the_module(tmp_path):
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(PACKAGE_PARENT)] + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    done = subprocess.run([sys.executable, "-m", "mypy.stubtest", "boxcyl", "--allowlist",
                           str(HERE / "stubtest_allowlist.txt")], capture_output=True, text=True, env=env,
                          cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
