"""The Python batch forms against the C++ batch they wrap, in one run, on the same boxes.

    cmake --build build --target boxcyl_python boxcyl_python_bench
    PYTHONPATH=build/python /usr/bin/python3 bench/python_batch.py [--boxes 1000000] [--repeat 15]

For aligned boxes (an (N, 2, 3) float64 array, boxes around one cylinder, about 10 % hitting) and
oriented boxes (center, axes, extents arrays), it times

  python   boxcyl.intersects_aligned / intersects_oriented: argument checks, the chunked gather and
           validation of every box, and the batch API, as a user calls them;
  c++      boxcyl::batch::intersects alone (the module _boxcyl_bench, bench/python_batch_core.cpp, built
           with the benchmarks and never part of the package), on the structure-of-arrays (aligned)
           or OrientedBox array (oriented) it takes, prepared beforehand and timed inside C++;
  c++ rows boxcyl::batch::intersects alone on the (N, 2, 3) array itself, read in place as
           AlignedBox<double> rows (aligned only; the form the Python aligned batch calls);
  c++ +    the same as c++ plus numpy's copy of the (N, 2, 3) array into the six arrays
  layout   (what a caller holding boxes as [min, max] rows would pay without the rows form; aligned only);

each with one thread and with all cores (threads=None / 0), interleaved, `--repeat` times. It prints
the fastest wall time and the fastest process CPU time (all threads) of each, and the ratios of the
python form to each C++ baseline. On a machine shared with other work the CPU times are the steadier figures.
Last, the Ctrl-C latency: SIGINT sent to a batch of 10^8 exactly touching boxes (each one left to the
exact fallback), the time until KeyboardInterrupt arrives, over five tries.
"""
import argparse
import os
import signal
import statistics
import threading
import time

import numpy as np

import boxcyl
from boxcyl import _core

try:
    import _boxcyl_bench as cpp
except ImportError:
    raise SystemExit("bench/python_batch.py: the module _boxcyl_bench is missing; build it beside boxcyl "
                     "(cmake --build build --target boxcyl_python_bench, or configure with "
                     "-DBOXCYL_BUILD_BENCHMARKS=ON)") from None


def best(samples):
    return min(s[0] for s in samples), min(s[1] for s in samples)


def timed(call):
    w, c = time.perf_counter(), time.process_time()
    call()
    return time.perf_counter() - w, time.process_time() - c


def cpp_cylinder(cyl):
    """The cylinder as _boxcyl_bench takes it: center, axis, radius, height."""
    return (cyl.center, cyl.axis, cyl.radius, cyl.height)


def aligned_case(rng, n):
    lo = rng.uniform(-5, 5, (n, 3))
    boxes = np.stack([lo, lo + rng.uniform(0, 1, (n, 3))], axis=1)
    cyl = boxcyl.Cylinder(center=(0, 0, 0), axis=(1, 2, 3), radius=2, height=5)
    return boxes, cyl


def oriented_case(rng, n):
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    w, x, y, z = q.T
    rows = np.stack([  # the rotation's rows are the box axes
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)], axis=1),
        np.stack([2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)], axis=1),
        np.stack([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)], axis=1),
    ], axis=1)
    center = rng.uniform(-5, 5, (n, 3))
    extents = rng.uniform(0, 0.5, (n, 3))
    cyl = boxcyl.Cylinder(center=(0, 0, 0), axis=(1, 2, 3), radius=2, height=5)
    return (center, rows, extents), cyl


def measure(name, python_call, baselines, repeat):
    """baselines: (label, call) pairs; each call returns (wall, cpu) seconds of its timed part."""
    py, base = [], [[] for _ in baselines]
    for _ in range(repeat):
        py.append(timed(python_call))
        for samples, (_, call) in zip(base, baselines):
            samples.append(call())
    pw, pc = best(py)
    print(f"{name:<22} python {pw * 1e3:8.2f} ms wall {pc * 1e3:8.2f} ms cpu")
    for samples, (label, _) in zip(base, baselines):
        bw, bc = best(samples)
        print(f"{'':<22} {label:<14} {bw * 1e3:8.2f} ms wall {bc * 1e3:8.2f} ms cpu | python/({label}) "
              f"{pw / bw:5.2f} wall {pc / bc:5.2f} cpu")


