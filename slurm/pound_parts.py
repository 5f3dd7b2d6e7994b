#!/usr/bin/python3
"""Check pound campaign files and journals (used by test-local-slurm.sh and by hand).

Needs Debian's python3-numpy (run it with /usr/bin/python3); check and compare read the campaign
files with the Python package pound (pound.open_campaign; python3-h5py): the one on PYTHONPATH,
else the one beside the binary $POUND (BUILD/bin/pound: BUILD/python; PREFIX/bin/pound:
PREFIX/lib/python3.X/dist-packages), else this tree's build/python, else an installed one.
range and journal need neither.

  pound_parts.py range  --chunk K --chunks C --samples N      print "LO HI" of chunk K
                                                               (as pound campaign --chunk K/C)
  pound_parts.py check  RUN.h5                                every sample exactly once
  pound_parts.py journal RUN.h5.journal                       records; fails on a duplicate
  pound_parts.py compare A.h5 B.h5                            /samples and /response equal

Splitting and merging are done by the engine: `pound campaign --chunk K/C` runs one range of
samples and `pound merge` joins the parts (see README.md).
"""
import argparse
import os
import shutil
import struct
import sys

import numpy as np

MAGIC = b"POUNDJ04"  # src/campaign/journal.hpp: the layout this script reads
HEADER_BYTES = 8 + 4 * 8
FNV_OFFSET = np.uint64(14695981039346656037)
FNV_PRIME = np.uint64(1099511628211)


def fail(msg):
    print("pound_parts: error: " + msg, file=sys.stderr)
    sys.exit(1)


def package_folders():
    """Where the package pound may be, best first: beside the binary $POUND (a build tree's
    bin/ and python/, or an install prefix's bin/ and lib/python3.X/dist-packages/), then this
    tree's build/python."""
    folders = []
    binary = os.environ.get("POUND")
    if binary:
        binary = shutil.which(binary) or binary  # POUND=pound: the one on PATH
        prefix = os.path.dirname(os.path.dirname(os.path.realpath(binary)))
        version = "python%d.%d" % sys.version_info[:2]
        folders += [os.path.join(prefix, "python"),
                    os.path.join(prefix, "lib", version, "dist-packages"),
                    os.path.join(prefix, "lib", version, "site-packages")]
    here = os.path.dirname(os.path.abspath(__file__))
    folders.append(os.path.join(os.path.dirname(here), "build", "python"))
    return [f for f in folders if os.path.isdir(os.path.join(f, "pound"))]


def open_campaign(path):
    """The campaign file through the package pound (imported on first use: range and journal,
    which the C++ tests also run, need no build of it)."""
    # After PYTHONPATH's folders (sys.path[1:]; [0] is this script's), before the installed ones.
    after = 1 + len([p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p])
    sys.path[after:after] = [f for f in package_folders() if f not in sys.path]
    try:
        import pound
    except ImportError as e:
        fail("cannot import the Python package pound (%s): build it (cmake --build --preset "
             "release makes build/python/pound), set POUND to the binary of that build, or put "
             "the package on PYTHONPATH" % e)
    try:
        return pound.open_campaign(path)
    except pound.Error as e:
        fail(str(e))


def chunk_range(k, chunks, samples):
    """Sample ids [lo, hi) of chunk k of `chunks` (sizes differ by at most one)."""
    if not (chunks >= 1 and 0 <= k < chunks):
        fail("chunk %d of %d: need 0 <= chunk < chunks" % (k, chunks))
    if chunks > samples:
        fail("%d chunks for %d samples: use at most one chunk per sample" % (chunks, samples))
    return k * samples // chunks, (k + 1) * samples // chunks


def read_header(path):
    with open(path, "rb") as f:
        h = f.read(HEADER_BYTES)
    if len(h) != HEADER_BYTES or h[:8] != MAGIC:
        fail(path + ": not a pound campaign journal of layout " + MAGIC.decode() + " "
             "(the engine's journal format changed: update pound_parts.py)")
    _hash, values, msg_bytes, samples = struct.unpack("<4Q", h[8:])
    return h, values, msg_bytes, samples


