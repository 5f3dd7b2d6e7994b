#!/usr/bin/python3
"""Compares every dataset of two HDF5 files bit for bit (the bytes of their values, NaNs
included), for checks that a change moved no result (issue 24):

    /usr/bin/python3 scripts/compare_h5.py A.h5 B.h5 [--skip /run] [--skip ...]

Attributes (git_revision, study text, times) are not compared; --skip leaves out a group or
dataset (a campaign file's /run holds the ranks and times of its samples, which differ from run
to run). Prints one line per differing or missing dataset and a summary; exits 1 when any
differs, 2 on a usage error.
"""
import argparse
import sys

import h5py
import numpy as np


def datasets(f):
    names = []
    f.visititems(lambda name, obj: names.append("/" + name) if isinstance(obj, h5py.Dataset) else None)
    return names


def same_values(va, vb):
    """Bit for bit; variable-length strings (object arrays) by value."""
    if va.dtype == object or vb.dtype == object:
        return va.shape == vb.shape and list(va.ravel()) == list(vb.ravel())
    return va.tobytes() == vb.tobytes()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--skip", action="append", default=[])
    args = ap.parse_args()
    skip = [s.rstrip("/") for s in args.skip]

    def kept(name):
        return not any(name == s or name.startswith(s + "/") for s in skip)

    with h5py.File(args.a, "r") as fa, h5py.File(args.b, "r") as fb:
        na = [n for n in datasets(fa) if kept(n)]
        nb = [n for n in datasets(fb) if kept(n)]
        bad = 0
        for n in sorted(set(na) ^ set(nb)):
            print(f"{n}: only in {args.a if n in na else args.b}")
            bad += 1
        same = 0
        for n in sorted(set(na) & set(nb)):
            da, db = fa[n], fb[n]
            if da.shape != db.shape or da.dtype != db.dtype:
                print(f"{n}: shape/type {da.shape} {da.dtype} vs {db.shape} {db.dtype}")
                bad += 1
            elif not same_values(np.asarray(da[()]), np.asarray(db[()])):
                print(f"{n}: values differ")
                bad += 1
            else:
                same += 1
    print(f"compare_h5: {same} datasets identical bit for bit, {bad} differ or missing"
          + (f" (skipped {', '.join(skip)})" if skip else ""))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
