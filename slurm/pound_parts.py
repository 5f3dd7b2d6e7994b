#!/usr/bin/python3
"""Split a pound campaign into chunks for a Slurm job array, merge the chunks, compare files.

Needs Debian's python3-h5py and python3-numpy (run it with /usr/bin/python3).

  pound_parts.py range  --chunk K --chunks C --samples N      print "LO HI" of chunk K
  pound_parts.py seed   --probe PROBE.journal --journal PART.h5.journal --chunk K --chunks C
  pound_parts.py merge  OUT.h5 PART0.h5 PART1.h5 ...          (parts in chunk order)
  pound_parts.py check  RUN.h5                                every sample exactly once
  pound_parts.py journal RUN.h5.journal                       records; fails on a duplicate
  pound_parts.py compare A.h5 B.h5                            /samples and /response equal

How the split works with the current engine (a stopgap until `pound campaign` can run a
sample range by itself): samples are pure functions of (study, sample id), and
`pound campaign --resume` skips every sample its journal already holds. `seed` writes a
journal for chunk K that holds *placeholder* records for every sample outside the chunk, so
that `--resume` simulates only the chunk's samples; the finished part file then has real
rows for its own samples and placeholder rows (all zeros, message PLACEHOLDER) elsewhere.
`merge` takes from each part only the rows of its own chunk and refuses placeholders.
The journal layout is the one documented in src/campaign/journal.hpp ("POUNDJ01"); the
header (study hash, values per record, sample count) is copied from a journal the engine
itself started for the same study and options (the probe), so this script never needs to
know how the study hash is computed.
"""
import argparse
import os
import shutil
import struct
import sys

import numpy as np

MAGIC = b"POUNDJ01"
HEADER_BYTES = 8 + 4 * 8
PLACEHOLDER = b"pound-slurm placeholder: this sample belongs to another chunk"
FNV_OFFSET = np.uint64(14695981039346656037)
FNV_PRIME = np.uint64(1099511628211)


def fail(msg):
    print("pound_parts: error: " + msg, file=sys.stderr)
    sys.exit(1)


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
        fail(path + ": not a pound campaign journal of layout POUNDJ01 "
             "(the engine's journal format changed: update pound_parts.py)")
    _hash, values, msg_bytes, samples = struct.unpack("<4Q", h[8:])
    return h, values, msg_bytes, samples


def placeholder_records(ids, values, msg_bytes):
    """Encoded placeholder records for `ids` (array of int64), as one bytes object."""
    n = len(ids)
    body = 16 + 8 * values + msg_bytes
    rec = np.zeros((n, body + 8), dtype=np.uint8)
    rec[:, 0:8] = ids.astype("<i8").view(np.uint8).reshape(n, 8)
    # status (8 bytes) = 0 (ok, so that the engine does not count them as failures),
    # values = 0.0 (a valid index for a sampled `model` too).
    msg = PLACEHOLDER[: msg_bytes - 1]
    rec[:, 16 + 8 * values: 16 + 8 * values + len(msg)] = np.frombuffer(msg, dtype=np.uint8)
    h = fnv_rows(rec[:, :body])
    rec[:, body:] = h.astype("<u8").view(np.uint8).reshape(n, 8)
    return rec.tobytes()


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


def cmd_seed(a):
    header, values, msg_bytes, samples = read_header(a.probe)
    lo, hi = chunk_range(a.chunk, a.chunks, samples)
    ids = np.concatenate([np.arange(0, lo), np.arange(hi, samples)]).astype(np.int64)
    tmp = a.journal + ".seeding"
    with open(tmp, "wb") as f:
        f.write(header)
        step = 65536
        for s in range(0, len(ids), step):
            f.write(placeholder_records(ids[s: s + step], values, msg_bytes))
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, a.journal)
    print("pound_parts: %s: chunk %d of %d = samples [%d, %d) of %d; %d placeholders"
          % (a.journal, a.chunk, a.chunks, lo, hi, samples, len(ids)))


def datasets(f, groups=("samples", "response", "run")):
    out = []
    for g in groups:
        if g in f:
            f[g].visititems(lambda name, obj, g=g: out.append(g + "/" + name)
                            if hasattr(obj, "shape") else None)
    return sorted(out)


def as_bytes(x):
    return x if isinstance(x, bytes) else str(x).encode()


