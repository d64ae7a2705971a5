"""solve_batch releases the GIL: a second Python thread keeps running while a long batch runs."""
import threading
import time

import impact3d
from conftest import SOURCE

import sys
sys.path.insert(0, str(SOURCE / "bench" / "naive"))
import pc_crash as peer  # noqa: E402


def test_another_thread_runs_during_a_batch():
    d = peer.random_collisions(100000, 2)
    d = {k: v.repeat(10) for k, v in d.items()}  # 10^6 rows, velocities on the scalar path: a long call
    started, done = threading.Event(), threading.Event()
    took = []

    def batch():
        started.set()
        t = time.perf_counter()
        impact3d.solve_batch(velocities=True, jobs=1, **d)
        took.append(time.perf_counter() - t)
        done.set()

    worker = threading.Thread(target=batch)
    worker.start()
    started.wait()
    ticks = 0
    while not done.is_set():
        ticks += 1
    worker.join()
    # Held for the whole call, the GIL would let this loop run only between the call's start and its
    # return: a handful of iterations. Released, it runs the whole time, millions a second.
    assert took[0] > 0.1
    assert ticks > 10000 * took[0]
