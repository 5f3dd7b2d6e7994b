"""Simulations in threads give the numbers of a serial loop, and run while the GIL is free
(issue 25)."""

import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import pound
from conftest import study

GAPS = [0.0, 0.001, 0.002, 0.003, 0.004, 0.005, 0.006, 0.008]  # m: every one pounds


def one(gap):
    return pound.simulate(study("ch8-three-five"), contact__model="hc-linear",
                          contact__k_factor=30, pair1__gap=gap, histories=True)


@pytest.mark.filterwarnings("ignore::pound.UnusedKeyWarning")  # the study's slab keys
def test_eight_simulations_in_threads_equal_a_serial_loop():
    serial = [one(g) for g in GAPS]
    with ThreadPoolExecutor(max_workers=4) as pool:
        threaded = list(pool.map(one, GAPS))
    for a, b in zip(serial, threaded):
        ha, hb = a.pop("histories"), b.pop("histories")
        assert a == b
        for run in ("pounding", "free"):
            for name, x in ha[run].items():
                assert np.array_equal(x, hb[run][name], equal_nan=True), (run, name)
    # Different gaps, different results: the comparison is not of eight copies of one.
    peaks = [r["contacts"][0]["peak_force_N"] for r in serial]
    assert len(set(peaks)) == len(GAPS) and min(peaks) > 0


def test_the_gil_is_free_while_the_engine_simulates():
    # A Python thread keeps counting while the other thread is inside pound.simulate: with the
    # GIL held for the whole simulation it would stand still until the call returns.
    counts = []
    done = threading.Event()

    def count():
        n = 0
        while not done.is_set():
            n += 1
        counts.append(n)

    rounds = []
    for _ in range(3):
        t = threading.Thread(target=count)
        counter_before = time.perf_counter()
        t.start()
        time.sleep(0.005)
        start = time.perf_counter()
        pound.simulate(study("ch8-yielding"))  # the damped Sears model, 31 s of record: ~70 ms
        elapsed = time.perf_counter() - start
        done.set()
        t.join()
        done.clear()
        rounds.append((counts[-1], elapsed, start - counter_before))
    # Iterations per second of the counter during the call against its rate alone (5 ms
    # before): the counter runs through most of the call (with the GIL held it would get
    # about 5 % of its rate alone).
    best = max(n / (e + before) for n, e, before in rounds)
    alone = []
    for _ in range(3):
        t = threading.Thread(target=count)
        t.start()
        time.sleep(0.1)
        done.set()
        t.join()
        done.clear()
        alone.append(counts[-1] / 0.1)
    assert best > 0.2 * max(alone), (rounds, alone)
