#!/usr/bin/python3
"""Digests of a medusa HDF5 store: one line per dataset and per attribute (path, dtype, shape, SHA-256 of
the bytes), attributes that legitimately differ between two runs of one command left out (the run id,
the command line and input paths, the software version). Two stores with equal digests hold the
same event stream, complex, filtrations and diagrams.

Text outputs beside the store (the diagrams CSV, the printed summary) are digested too, with their
'#' lines (the run id) and the summary's 'read:' line (the input's path) left out and the store's
folder written as WORK.

Usage: store_digest.py STORE.h5 [TEXT ...]                   print the digest lines
       store_digest.py STORE.h5 [TEXT ...] --check RECORDED  compare with a recorded file: exit 1 with
                                                             one line naming the first that differs
"""
import os
import hashlib
import sys

import h5py
import numpy as np

# run_id: random per run; command_line and source_files: paths of the machine it ran on;
# software_version: changes with every release, not with the content.
VARYING = {"run_id", "command_line", "source_files", "software_version"}


def value_bytes(value):
    if isinstance(value, (bytes, str)):
        return value.encode() if isinstance(value, str) else value
    a = np.asarray(value)
    if a.dtype.kind == "O":
        return repr(a.tolist()).encode()
    return np.ascontiguousarray(a).tobytes()


def digest_lines(path):
    lines = []

    def attrs(name, obj):
        for key in sorted(obj.attrs.keys()):
            if key in VARYING:
                continue
            v = obj.attrs[key]
            lines.append(f"attr {name or '/'}@{key} {hashlib.sha256(value_bytes(v)).hexdigest()[:16]}")

    with h5py.File(path, "r") as f:
        attrs("", f)

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                data = obj[()]
                lines.append(f"data {name} {obj.dtype.str} {obj.shape} "
                             f"{hashlib.sha256(value_bytes(data)).hexdigest()[:16]}")
            attrs(name, obj)

        f.visititems(visit)
    return sorted(lines)


def text_line(path, folder):
    with open(path) as f:
        # "read: <input>" names a path of the machine it ran on, as source_files does.
        text = "".join(l for l in f if not l.startswith("#") and not l.startswith("read: ")).replace(folder, "WORK")
    return f"text {os.path.basename(path)} {hashlib.sha256(text.encode()).hexdigest()[:16]}"


def main():
    args = sys.argv[1:]
    check = None
    if "--check" in args:
        i = args.index("--check")
        if i + 2 != len(args):
            print(__doc__, file=sys.stderr)
            return 2
        check = args[i + 1]
        args = args[:i]
    if not args:
        print(__doc__, file=sys.stderr)
        return 2
    folder = os.path.dirname(os.path.abspath(args[0]))
    lines = digest_lines(args[0]) + [text_line(t, folder) for t in args[1:]]
    if check is None:
        print("\n".join(lines))
        return 0
    store = args[0]
    try:
        with open(check) as f:
            recorded = [l.rstrip("\n") for l in f if l.strip() and not l.startswith("#")]
    except OSError as e:
        print(f"{check}: cannot read the recorded digests: {e.strerror}", file=sys.stderr)
        return 1
    if not recorded:
        print(f"{check}: no recorded digests", file=sys.stderr)
        return 1
    key = lambda l: " ".join(l.split()[:2])
    now = {key(l): l for l in lines}
    old = {key(l): l for l in recorded}
    for k in sorted(set(now) | set(old)):
        if k not in old:
            print(f"{store}: {k} is new (not in {check})", file=sys.stderr)
            return 1
        if k not in now:
            print(f"{store}: {k} is missing (recorded in {check})", file=sys.stderr)
            return 1
        if now[k] != old[k]:
            print(f"{store}: {k} differs: recorded '{old[k]}', now '{now[k]}'", file=sys.stderr)
            return 1
    print(f"{store}: {len(lines)} datasets and attributes equal the recorded ones")
    return 0


if __name__ == "__main__":
    sys.exit(main())
