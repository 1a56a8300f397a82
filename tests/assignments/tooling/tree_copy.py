"""A throwaway git repository holding the instructor tree's tracked files, so that the tooling
tests can plant untracked files and run the scripts without touching the real tree."""

import os
import shutil
import subprocess
import tempfile


def tracked_files(root):
    listed = subprocess.run(["git", "ls-files", "-z"], cwd=root, stdout=subprocess.PIPE,
                            check=True).stdout.decode()
    return [f for f in listed.split("\0") if f and os.path.isfile(os.path.join(root, f))]


def copy_tree(root, files=None):
    """A new temporary folder with `files` (default: every tracked file) of `root`, committed
    in a fresh git repository there; the caller removes it."""
    copy = tempfile.mkdtemp(prefix="mcrt-tree-")
    for f in files if files is not None else tracked_files(root):
        target = os.path.join(copy, f)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy2(os.path.join(root, f), target)
    quiet = {"cwd": copy, "stdout": subprocess.DEVNULL, "check": True}
    subprocess.run(["git", "init", "-q"], **quiet)
    subprocess.run(["git", "add", "-A"], **quiet)
    subprocess.run(["git", "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m",
                    "copy"], **quiet)
    return copy


def remove(path):
    shutil.rmtree(path, ignore_errors=True)


def run_script(path, args, cwd):
    """(exit status, output) of the Python script at `path` run in this process (a new
    interpreter costs seconds on a loaded machine): its module loaded afresh, so that its ROOT
    is the tree it lies in."""
    import contextlib
    import importlib.machinery
    import importlib.util
    import io
    import sys
    loader = importlib.machinery.SourceFileLoader(f"script_{abs(hash(path))}", path)
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)
    output, saved_argv, saved_cwd = io.StringIO(), sys.argv, os.getcwd()
    sys.argv = [path, *args]
    os.chdir(cwd)
    status = 0
    try:
        with contextlib.redirect_stdout(output), contextlib.redirect_stderr(output):
            module.main()
    except SystemExit as e:
        status = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
    finally:
        sys.argv = saved_argv
        os.chdir(saved_cwd)
    return status, output.getvalue()


def load_script(path):
    """The Python script at `path` loaded as a module (its ROOT the tree it lies in)."""
    import importlib.machinery
    import importlib.util
    loader = importlib.machinery.SourceFileLoader(f"loaded_{abs(hash(path))}", path)
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)
    return module