def cmd_merge(a):
    import h5py
    parts = a.parts
    chunks = len(parts)
    files = [h5py.File(p, "r") for p in parts]
    try:
        first = files[0]
        samples = int(first["samples/id"].shape[0])
        names = datasets(first)
        for p, f in zip(parts, files):
            if datasets(f) != names or int(f["samples/id"].shape[0]) != samples:
                fail(p + ": not a part of the same campaign as " + parts[0])
            for key in ("study", "seed", "samples"):
                if f.attrs.get(key) != first.attrs.get(key):
                    fail("%s: attribute %s differs from %s" % (p, key, parts[0]))
        for k, (p, f) in enumerate(zip(parts, files)):
            lo, hi = chunk_range(k, chunks, samples)
            ids = f["samples/id"][lo:hi]
            if not np.array_equal(ids, np.arange(lo, hi)):
                fail("%s: rows [%d, %d) do not hold samples %d..%d" % (p, lo, hi, lo, hi - 1))
            msgs = f["samples/message"][lo:hi]
            if any(as_bytes(m) == PLACEHOLDER for m in msgs):
                fail("%s: chunk %d holds placeholders; is this part of chunk %d of %d?"
                     % (p, k, k, chunks))
        tmp = a.out + ".merging"
        shutil.copyfile(parts[0], tmp)
        with h5py.File(tmp, "r+") as out:
            for k, f in enumerate(files[1:], start=1):
                lo, hi = chunk_range(k, chunks, samples)
                for name in names:
                    out[name][lo:hi] = f[name][lo:hi]
            if any(as_bytes(m) == PLACEHOLDER for m in out["samples/message"][:]):
                fail("merged file still holds placeholders")
            out.attrs["ranks"] = float(sum(f.attrs.get("ranks", 0) for f in files))
            out.attrs["start_time"] = min(as_bytes(f.attrs["start_time"]) for f in files).decode()
            out.attrs["end_time"] = max(as_bytes(f.attrs["end_time"]) for f in files).decode()
            out.attrs["host"] = ", ".join(sorted({as_bytes(f.attrs["host"]).decode() for f in files}))
            out.attrs["merged_parts"] = float(chunks)
        os.replace(tmp, a.out)
    finally:
        for f in files:
            f.close()
    print("pound_parts: merged %d parts (%d samples) into %s" % (chunks, samples, a.out))


def cmd_check(a):
    import h5py
    with h5py.File(a.file, "r") as f:
        ids = f["samples/id"][:]
        n = int(f.attrs["samples"])
        msgs = f["samples/message"][:]
        status = f["samples/status"][:]
    if len(ids) != n or not np.array_equal(np.sort(ids), np.arange(n)) or not np.array_equal(ids, np.arange(n)):
        fail("%s: sample ids are not 0..%d, each once" % (a.file, n - 1))
    if any(as_bytes(m) == PLACEHOLDER for m in msgs):
        fail(a.file + ": holds placeholder rows")
    print("pound_parts: %s: %d samples, ids 0..%d each exactly once, %d not ok"
          % (a.file, n, n - 1, int(np.count_nonzero(status != 0))))


def cmd_compare(a):
    import h5py
    bad = 0
    with h5py.File(a.a, "r") as fa, h5py.File(a.b, "r") as fb:
        na, nb = datasets(fa, ("samples", "response")), datasets(fb, ("samples", "response"))
        if na != nb:
            print("datasets differ: %s vs %s" % (sorted(set(na) ^ set(nb)), ""), file=sys.stderr)
            bad += 1
        for name in sorted(set(na) & set(nb)):
            x, y = fa[name][()], fb[name][()]
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
    s = sub.add_parser("seed")
    s.add_argument("--probe", required=True, help="a journal the engine started for this study")
    s.add_argument("--journal", required=True, help="the part's journal to write")
    s.add_argument("--chunk", type=int, required=True)
    s.add_argument("--chunks", type=int, required=True)
    m = sub.add_parser("merge")
    m.add_argument("out")
    m.add_argument("parts", nargs="+")
    c = sub.add_parser("check")
    c.add_argument("file")
    j = sub.add_parser("journal")
    j.add_argument("journal")
    d = sub.add_parser("compare")
    d.add_argument("a")
    d.add_argument("b")
    a = p.parse_args()
    try:
        {"range": cmd_range, "seed": cmd_seed, "merge": cmd_merge, "check": cmd_check,
         "journal": cmd_journal, "compare": cmd_compare}[a.cmd](a)
    except OSError as e:
        fail(str(e))


if __name__ == "__main__":
    main()
