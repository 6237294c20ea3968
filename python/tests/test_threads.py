"""Four Python threads each meshing a million-point set at once: the same
meshes as one at a time, and the GIL released meanwhile (a Python thread
counting all along is never held up for long)."""
import threading
import time

import numpy as np

import gpdr

POINTS = 1_000_000
SETS = 4


def test_four_threads_at_once_and_the_gil_released():
    point_sets = [np.random.default_rng(seed).random((POINTS, 2)) for seed in range(SETS)]
    one_at_a_time = [gpdr.delaunay(points) for points in point_sets]

    at_once = [None] * SETS
    start = threading.Barrier(SETS + 1)

    def mesh(i):
        start.wait()
        at_once[i] = gpdr.delaunay(point_sets[i])

    ticks = []
    counting = threading.Event()
    done = threading.Event()

    def count():
        counting.set()
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    counting.wait()
    workers = [threading.Thread(target=mesh, args=(i,)) for i in range(SETS)]
    for worker in workers:
        worker.start()
    start.wait()
    began = time.perf_counter()
    for worker in workers:
        worker.join()
    ended = time.perf_counter()
    done.set()
    counter.join()

    for alone, together in zip(one_at_a_time, at_once):
        assert together.shape == alone.shape and together.shape[0] > 1_900_000
        assert np.array_equal(together, alone)

    # The counter kept counting while the four meshed: its longest pause is
    # a small part of the time they took (holding the GIL, each mesh would
    # stop it for the whole of its own run).
    during = [began] + [t for t in ticks if began < t < ended] + [ended]
    longest_pause = max(b - a for a, b in zip(during, during[1:]))
    assert len(during) > 100
    assert longest_pause < 0.25 * (ended - began), (longest_pause, ended - began)
