"""Ctrl-C during medusa.run (run with /usr/bin/python3, PYTHONPATH=<build>/python).

usage: check_interrupt.py <run input> <work folder>

A child Python process calls medusa.run on a run that takes far longer than the delay (the large
bundled run, 4,945 cells); SIGINT is sent to it mid-run. The child must get KeyboardInterrupt out of
medusa.run, and leave no store, temporary file or lock in its folder. A second child replaces an
existing store with force=True and is interrupted the same way: the old store must be left as it was.
"""
import hashlib
import os
import signal
import subprocess
import sys
import time

CHILD = r"""
import sys, medusa
print("running", flush=True)
try:
    medusa.run(sys.argv[1], radius="3", output="interrupted.h5", force=True)
except KeyboardInterrupt:
    print("KeyboardInterrupt", flush=True)
    sys.exit(3)
print("finished", flush=True)
"""


def interrupt_child(run_input, folder):
    child = subprocess.Popen([sys.executable, "-c", CHILD, run_input], cwd=folder, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "running", child.stderr.read()
    time.sleep(2)  # into the kinetic stage (reading the run takes a fraction of a second)
    child.send_signal(signal.SIGINT)
    try:
        out, err = child.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        child.kill()
        sys.exit("medusa.run did not stop within 120 s of SIGINT")
    assert child.returncode == 3 and "KeyboardInterrupt" in out, \
        f"exit {child.returncode}, stdout {out!r}, stderr {err!r}: expected KeyboardInterrupt"
    print(f"{folder}: KeyboardInterrupt")


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def main():
    run_input, work = sys.argv[1], os.path.abspath(sys.argv[2])
    fresh, existing = os.path.join(work, "fresh"), os.path.join(work, "existing")
    for folder in (fresh, existing):
        os.makedirs(folder, exist_ok=True)
        for name in os.listdir(folder):
            os.remove(os.path.join(folder, name))
    interrupt_child(run_input, fresh)
    left = os.listdir(fresh)
    assert not left, f"left behind: {left}"
    # An existing store (any file: it must come out byte for byte the same).
    old = os.path.join(existing, "interrupted.h5")
    with open(old, "wb") as f:
        f.write(b"the store of an earlier run\n")
    before = digest(old)
    interrupt_child(run_input, existing)
    assert sorted(os.listdir(existing)) == ["interrupted.h5"], f"left behind: {os.listdir(existing)}"
    assert digest(old) == before, "the existing store was changed"
    print("interrupted cleanly: no store, temporary or lock left; an existing store kept")


if __name__ == "__main__":
    main()
