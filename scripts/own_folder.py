"""What render-docs and make-gallery share with the chapters' runs (issue 43): they write only in
folders of their own, and read only regular files, without blocking.

  refuse_unowned(program, "--out", folder)   exit 2, one line, when another user owns `folder`
                                             or can write in it (git's safe.directory rule)
  read_regular(program, path)                the bytes of a regular file; exit 1, one line, for
                                             a FIFO, a device or a folder (never opened to wait)
"""

import os
import stat
import sys


def not_ours(info, parent=False):
    """Why a folder with this stat is not one we can own ("" when it is). Root may own a parent
    with the sticky bit (/tmp): others can add to it but cannot rename what we make in it."""
    if info.st_uid != os.geteuid() and not (parent and info.st_uid == 0):
        return "is owned by another user"
    sticky = parent and info.st_mode & stat.S_ISVTX
    group_writable = info.st_mode & stat.S_IWGRP and info.st_gid != os.getegid()
    if not sticky and (info.st_mode & stat.S_IWOTH or group_writable):
        return "can be written by other users"
    return ""


def refuse_unowned(program, flag, folder, parent=False):
    """Exit 2 with one line naming `flag` when `folder` (if it exists) is not ours."""
    try:
        why = not_ours(os.stat(folder), parent)
    except FileNotFoundError:
        return
    if why:
        print(f"{program}: {flag} {folder} {why}; it writes only in folders of your own, so "
              "choose one", file=sys.stderr)
        sys.exit(2)


def read_regular(program, path):
    """The bytes of the regular file `path`, opened without blocking; None if it does not
    exist. Anything else (a FIFO, a device, a folder): exit 1 with one line naming it."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except FileNotFoundError:
        return None
    except OSError as error:
        print(f"{program}: {path}: {error.strerror}", file=sys.stderr)
        sys.exit(1)
    with os.fdopen(fd, "rb") as f:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            print(f"{program}: {path}: not a regular file (a FIFO or a device?); not read",
                  file=sys.stderr)
            sys.exit(1)
        return f.read()