def fnv_rows(rec):
    """FNV-1a 64 of each row of a uint8 matrix."""
    h = np.full(rec.shape[0], FNV_OFFSET, dtype=np.uint64)
    with np.errstate(over="ignore"):
        for j in range(rec.shape[1]):
            h ^= rec[:, j].astype(np.uint64)
            h *= FNV_PRIME
    return h


def cmd_journal(a):
    _h, values, msg_bytes, samples = read_header(a.journal)
    size = 16 + 8 * values + msg_bytes + 8
    with open(a.journal, "rb") as f:
        f.seek(HEADER_BYTES)
        data = f.read()
    n = len(data) // size
    rec = np.frombuffer(data[: n * size], dtype=np.uint8).reshape(n, size)
    sums = rec[:, size - 8:].copy().view("<u8").reshape(n)
    valid = fnv_rows(rec[:, : size - 8]) == sums
    first_bad = int(np.argmin(valid)) if not valid.all() else n
    ids = rec[:first_bad, 0:8].copy().view("<i8").reshape(first_bad)
    uniq = np.unique(ids)
    dup = first_bad - len(uniq)
    print("pound_parts: %s: %d of %d samples in %d valid records, %d duplicate(s)%s"
          % (a.journal, len(uniq), samples, first_bad, dup,
             "" if first_bad * size == len(data) else ", torn tail of %d bytes" % (len(data) - first_bad * size)))
    if dup or (len(uniq) and (uniq[0] < 0 or uniq[-1] >= samples)):
        fail(a.journal + ": duplicate or out-of-range sample ids")


def cmd_range(a):
    lo, hi = chunk_range(a.chunk, a.chunks, a.samples)
    print(lo, hi)


def cmd_check(a):
    with open_campaign(a.file) as c:
        ids = c.ids
        n = c.sample_count
        status = c.status
    if len(ids) != n or not np.array_equal(np.sort(ids), np.arange(n)) or not np.array_equal(ids, np.arange(n)):
        fail("%s: sample ids are not 0..%d, each once" % (a.file, n - 1))
    print("pound_parts: %s: %d samples, ids 0..%d each exactly once, %d not ok"
          % (a.file, n, n - 1, int(np.count_nonzero(status != 0))))


def cmd_compare(a):
    bad = 0
    with open_campaign(a.a) as fa, open_campaign(a.b) as fb:
        na, nb = fa.datasets(("samples", "response")), fb.datasets(("samples", "response"))
        if na != nb:
            print("datasets differ: %s vs %s" % (sorted(set(na) ^ set(nb)), ""), file=sys.stderr)
            bad += 1
        for name in sorted(set(na) & set(nb)):
            x, y = fa.dataset(name), fb.dataset(name)
            if x.dtype.kind == "f" and y.dtype.kind == "f":
                same = x.shape == y.shape and np.array_equal(x, y, equal_nan=True)
            else:
                same = x.shape == y.shape and np.array_equal(x, y)
            if not same:
                print("differs: /" + name, file=sys.stderr)
                bad += 1
    if bad:
        fail("%s and %s differ in %d dataset(s)" % (a.a, a.b, bad))
    print("pound_parts: %s == %s (%d datasets under /samples and /response, exactly)"
          % (a.a, a.b, len(na)))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("range")
    r.add_argument("--chunk", type=int, required=True)
    r.add_argument("--chunks", type=int, required=True)
    r.add_argument("--samples", type=int, required=True)
    c = sub.add_parser("check")
    c.add_argument("file")
    j = sub.add_parser("journal")
    j.add_argument("journal")
    d = sub.add_parser("compare")
    d.add_argument("a")
    d.add_argument("b")
    a = p.parse_args()
    try:
        {"range": cmd_range, "check": cmd_check, "journal": cmd_journal,
         "compare": cmd_compare}[a.cmd](a)
    except OSError as e:
        fail(str(e))


if __name__ == "__main__":
    main()
