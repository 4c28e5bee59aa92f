"""Every store is checked before it is believed (docs/FORMAT.md, "File-level properties").

usage: check_store_trust.py bitflip <medusa> <small run csv> <workdir>
       check_store_trust.py semantic <medusa> <small run csv> <workdir>
       check_store_trust.py messages <medusa> <small run csv> <workdir>

bitflip:  a bit flipped inside a chunk of a /persistence dataset, which h5py (the independent reader)
          refuses with a checksum error, makes every command that reads the store exit 5 with one line.
semantic: stores edited with h5py (valid checksums) to hold impossible run facts are refused with exit
          5 and one line naming the fact.
messages: a folder, a missing file and a file that is not HDF5 given as the store give one plain
          sentence (no HDF5 internals unless --verbose).
Run with /usr/bin/python3.
"""
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

if not __debug__:
    sys.exit("these checks are assert statements: run without -O and without PYTHONOPTIMIZE")


def run(args, cwd):
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    print("$", " ".join(args), "->", result.returncode, result.stderr.strip())
    return result


def fresh_store(medusa, csv, work, name):
    result = run([medusa, "run", csv, "-o", name, "--radius", "3", "-q"], work)
    assert result.returncode == 0, result.stderr
    return os.path.join(work, name)


def commands(medusa, store, good):
    """Every command that reads a store, on `store` (and `good` where two are needed)."""
    return [
        [medusa, "info", store],
        [medusa, "diagrams", store, "--type", "all", "--filtration", "forward"],
        [medusa, "barcode", store, "--format", "csv", "--type", "all"],
        [medusa, "at", store, "--time", "0", "-o", "shape.csv"],
        [medusa, "curves", store, "-o", "curves"],
        [medusa, "compare", store, good],
    ]


def refused(result, fragment, store):
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 5, f"exit {result.returncode}, expected 5: {result.stderr}"
    assert len(lines) == 1, f"expected one line on stderr: {result.stderr!r}"
    assert os.path.basename(store) in lines[0], lines[0]
    said = lines[0].split(os.path.basename(store), 1)[1]  # the store's name may hold the fragment
    assert fragment in said, f"'{fragment}' not in: {lines[0]}"


def check_bitflip(medusa, csv, work):
    good = fresh_store(medusa, csv, work, "good.h5")
    tried = 0
    for dataset in ["persistence/forward_all/birth", "persistence/reverse_type1/death_cell",
                    "persistence/forward_type2/zero_length"]:
        store = os.path.join(work, "flipped.h5")
        shutil.copyfile(good, store)
        with h5py.File(store, "r") as f:
            chunk = f[dataset].id.get_chunk_info(0)
        with open(store, "r+b") as f:
            f.seek(chunk.byte_offset + chunk.size // 2)
            byte = f.read(1)[0]
            f.seek(chunk.byte_offset + chunk.size // 2)
            f.write(bytes([byte ^ 0x10]))
        # The oracle: h5py refuses the dataset (fletcher32 or inflate error).
        try:
            with h5py.File(store, "r") as f:
                f[dataset][()]
            raise AssertionError(f"h5py read {dataset} after the flip: the flip missed the data")
        except OSError as e:
            print(f"h5py on {dataset}: {e}")
        for args in commands(medusa, store, good):
            refused(run(args, work), "corrupted", store)
        tried += 1
    assert tried == 3


def mutate(good, work, name, change):
    store = os.path.join(work, name + ".h5")
    shutil.copyfile(good, store)
    with h5py.File(store, "r+") as f:
        change(f)
    return store


def check_semantic(medusa, csv, work):
    good = fresh_store(medusa, csv, work, "good.h5")
    assert run([medusa, "info", good], work).returncode == 0

    def swap_frames(f):
        t = f["input/frame_times"][:]
        t[[1, 2]] = t[[2, 1]]
        f["input/frame_times"][:] = t

    def set_item(path, index, value):
        def change(f):
            data = f[path][:]
            data[index] = value
            f[path][:] = data
        return change

    cases = [
        ("grid_scale_zero", lambda f: f.attrs.modify("grid_scale", np.int64(0)), "grid scale"),
        ("end_time_changed", lambda f: f.attrs.modify("end_time", f.attrs["end_time"] + 50.0), "end_time"),
        ("dimension_seven", lambda f: f.attrs.modify("dimension", np.int64(7)), "dimension"),
        ("negative_type", set_item("input/cell_type", 0, -2), "negative type"),
        ("unsorted_frames", swap_frames, "frame times"),
        ("first_frame_out_of_range", set_item("input/first_frame", 0, 7), "after the last frame"),
        ("radius_negative", lambda f: f.attrs.modify("radius", -3.0), "radius"),
    ]
    for name, change, fragment in cases:
        store = mutate(good, work, name, change)
        # Valid checksums: h5py reads every dataset of the edited store.
        with h5py.File(store, "r") as f:
            f.visititems(lambda _, obj: obj[()] if isinstance(obj, h5py.Dataset) else None)
        for args in commands(medusa, store, good)[:2]:
            refused(run(args, work), fragment, store)
    print(f"{len(cases)} impossible stores refused")


def check_messages(medusa, csv, work):
    os.makedirs(os.path.join(work, "folder.h5"), exist_ok=True)
    with open(os.path.join(work, "text.h5"), "w") as f:
        f.write("not a store\n")
    for store, fragment in [("folder.h5", "is a folder"), ("missing.h5", "no such file"),
                            ("text.h5", "not an HDF5 file")]:
        result = run([medusa, "info", store], work)
        refused(result, fragment, store)
        for internal in ["errno", "time =", "H5F", "flags", "HDF5:"]:
            assert internal not in result.stderr, f"'{internal}' in: {result.stderr}"
    verbose = run([medusa, "info", "text.h5", "--verbose"], work)
    refused(verbose, "(HDF5: ", "text.h5")


def main():
    mode, medusa, csv, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    {"bitflip": check_bitflip, "semantic": check_semantic, "messages": check_messages}[mode](medusa, csv, work)
    print("ok")


if __name__ == "__main__":
    main()
