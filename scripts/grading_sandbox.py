"""The sandbox of one grading (scripts/grade, as root): a user of its own, the launcher that
starts the submission's programs through scripts/sandbox-run as that user, and the end of
everything that user left.

Each grading takes a user id no account and no other grading uses (k_first_uid +
[0, k_uid_count), held by an flock on /run/mcrt-grade/uid-N.lock for the grading's whole life),
so that it kills exactly its own processes and removes exactly its own files: two gradings on
one machine never touch each other's subjects.
"""

import errno
import fcntl
import os
import pwd
import random
import shlex
import shutil
import signal
import stat
import subprocess

# Far above every account's id (useradd's range ends at 60000, container ids at 2^31 - 2^16 are
# the usual subordinate ranges' end): a million ids, so two gradings draw the same one with
# probability 1e-6 and the lock settles it.
k_first_uid = 1_900_000_000
k_uid_count = 1_000_000
k_lock_folder = "/run/mcrt-grade"
# World-writable places a submission could leave files in (besides the grading's own folders).
k_shared_folders = ("/tmp", "/var/tmp", "/dev/shm")
# The build's limits (the compiler's own are in sandbox-run): its whole wall time, the output
# kept (the first errors are what a student needs).
k_build_seconds = 1200  # a full build of the subject's tree takes about 4 min on 2 loaded cores
k_build_output_bytes = 1 << 20


class Refusal(Exception):
    """A machine the grading cannot own its sandbox on (the message is the whole line)."""


def _lock_folder():
    """/run/mcrt-grade: root's, mode 700, never a link (made here if missing)."""
    try:
        os.mkdir(k_lock_folder, 0o700)
    except FileExistsError:
        pass
    st = os.lstat(k_lock_folder)
    if not stat.S_ISDIR(st.st_mode) or st.st_uid != 0 or st.st_mode & 0o077:
        raise Refusal(f"{k_lock_folder} is not a folder of root's only (mode 700): remove it")
    return k_lock_folder


def _runs_processes(uid):
    return any(owner == uid for _, owner in _processes())


def _processes():
    """(pid, real uid) of every process in /proc."""
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/status") as f:
                owner = next(int(line.split()[1]) for line in f if line.startswith("Uid:"))
        except (OSError, StopIteration, ValueError, IndexError):
            continue
        yield int(entry), owner


class GradingUser:
    """The user id of this grading, locked for its life (the lock goes with the process)."""

    def __init__(self):
        folder = _lock_folder()
        for _ in range(100):
            uid = k_first_uid + random.randrange(k_uid_count)
            try:
                pwd.getpwuid(uid)
                continue  # an account has it
            except KeyError:
                pass
            handle = os.open(os.path.join(folder, f"uid-{uid}.lock"),
                             os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW | os.O_CLOEXEC, 0o600)
            try:
                fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError as e:
                os.close(handle)
                if e.errno in (errno.EWOULDBLOCK, errno.EAGAIN):
                    continue  # another grading's
                raise
            if _runs_processes(uid):  # a leftover of a grading that was killed itself
                os.close(handle)
                continue
            self.uid, self._lock = uid, handle
            return
        raise Refusal("no free grading user id after 100 draws")

    def kill_processes(self):
        """SIGKILL to every process of this grading's user, until none is left (one may fork
        while the others are killed)."""
        for _ in range(100):
            mine = [pid for pid, owner in _processes() if owner == self.uid]
            if not mine:
                return
            for pid in mine:
                try:
                    os.kill(pid, signal.SIGKILL)
                except OSError:
                    pass

    def remove_files(self):
        """Every entry of the shared folders owned by this grading's user (a folder with what is
        in it; links removed, never followed). Its processes are gone, so nothing races."""
        removed = 0
        for folder in k_shared_folders:
            try:
                names = os.listdir(folder)
            except OSError:
                continue
            for name in names:
                path = os.path.join(folder, name)
                try:
                    st = os.lstat(path)
                except OSError:
                    continue
                if st.st_uid != self.uid:
                    continue
                try:
                    if stat.S_ISDIR(st.st_mode):
                        shutil.rmtree(path)
                    else:
                        os.unlink(path)
                    removed += 1
                except OSError:
                    pass
        return removed

    def give(self, folder):
        """Makes `folder` (made by this grading: a build folder) this user's, without following
        a link."""
        for parent, dirs, names in os.walk(folder):
            for name in dirs + names:
                os.lchown(os.path.join(parent, name), self.uid, self.uid)
        os.lchown(folder, self.uid, self.uid)


