"""Ctrl-C stops a long batch: the batch runs in chunks with the GIL released while the calling thread
runs Python's signal handlers between them, so SIGINT raises KeyboardInterrupt within milliseconds
instead of after the whole batch.

Each case runs in a child interpreter (a KeyboardInterrupt in pytest's own process would end the
session): it starts a batch that takes seconds, sends itself SIGINT from a timer thread, and prints
how long the interrupt took to arrive. The bound asserted here (1 s, against batches of several
seconds) leaves room for a loaded machine; the typical figure is printed (pytest -s) and measured by
bench/python_batch.py.
"""
import json
import os
import subprocess
import sys
import textwrap

import pytest

CHILD = textwrap.dedent("""
    import json, os, signal, sys, threading, time
    import numpy as np
    import boxcyl

    form, threads = sys.argv[1], int(sys.argv[2])
    cyl = boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 5), radius=2, height=1)
    if form == "batch":
        # One cylinder, 10^8 boxes (a broadcast view: no memory for the boxes): the batch API path.
        boxes = np.broadcast_to(np.array([[-1.0, -1, -1], [1, 1, 1]]), (100_000_000, 2, 3))
        call = lambda: boxcyl.intersects_aligned(boxes, cyl, threads=threads)
    else:
        # The exact oracle on 10^6 boxes, each against its own cylinder: the scalar path.
        rng = np.random.default_rng(5)
        lo = rng.uniform(-3, 3, (1_000_000, 3))
        cyls = (np.tile(cyl.center, (1_000_000, 1)), cyl.axis, cyl.radius, cyl.height)
        call = lambda: boxcyl.intersects_aligned((lo, lo + 1), cyls, algorithm="oracle", threads=threads)
    sent = []
    def interrupt():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)
    timer = threading.Timer(0.5, interrupt)
    start = time.perf_counter()
    timer.start()
    try:
        call()
        print(json.dumps({"interrupted": False, "ran_s": time.perf_counter() - start}))
    except KeyboardInterrupt:
        now = time.perf_counter()
        # After the interrupt the module answers again, normally.
        again = boxcyl.intersects_aligned(np.broadcast_to(np.array([[-1.0, -1, -1], [1, 1, 1]]), (70_000, 2, 3)), cyl)
        print(json.dumps({"interrupted": True, "latency_s": now - sent[0], "ran_s": now - start,
                          "then": bool(again.all()) and again.shape == (70_000,)}))
""")


@pytest.mark.parametrize("form, threads", [("batch", 1), ("batch", 2), ("scalar", 1), ("scalar", 2)])
def test_ctrl_c_interrupts_a_long_batch_promptly(form, threads):
    env = dict(os.environ)
    done = subprocess.run([sys.executable, "-c", CHILD, form, str(threads)], capture_output=True, text=True,
                          timeout=300, env=env)
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout.strip().splitlines()[-1])
    print(form, threads, result)
    assert result["interrupted"], f"the batch finished ({result['ran_s']:.2f} s) before SIGINT arrived"
    assert result["latency_s"] < 1.0, result
    assert result["then"]
