"""The git-tracked text files of a repository, as the documentation checks read them."""
import subprocess


def tracked_text_files(root):
    """Yields (path, text) for every tracked file but binaries (gzip, HDF5) and the checks themselves,
    which spell out what they look for."""
    out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True, check=True).stdout
    for name in out.decode().split("\0"):
        if not name or name.startswith("tests/docs/"):
            continue
        try:
            with open(f"{root}/{name}", "rb") as f:
                data = f.read()
        except OSError:
            continue
        if b"\0" in data[:8192]:
            continue
        yield name, data.decode("utf-8", errors="replace")