def namespaces_work(root, uid):
    """Whether sandbox-run's PID and mount namespaces can be made on this machine (a container
    may forbid them; sandbox-run then runs without, and the grader refuses a hidden folder the
    grading user could read)."""
    probe = subprocess.run([os.path.join(root, "scripts", "sandbox-run"), "--uid", str(uid), "--",
                            "true"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return probe.returncode == 0


def readable_by(uid, path):
    """Whether user `uid` could open `path` (a child process takes the user's ids and tries)."""
    pid = os.fork()
    if pid == 0:
        try:
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
            os.close(os.open(path, os.O_RDONLY))
            os._exit(0)
        except BaseException:
            os._exit(1)
    _, status = os.waitpid(pid, 0)
    return os.waitstatus_to_exitcode(status) == 0


def write_launcher(path, words):
    """The launcher of this grading: sandbox-run with its user and the folders to hide (one
    program, as CMake's emulator and the checker's MCRT_SUBJECT_LAUNCHER take it)."""
    text = "#!/bin/sh\nexec " + " ".join(shlex.quote(w) for w in words) + ' -- "$@"\n'
    if os.path.lexists(path):
        os.unlink(path)
    handle = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o755)
    with os.fdopen(handle, "w") as f:
        f.write(text)
    os.chmod(path, 0o755)
    return path


def run_limited(command, env, seconds=k_build_seconds, cap=k_build_output_bytes):
    """Runs `command` (a build step through the launcher --build: a session of its own) with a
    wall time and an output cap; returns (status, output, the limit it hit or None). The whole
    session is killed at the limit."""
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                               start_new_session=True)
    import selectors
    import time
    chunks, kept, hit = [], 0, None
    deadline = time.monotonic() + seconds
    selector = selectors.DefaultSelector()
    selector.register(process.stdout, selectors.EVENT_READ)
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            hit = f"the build ran longer than its limit of {seconds} s and was stopped"
            break
        if not selector.select(timeout=min(left, 1.0)):
            if process.poll() is not None:
                break
            continue
        data = os.read(process.stdout.fileno(), 65536)
        if not data:
            break
        if kept < cap:
            chunks.append(data[:cap - kept])
        kept += len(data)
        if kept > 16 * cap:  # printing without end: stop it rather than read forever
            hit = f"the build printed more than {16 * cap >> 20} MiB and was stopped"
            break
    if hit:
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except OSError:
            pass
    process.stdout.close()
    status = process.wait()
    output = b"".join(chunks).decode("utf-8", "replace")
    if kept > cap:
        output += f"\n[{kept - cap} more bytes of the build's output left out]\n"
    if hit is None:
        hit = limit_named(output, status)
    return status, output, hit


def limit_named(output, status):
    """The build limit a failed build's output shows it hit (sandbox-run's), or None."""
    if status == 0:
        return None
    text = output.lower()
    if "memory exhausted" in text or "out of memory" in text or "cannot allocate memory" in text:
        return "the compiler hit its memory limit (4 GiB a process)"
    if "file size limit exceeded" in text or "file too large" in text:
        return "the build wrote a file larger than its limit of 512 MiB"
    if "cpu time limit exceeded" in text:
        return "a compiler process ran longer than its limit of 300 CPU seconds"
    return None
