"""Checks the libraries' #include lines against their dependency order (run with /usr/bin/python3).

usage: check_include_layers.py <source root>     checks the tracked sources (git ls-files)
       check_include_layers.py --self-test       checks that planted violations are caught

core <- kinetic <- medusa <- persistence <- pipeline (docs/CONVENTIONS.md): a library's sources
include medusa headers only of itself and of the libraries before it, never another library's
private sources, and libkinetic knows nothing of HDF5 or PHAT, libmedusa nothing of PHAT.
cmake/MedusaLayers.cmake checks the same order on the link lines.
"""
import os
import re
import subprocess
import sys
import tempfile

# Folder -> the medusa/<part>/ headers its sources may include.
ALLOWED = {
    "libcore/": {"core"},
    "libkinetic/": {"core", "kinetic"},
    "libmedusa/": {"core", "kinetic", "medusa"},
    "libpersistence/": {"core", "kinetic", "medusa", "persistence"},
    "pipeline/io/": {"core", "kinetic", "io"},
    "pipeline/periodic/": {"core", "kinetic", "io", "periodic"},
    "pipeline/cli/": {"core", "kinetic", "medusa", "persistence", "io", "periodic"},
}
# Folder -> third-party headers it must not include (the library knows nothing of them).
FORBIDDEN = {
    "libcore/": ("hdf5", "H5", "phat/", "CGAL/", "gmp"),
    "libkinetic/": ("hdf5", "H5", "phat/"),
    "libmedusa/": ("phat/",),
}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
SOURCE = re.compile(r"\.(h|hpp|cpp|cc|in)$")


def tracked_sources(root):
    try:
        listed = subprocess.run(["git", "-C", root, "ls-files"], capture_output=True, text=True, check=True)
        files = listed.stdout.splitlines()
    except (OSError, subprocess.CalledProcessError):  # not a git checkout: every file under root
        files = [os.path.relpath(os.path.join(d, f), root) for d, _, names in os.walk(root) for f in names]
    return sorted(f for f in files if SOURCE.search(f) and any(f.startswith(p) for p in ALLOWED))


def violations(root):
    found, checked = [], 0
    for rel in tracked_sources(root):
        folder = next(p for p in ALLOWED if rel.startswith(p))
        checked += 1
        with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                header = m.group(2)
                where = f"{rel}:{number}: {line.strip()}"
                part = re.match(r"medusa/([a-z_]+)/", header)
                if part and part.group(1) not in ALLOWED[folder]:
                    found.append(f"{where}: {folder} may include only medusa/{{{','.join(sorted(ALLOWED[folder]))}}}/")
                if re.search(r"(^|/)(libcore|libkinetic|libmedusa|libpersistence|pipeline)/", header) or (
                    m.group(1) == '"' and header.startswith("../")
                ):
                    found.append(f"{where}: another part's private sources")
                for prefix in FORBIDDEN.get(folder, ()):
                    if m.group(1) == "<" and header.startswith(prefix):
                        found.append(f"{where}: {folder} must not depend on {prefix.rstrip('/')}")
    return found, checked


def check(root):
    found, checked = violations(root)
    print(f"checked the #include lines of {checked} source files")
    if checked == 0:
        sys.exit("no source files found: nothing was checked")
    for v in found:
        print(v)
    if found:
        sys.exit(f"{len(found)} #include lines break the dependency order (docs/CONVENTIONS.md)")
    print("ok")


def self_test():
    planted = {
        "libkinetic/src/engine.cpp": '#include "medusa/medusa/store_writer.h"\n',
        "libmedusa/src/x.cpp": "#include <phat/compute_persistence_pairs.h>\n",
        "pipeline/io/src/y.cpp": '#include "medusa/persistence/diagram.h"\n',
        "libpersistence/src/z.cpp": '#include "../../libmedusa/src/store_layout.h"\n',
        "libkinetic/src/ok.cpp": '#include "medusa/kinetic/observer.h"\n#include "engine.h"\n#include <CGAL/Gmpz.h>\n',
        "pipeline/cli/ok.cpp": '#include "medusa/persistence/diagram.h"\n#include "medusa/io/run_reader.h"\n',
    }
    with tempfile.TemporaryDirectory() as root:
        for rel, text in planted.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        found, checked = violations(root)
    print("\n".join(found))
    assert checked == len(planted), checked
    assert len(found) == 4, found
    for rel in ("libkinetic/src/engine.cpp", "libmedusa/src/x.cpp", "pipeline/io/src/y.cpp", "libpersistence/src/z.cpp"):
        assert any(v.startswith(rel + ":") for v in found), rel
    print("ok: the 4 planted violations are reported, the 2 allowed files are not")


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        self_test()
    else:
        check(sys.argv[1])