def interrupt_latency(tries):
    cyl = boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 5), radius=2, height=1)
    boxes = np.broadcast_to(np.array([[-1.0, -1, -1], [1, 1, 1]]), (100_000_000, 2, 3))  # all touching
    latencies = []
    for _ in range(tries):
        sent = []
        timer = threading.Timer(0.3, lambda: (sent.append(time.perf_counter()), os.kill(os.getpid(), signal.SIGINT)))
        timer.start()
        try:
            boxcyl.intersects_aligned(boxes, cyl, threads=1)
            raise SystemExit("the batch ended before SIGINT")
        except KeyboardInterrupt:
            latencies.append(time.perf_counter() - sent[0])
    return latencies


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--boxes", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=15)
    args = parser.parse_args()
    rng = np.random.default_rng(20261126)
    n = args.boxes
    print(f"boxcyl {boxcyl.__version__}, {n} boxes, {_core._hardware_threads()} hardware threads, "
          f"best of {args.repeat}")

    boxes, cyl = aligned_case(rng, n)
    ccyl = cpp_cylinder(cyl)
    soa = np.ascontiguousarray(np.moveaxis(boxes, 0, -1).reshape(6, n))  # min_x, min_y, min_z, max_x, ...
    expected, _, _ = cpp.aligned(soa, *ccyl, 1)
    assert np.array_equal(boxcyl.intersects_aligned(boxes, cyl), expected)
    assert np.array_equal(cpp.aligned_rows(boxes, *ccyl, 1)[0], expected)
    print(f"aligned: {expected.mean() * 100:.1f} % hit")

    def layout_and_batch(threads):
        w, c = time.perf_counter(), time.process_time()
        s = np.ascontiguousarray(np.moveaxis(boxes, 0, -1).reshape(6, n))
        lw, lc = time.perf_counter() - w, time.process_time() - c
        _, bw, bc = cpp.aligned(s, *ccyl, threads)
        return lw + bw, lc + bc

    for threads in (1, None):
        t = 0 if threads is None else threads
        measure(f"aligned, threads={threads}", lambda: boxcyl.intersects_aligned(boxes, cyl, threads=threads),
                [("c++", lambda: cpp.aligned(soa, *ccyl, t)[1:]),
                 ("c++ rows", lambda: cpp.aligned_rows(boxes, *ccyl, t)[1:]),
                 ("c++ + layout", lambda: layout_and_batch(t))], args.repeat)

    (center, axes, extents), cyl = oriented_case(rng, n)
    ccyl = cpp_cylinder(cyl)
    rows = np.concatenate([center, axes.reshape(n, 9), extents], axis=1)
    expected, _, _ = cpp.oriented(rows, *ccyl, 1)
    assert np.array_equal(boxcyl.intersects_oriented((center, axes, extents), cyl), expected)
    print(f"oriented: {expected.mean() * 100:.1f} % hit")
    for threads in (1, None):
        t = 0 if threads is None else threads
        measure(f"oriented, threads={threads}",
                lambda: boxcyl.intersects_oriented((center, axes, extents), cyl, threads=threads),
                [("c++", lambda: cpp.oriented(rows, *ccyl, t)[1:])], args.repeat)

    lat = interrupt_latency(5)
    print(f"Ctrl-C: KeyboardInterrupt {statistics.median(lat) * 1e3:.1f} ms after SIGINT (median of 5, "
          f"max {max(lat) * 1e3:.1f} ms)")


if __name__ == "__main__":
    main()
