#!/usr/bin/env python3
"""The Python module's cost per call (issue 25, docs/python.md "Speed"): N calls of
pound.simulate on the two-SDOF study (studies/ch6-sdof-pair.ini, the lumped hc-linear model)
in one process, serially and in threads on every core, against N `pound simulate --json`
processes (each started with subprocess and its output parsed, as a script would without the
module). Prints figures; a benchmark, not a test.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--calls 1000]
        [--processes 1000] [--threads N] [--study studies/ch6-sdof-pair.ini]

Per call: the wall time of pound.simulate; inside it the engine's own time (reading and
checking the study and the record, both simulations, the JSON text; measured in C++), and the
rest, the module's overhead (arguments, GIL, json.loads, the result's objects). The target of
issue 25: overhead under 5 % of a sample's own cost. Thread speed-up: the serial loop's wall
time over the threaded one (target: 1.9 on two cores), the calls handed out one by one by a
ThreadPoolExecutor (its map, and submit then wait), and made in a loop by each thread. On a shared machine the threads compete
with other work: the load average is printed, and for the serial and the threaded loop the
cores other processes kept busy meanwhile (/proc/stat less this process's CPU time).
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor, wait
from pathlib import Path

import pound
from pound import _simulate as engine_call

ROOT = Path(__file__).resolve().parent.parent


class OtherLoad:
    """The cores that other processes kept busy while a phase ran: the machine's busy time
    (/proc/stat) less this process's own CPU time, over the phase's wall time."""

    def __init__(self):
        self.busy, self.own, self.wall = self._machine(), self._own(), time.perf_counter()

    @staticmethod
    def _machine():
        with open("/proc/stat") as f:
            user, nice, system, _, _, irq, softirq, steal = map(int, f.readline().split()[1:9])
        return (user + nice + system + irq + softirq + steal) / os.sysconf("SC_CLK_TCK")

    @staticmethod
    def _own():
        t = os.times()
        return t.user + t.system + t.children_user + t.children_system

    def cores(self):
        wall = time.perf_counter() - self.wall
        return max(0.0, (self._machine() - self.busy) - (self._own() - self.own)) / wall


def serial(study, n):
    """Wall time of n public calls."""
    start = time.perf_counter()
    for _ in range(n):
        pound.simulate(study)
    return time.perf_counter() - start


def breakdown(study, n):
    """Per call: (total, prepare, run, json) in s, the medians over n calls of the call
    pound.simulate makes (the same work; its timing is what the engine measured)."""
    rows = []
    for _ in range(n):
        start = time.perf_counter()
        _, _, t = engine_call._simulate(study, None, False, {})
        total = time.perf_counter() - start
        rows.append((total, t["prepare_s"], t["run_s"], t["json_s"]))
    return [statistics.median(c) for c in zip(*rows)]


def threaded(study, n, threads):
    """Wall time of n calls handed to a ThreadPoolExecutor one by one (pool.map)."""
    start = time.perf_counter()
    with ThreadPoolExecutor(max_workers=threads) as pool:
        list(pool.map(lambda _: pound.simulate(study), range(n)))
    return time.perf_counter() - start


def submitted(study, n, threads):
    """Wall time of n calls submitted to a ThreadPoolExecutor at once, then waited for
    (concurrent.futures.wait) and their results taken: the main thread sleeps until the last
    call ends, where pool.map's generator wakes it at each result, and on two cores the woken
    main thread takes turns with the two workers."""
    start = time.perf_counter()
    with ThreadPoolExecutor(max_workers=threads) as pool:
        futures = [pool.submit(pound.simulate, study) for _ in range(n)]
        wait(futures)
        [f.result() for f in futures]
    return time.perf_counter() - start


def looping(study, n, threads):
    """Wall time of n calls in `threads` threads that each make n / threads calls in a loop
    (no executor: its bookkeeping per task, about 7 us, runs under the GIL)."""
    def loop(k):
        for _ in range(k):
            pound.simulate(study)
    workers = [threading.Thread(target=loop, args=(n // threads + (i < n % threads),))
               for i in range(threads)]
    start = time.perf_counter()
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    return time.perf_counter() - start


def processes(binary, study, n):
    start = time.perf_counter()
    for _ in range(n):
        out = subprocess.run([binary, "simulate", "--config", study, "--json"],
                             capture_output=True, text=True, check=True)
        json.loads(out.stdout)
    return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--calls", type=int, default=1000)
    ap.add_argument("--processes", type=int, default=1000)
    ap.add_argument("--threads", type=int, default=os.cpu_count())
    ap.add_argument("--study", default=str(ROOT / "studies" / "ch6-sdof-pair.ini"))
    ap.add_argument("--binary", default=str(ROOT / "build" / "bin" / "pound"))
    a = ap.parse_args()
    n = a.calls
    expected = pound.simulate(a.study)  # warm-up, and the numbers the threads must give
    with ThreadPoolExecutor(max_workers=a.threads) as pool:
        assert all(r == expected for r in pool.map(lambda _: pound.simulate(a.study), range(8)))

    load0 = os.getloadavg()[0]
    other = OtherLoad()
    t_serial = serial(a.study, n)
    other_serial = other.cores()
    total, prepare, run, text = breakdown(a.study, n)
    other = OtherLoad()
    t_threads = threaded(a.study, n, a.threads)
    other_threads = other.cores()
    other = OtherLoad()
    t_submit = submitted(a.study, n, a.threads)
    other_submit = other.cores()
    other = OtherLoad()
    t_loops = looping(a.study, n, a.threads)
    other_loops = other.cores()
    t_proc = processes(a.binary, a.study, a.processes) if a.processes else float("nan")
    load1 = os.getloadavg()[0]

    engine = prepare + run + text
    overhead = total - engine
    ms = 1e3
    print(f"python_overhead: {Path(a.study).name}, {n} calls, pound {pound.__version__} "
          f"{pound.git_revision}, {os.cpu_count()} cores, load average {load0:.2f} -> "
          f"{load1:.2f}")
    print(f"  pound.simulate, serial        {t_serial / n * ms:8.3f} ms per call "
          f"({t_serial:.2f} s in all; other processes kept {other_serial:.2f} cores busy)")
    print(f"    median call                 {total * ms:8.3f} ms: engine {engine * ms:.3f} ms "
          f"(study and record {prepare * ms:.3f}, simulations {run * ms:.3f}, JSON "
          f"{text * ms:.3f}), module {overhead * 1e6:.1f} us")
    print(f"    module overhead             {100 * overhead / run:8.2f} % of the simulations, "
          f"{100 * overhead / engine:.2f} % of the engine's call (target < 5 %)")
    print(f"  pound.simulate, {a.threads} threads     {t_threads / n * ms:8.3f} ms per call "
          f"({t_threads:.2f} s in all; others {other_threads:.2f} cores): speed-up "
          f"{t_serial / t_threads:.2f} with ThreadPoolExecutor.map (target >= 1.9 on two cores)")
    print(f"                                {t_submit / n * ms:8.3f} ms per call "
          f"({t_submit:.2f} s in all; others {other_submit:.2f} cores): speed-up "
          f"{t_serial / t_submit:.2f} with ThreadPoolExecutor.submit and wait")
    print(f"                                {t_loops / n * ms:8.3f} ms per call "
          f"({t_loops:.2f} s in all; others {other_loops:.2f} cores): speed-up "
          f"{t_serial / t_loops:.2f} with a loop in each thread")
    if a.processes:
        print(f"  pound simulate processes      {t_proc / a.processes * ms:8.3f} ms per call "
              f"({a.processes} processes, {t_proc:.2f} s): "
              f"{t_proc / a.processes / (t_serial / n):.1f} x the module's serial call")
    return 0


if __name__ == "__main__":
    sys.exit(main())
