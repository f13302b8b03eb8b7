"""sandbox: run one graded test program so that the code it holds can do no harm.

The grader starts this file as a process of its own for every run of a test program:

    python3 sandbox.py CONFIG_JSON

and it, in turn, starts the program, in every way of holding it that the system
allows (each one tried, and said so when missing; see isolation_note):

  user      when the grader runs as root: the program runs as a user id of its own
            (no account, no groups), which cannot read the instructor's files, write
            the tree or the results, or signal the grader; afterwards every process
            of that user is killed and every file it left in /tmp, /var/tmp and
            /dev/shm removed;
  pidns     its own PID namespace, whose first process is this file's: when that
            ends, the kernel kills every process left in it, double forks and setsid
            included (no process outlives the run); also its own network (none) and
            IPC namespaces;
  userns    without root, the namespaces above inside a user namespace of its own;
  mount     its own mount namespace, where the tree and the grader's folders are
            covered by empty, unreadable file systems, and /tmp, /var/tmp, /dev/shm
            and /run/lock are small file systems of its own (64 MB each, in memory,
            gone with the namespace: nothing written there outlives the run or grows
            past the limits); the grader's folder of programs and scratch folders is
            put back in its place;
  proc      with the PID namespace and the mount namespace, a /proc of its own, which
            shows the namespace's processes and no other;
  subreaper without a PID namespace: orphans of the program are reparented to this
            process, which kills them all when the program ends;
  limits    memory (data segment), processes, file size (64 MB), open files, no core
            files; and no new privileges (set-user-ID programs do not elevate);
  seccomp   a filter on the program and all it starts (Linux, x86-64 and ARM64):
            ptrace, process_vm_readv/writev and making a process dumpable again
            fail with EPERM, as does every system call of another ABI (x32, i386),
            so that nothing can read the harness's memory from outside, and the
            harness's own non-dumpable flag (support/graded_main.cpp) stays set;
  group     the program's process group is killed at the end, on any POSIX system.

The wall-time limit is enforced here: at the deadline the program (and everything it
started) is killed. The status goes to the grader on a descriptor of its own, as one
JSON object: {"returncode": code, -signal or null on timeout, "timed_out": bool,
"missing": [layers not available]}.

GI_SANDBOX_OFF=user,pidns,userns,mount,proc,subreaper,limits,seccomp (or "all") switches layers
off, so that the fallbacks can be tested on a system where everything works.
"""
import json
import os
import platform
import signal
import sys
import time
from pathlib import Path

LAYERS = ("user", "pidns", "userns", "mount", "proc", "subreaper", "limits", "seccomp")
PRIVATE = ("/tmp", "/var/tmp", "/dev/shm", "/run/lock")  # folders anyone may write: the run's own
PRIVATE_SIZE = "64m"     # each of them: tmpfs pages count against no process's limit
MAX_FILE = 64 << 20      # bytes any file the program writes may reach
MAX_PROCESSES = 256      # threads count too: parallel_for starts one per core
MAX_OPEN_FILES = 256

CLONE_NEWNS, CLONE_NEWUTS, CLONE_NEWIPC = 0x00020000, 0x04000000, 0x08000000
CLONE_NEWUSER, CLONE_NEWPID, CLONE_NEWNET = 0x10000000, 0x20000000, 0x40000000
MS_NOSUID, MS_NODEV, MS_NOEXEC, MS_BIND, MS_REC, MS_PRIVATE = 2, 4, 8, 1 << 12, 1 << 14, 1 << 18
PR_SET_PDEATHSIG, PR_SET_DUMPABLE, PR_SET_SECCOMP, PR_SET_CHILD_SUBREAPER, PR_SET_NO_NEW_PRIVS = 1, 4, 22, 36, 38
SECCOMP_MODE_FILTER = 2


def switched_off():
    text = os.environ.get("GI_SANDBOX_OFF", "")
    return set(LAYERS) if text.strip() == "all" else {w.strip() for w in text.split(",") if w.strip()}


def libc():
    if not sys.platform.startswith("linux"):
        return None
    import ctypes
    try:
        return ctypes.CDLL(None, use_errno=True)
    except OSError:
        return None


def call(lib, name, *args):
    """True when the libc call succeeded."""
    import ctypes
    function = getattr(lib, name)
    function.restype = ctypes.c_int
    return function(*args) == 0


def process_uids():
    """(pid, (real, effective, saved, filesystem user ids)) of each process /proc shows;
    raises OSError when /proc itself cannot be read."""
    for status in Path("/proc").glob("[0-9]*/status"):
        try:
            line = next(l for l in status.read_text().splitlines() if l.startswith("Uid:"))
            yield int(status.parent.name), tuple(int(x) for x in line.split()[1:5])
        except (OSError, StopIteration, ValueError):
            continue  # gone meanwhile, or not a process's


def free_uid():
    """(uid, lock): a user id no account and no process uses, for the programs under test
    (root only), and a descriptor holding it: two graders running at once must not share
    a user, or the one that cleans up after its tests would kill the other's and remove
    its files. Keep the lock open while the uid is in use; closing it frees the uid."""
    used = set()
    try:
        used |= {int(line.split(":")[2]) for line in Path("/etc/passwd").read_text().splitlines() if line.count(":") >= 2}
    except (OSError, ValueError):
        pass
    for _, uids in process_uids():
        used |= set(uids)
    import fcntl  # POSIX, as is running as root

    for uid in range(61000, 62000):
        if uid in used:
            continue
        lock = os.open(f"/tmp/gi-sandbox-uid-{uid}.lock", os.O_RDWR | os.O_CREAT | os.O_CLOEXEC | os.O_NOFOLLOW, 0o600)
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            return uid, lock
        except OSError:
            os.close(lock)  # another grader holds this one
    raise OSError("no free user id from 61000 to 61999 for the tests")


# ---- inside the sandbox -------------------------------------------------------------

def enter_namespaces(lib, config, missing):
    """(in a PID namespace, in a mount namespace, in a user namespace of our own)."""
    off = switched_off()
    if lib is None or "pidns" in off:
        missing.append("pidns")
        return False, False, False
    flags = CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWIPC | CLONE_NEWUTS
    mount_wanted = "mount" not in off
    if mount_wanted:
        flags |= CLONE_NEWNS
    if os.geteuid() == 0 and call(lib, "unshare", flags):
        return True, mount_wanted, False
    if "userns" not in off:
        uid, gid = os.geteuid(), os.getegid()
        if call(lib, "unshare", CLONE_NEWUSER | flags):
            try:
                Path("/proc/self/setgroups").write_text("deny")
                Path("/proc/self/uid_map").write_text(f"0 {uid} 1")
                Path("/proc/self/gid_map").write_text(f"0 {gid} 1")
                return True, mount_wanted, True
            except OSError:
                pass
    missing.append("pidns")
    return False, False, False


def cover(lib, folders, missing):
    """Covers each folder with an empty file system nobody may enter (in our own mount namespace)."""
    import ctypes
    if not call(lib, "mount", None, b"/", None, ctypes.c_ulong(MS_REC | MS_PRIVATE), None):
        missing.append("mount")
        return
    for folder in folders:
        if Path(folder).is_dir() and not call(lib, "mount", b"tmpfs", os.fsencode(folder), b"tmpfs",
                                              ctypes.c_ulong(MS_NOSUID | MS_NODEV | MS_NOEXEC), b"size=16k,mode=000"):
            missing.append("mount")
            return


def make_private(lib, keep, missing):
    """Gives the namespace its own /tmp, /var/tmp, /dev/shm and /run/lock: a small
    tmpfs each, which ends with the namespace. `keep` (the grader's folder, holding the
    program and its scratch folder) is put back where it was when one of them covers it:
    bound from a descriptor opened before it was covered."""
    import ctypes
    held = os.open(keep, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC) if keep else None
    try:
        for folder in PRIVATE:
            if not Path(folder).is_dir() or Path(folder).is_symlink():
                continue  # /run/lock is missing on some systems, a link to /run on others
            if not call(lib, "mount", b"tmpfs", os.fsencode(folder), b"tmpfs", ctypes.c_ulong(MS_NOSUID | MS_NODEV),
                        f"size={PRIVATE_SIZE},nr_inodes=16k,mode=1777".encode()):
                missing.append("mount")
                return
            if held is not None and os.path.commonpath([folder, keep]) == folder:
                os.makedirs(keep, exist_ok=True)
                if not call(lib, "mount", f"/proc/self/fd/{held}".encode(), os.fsencode(keep), None,
                            ctypes.c_ulong(MS_BIND | MS_REC), None):
                    # The grader's folder cannot be put back: the machine's folder it is,
                    # then (MNT_DETACH), and the run goes on without this layer.
                    call(lib, "umount2", os.fsencode(folder), 2)
                    missing.append("mount")
    finally:
        if held is not None:
            os.close(held)


def own_proc(lib, missing):
    """A /proc of the PID namespace (called by its first process): the host's shows every
    process of the machine and its command line."""
    import ctypes
    if "proc" in switched_off() or not call(lib, "mount", b"proc", b"/proc", b"proc",
                                             ctypes.c_ulong(MS_NOSUID | MS_NODEV | MS_NOEXEC), None):
        missing.append("proc")


def set_limits(config, missing):
    if "limits" in switched_off():
        return
    try:
        import resource  # POSIX only, as the rest of the sandbox's own process
    except ImportError:
        missing.append("limits")
        return
    limits = [(resource.RLIMIT_FSIZE, MAX_FILE), (resource.RLIMIT_CORE, 0), (resource.RLIMIT_NOFILE, MAX_OPEN_FILES)]
    if config.get("memory"):
        limits.append((getattr(resource, "RLIMIT_DATA", resource.RLIMIT_AS), config["memory"]))
    if config.get("uid") is not None and hasattr(resource, "RLIMIT_NPROC"):
        limits.append((resource.RLIMIT_NPROC, MAX_PROCESSES))  # counted per user: exact for a user of its own
    for which, value in limits:
        try:
            soft, hard = resource.getrlimit(which)
            value = value if hard == resource.RLIM_INFINITY else min(value, hard)
            resource.setrlimit(which, (value, value))
        except (ValueError, OSError):
            missing.append("limits")


def become_program(lib, config, in_userns, said):
    """In the child that becomes the program: limits, user, filter, then exec. Never
    returns. What it could not set up goes to the descriptor `said` (closed by exec)."""
    try:
        os.setpgid(0, 0)
        missing = []
        set_limits(config, missing)
        uid = config.get("uid")
        if uid is not None:
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
        elif in_userns and lib is not None:
            # Inside a user namespace we are its root: we could uncover the covered
            # folders again, and the program, owning its /proc files, could open its
            # own memory. A second user namespace, where we are no one, takes that away.
            # (Our ids are read before: inside the new namespace they are unmapped.)
            outer_uid, outer_gid = os.geteuid(), os.getegid()
            if call(lib, "unshare", CLONE_NEWUSER | CLONE_NEWNS):
                Path("/proc/self/setgroups").write_text("deny")
                Path("/proc/self/uid_map").write_text(f"1000 {outer_uid} 1")
                Path("/proc/self/gid_map").write_text(f"1000 {outer_gid} 1")
        if lib is not None:
            call(lib, "prctl", PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
            call(lib, "prctl", PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        deny_tracing(lib, missing)
        os.write(said, json.dumps(sorted(set(missing))).encode())
        os.chdir(config["scratch"])
        os.execve(config["argv"][0], config["argv"], config["env"])
    except BaseException as e:  # noqa: B902 -- nothing may escape a forked child
        os.write(2, f"sandbox: cannot start {config['argv'][0]}: {e}\n".encode(errors="replace"))
    os._exit(127)


# seccomp's view of a system call (struct seccomp_data): nr at 0, arch at 4, the
# arguments from 16, 8 bytes each (their low 32 bits first, on these little-endian
# machines). Per machine: the audit arch, and the numbers of ptrace,
# process_vm_readv, process_vm_writev and prctl.
SYSCALLS = {"x86_64": (0xC000003E, 101, 310, 311, 157), "aarch64": (0xC00000B7, 117, 270, 271, 167)}
X32_BIT = 0x40000000


def tracing_filter(machine):
    """The BPF program of deny_tracing, as (code, jt, jf, k) rows; None on another machine.
    A jump names where it goes on true and on false: "deny", "allow", or None for the next row."""
    if machine not in SYSCALLS:
        return None
    arch, ptrace, readv, writev, prctl = SYSCALLS[machine]
    LOAD, EQUAL, AT_LEAST, RETURN = 0x20, 0x15, 0x35, 0x06  # BPF_LD|W|ABS, BPF_JMP|JEQ|K, BPF_JMP|JGE|K, BPF_RET|K
    steps = [(LOAD, 4), (EQUAL, arch, None, "deny"),                  # another ABI (i386)
             (LOAD, 0)]                                               # the call's number
    if machine == "x86_64":
        steps.append((AT_LEAST, X32_BIT, "deny", None))               # the x32 ABI
    steps += [(EQUAL, ptrace, "deny", None), (EQUAL, readv, "deny", None), (EQUAL, writev, "deny", None),
              (EQUAL, prctl, None, "allow"),
              (LOAD, 16), (EQUAL, PR_SET_DUMPABLE, None, "allow"),    # prctl's option
              (LOAD, 24), (EQUAL, 0, "allow", "deny")]                # PR_SET_DUMPABLE to 0 only
    where = {"deny": len(steps), "allow": len(steps) + 1}
    rows = []
    for at, step in enumerate(steps):
        if step[0] == LOAD:
            rows.append((LOAD, 0, 0, step[1]))
        else:
            jump = [where[to] - at - 1 if to else 0 for to in step[2:]]
            rows.append((step[0], jump[0], jump[1], step[1]))
    return rows + [(RETURN, 0, 0, 0x00050000 | 1),   # SECCOMP_RET_ERRNO | EPERM
                   (RETURN, 0, 0, 0x7FFF0000)]       # SECCOMP_RET_ALLOW


def deny_tracing(lib, missing):
    """Installs the seccomp filter (after no-new-privileges, which it needs)."""
    rows = tracing_filter(platform.machine())
    if "seccomp" in switched_off() or lib is None or rows is None:
        missing.append("seccomp")
        return
    import ctypes

    class Row(ctypes.Structure):
        _fields_ = [("code", ctypes.c_ushort), ("jt", ctypes.c_ubyte), ("jf", ctypes.c_ubyte), ("k", ctypes.c_uint)]

    class Program(ctypes.Structure):
        _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.POINTER(Row))]

    table = (Row * len(rows))(*[Row(*r) for r in rows])
    program = Program(len(rows), table)
    if not call(lib, "prctl", PR_SET_SECCOMP, SECCOMP_MODE_FILTER, ctypes.byref(program), 0, 0):
        missing.append("seccomp")


def said(fd):
    """The layers the program's child reported missing, read until it execs (or dies)."""
    with os.fdopen(fd, "rb") as r:
        text = r.read(4096)
    try:
        return [str(m) for m in json.loads(text)]
    except ValueError:
        return []


def wait_until(pid, deadline, reap_others=False):
    """(wait status or None at the deadline). As a namespace's first process, also
    reaps every orphan handed to it."""
    while True:
        try:
            done, status = os.waitpid(-1 if reap_others else pid, os.WNOHANG)
        except ChildProcessError:
            return None
        if done == pid:
            return status
        if done == 0:
            if time.monotonic() >= deadline:
                return None
            time.sleep(0.005)


def returncode(status):
    if status is None:
        return None
    return -os.WTERMSIG(status) if os.WIFSIGNALED(status) else os.WEXITSTATUS(status)


def kill_descendants(me):
    """Kills every process below this one (a subreaper: orphans come here) until none is left."""
    for _ in range(1000):
        children = {}
        for stat in Path("/proc").glob("[0-9]*/stat"):
            try:
                fields = stat.read_text().rsplit(")", 1)[1].split()
                children.setdefault(int(fields[1]), []).append(int(stat.parent.name))
            except (OSError, IndexError, ValueError):
                pass
        below, queue = [], list(children.get(me, []))
        while queue:
            pid = queue.pop()
            below.append(pid)
            queue += children.get(pid, [])
        for pid in below:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
        try:
            while os.waitpid(-1, os.WNOHANG)[0] > 0:
                pass
        except ChildProcessError:
            if not below:
                return
        if not below:
            return
        time.sleep(0.002)


def others_of(uid):
    """Whether a process other than this one runs as `uid` (its real or saved user id:
    those kill(-1) reaches from that user), as far as /proc shows; True when it cannot
    be read, so that the caller goes on killing until its deadline."""
    me = os.getpid()
    try:
        return any(pid != me and uid in (uids[0], uids[2]) for pid, uids in process_uids())
    except OSError:
        return True


def kill_user(uid, deadline):
    """Kills every process of `uid` (a helper process takes that user id, since only
    its own user may signal all of them with kill(-1)). kill(-1) succeeds whenever the
    system has any other process, so the helper stops when /proc shows none of the
    user's, or at the deadline."""
    helper = os.fork()
    if helper == 0:
        try:
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
            while time.monotonic() < deadline:
                os.kill(-1, signal.SIGSTOP)  # stopped, none of them can fork any more
                os.kill(-1, signal.SIGKILL)
                if not others_of(uid):
                    os._exit(0)
                time.sleep(0.001)
        except ProcessLookupError:
            os._exit(0)
        except BaseException:  # noqa: B902
            os._exit(1)
        os._exit(1)
    while True:  # reap as they die: zombies of the user count as processes to kill(-1)
        try:
            pid, _ = os.waitpid(-1, 0)
        except ChildProcessError:
            return
        if pid == helper:
            try:
                while os.waitpid(-1, os.WNOHANG)[0] > 0:
                    pass
            except ChildProcessError:
                pass
            return


def remove_files_of(uid, keep):
    """Removes what the user left in the shared temporary folders (its scratch folder,
    `keep`, is the grader's to read and remove)."""
    for top in PRIVATE:
        for folder, subfolders, files in os.walk(top, topdown=False):
            if os.path.commonpath([folder, keep]) == keep:
                continue
            for name in files + subfolders:
                path = os.path.join(folder, name)
                try:
                    info = os.lstat(path)
                    if info.st_uid == uid:
                        os.rmdir(path) if os.path.isdir(path) and not os.path.islink(path) else os.unlink(path)
                except OSError:
                    pass


def run(config):
    """The sandbox's own work: returns the status for the grader."""
    lib, missing, off = libc(), [], switched_off()
    deadline = time.monotonic() + config["timeout"]
    uid = config.get("uid")
    subreaper = lib is not None and "subreaper" not in off and call(lib, "prctl", PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
    if not subreaper:
        missing.append("subreaper")
    if "limits" in off:
        missing.append("limits")
    in_pidns, mounts, in_userns = enter_namespaces(lib, config, missing)
    if not mounts and "mount" not in missing:
        missing.append("mount")
    if not (mounts and in_pidns) and "proc" not in missing:
        missing.append("proc")
    report_read, report_write = os.pipe()
    # What the program's child could not set up. Python's pipes are closed on exec
    # already (PEP 446), so the program never holds this one; os.pipe2 is Linux's only.
    said_read, said_write = os.pipe()
    first = os.fork()
    if first == 0:
        os.close(report_read)
        if mounts:
            cover(lib, config.get("hide", []), missing)
            make_private(lib, config.get("keep"), missing)
            if in_pidns:
                own_proc(lib, missing)
        if not in_pidns:
            os.close(said_read)
            become_program(lib, config, False, said_write)
        # The namespace's first process: start the program, reap every orphan, and at
        # its end (or the deadline) exit, which kills whatever is left in the namespace.
        if lib is not None:
            call(lib, "prctl", PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        program = os.fork()
        if program == 0:
            os.close(said_read)
            become_program(lib, config, in_userns and uid is None, said_write)
        os.close(said_write)
        missing += said(said_read)
        status = wait_until(program, deadline, reap_others=True)
        os.write(report_write, json.dumps({"returncode": returncode(status), "missing": missing}).encode())
        os._exit(0)
    os.close(report_write)
    os.close(said_write)
    if not in_pidns:
        missing += said(said_read)
    else:
        os.close(said_read)
    if in_pidns:
        wait_until(first, deadline + 5)
        try:
            os.kill(first, signal.SIGKILL)
        except OSError:
            pass
        with os.fdopen(report_read, "rb") as r:
            text = r.read()
        try:
            inner = json.loads(text)
        except ValueError:
            inner = {"returncode": None, "missing": missing}
        code, missing = inner["returncode"], sorted(set(missing + inner["missing"]))
    else:
        os.close(report_read)
        code = returncode(wait_until(first, deadline))
        try:
            os.killpg(first, signal.SIGKILL)
        except OSError:
            pass
    if uid is not None and not in_pidns:  # in a PID namespace the kernel has killed them all
        kill_user(uid, time.monotonic() + 10)
    if subreaper:
        kill_descendants(os.getpid())
    if uid is not None:
        remove_files_of(uid, os.path.realpath(config["scratch"]))
    else:
        missing.append("user")
    return {"returncode": code, "timed_out": code is None, "missing": sorted(set(missing))}


def main(argv):
    config = json.loads(argv[1])
    status_fd = config["status_fd"]
    os.set_inheritable(status_fd, False)
    try:
        status = run(config)
    except BaseException as e:  # noqa: B902 -- the grader must hear why
        status = {"returncode": None, "timed_out": False, "missing": [], "error": f"{type(e).__name__}: {e}"}
    with os.fdopen(status_fd, "w") as out:
        out.write(json.dumps(status))
    return 0


# ---- the grader's side ------------------------------------------------------------

NOTES = {
    "user": "no user of its own (the grader is not root): the code can read and write what you can",
    "pidns": "no PID namespace (unshare not permitted): processes it leaves are killed one by one",
    "mount": "the tree is not covered (no mount namespace): the code can read it, and what it leaves in /tmp, "
             "/dev/shm or /run/lock stays after grading",
    "proc": "no /proc of its own: the code can see every process of the machine",
    "subreaper": "no subreaper: a process the code detaches may outlive grading",
    "limits": "no resource limits: memory, processes and file size are unlimited",
    "seccomp": "no seccomp filter: only the test program's own flag keeps other processes out of its memory",
}


def isolation_note(missing):
    """One line naming what this system could not give the code under test, or ""."""
    parts = [NOTES[m] for m in LAYERS if m in missing and m in NOTES]
    return "; ".join(parts)


def command(config):
    """The argv that runs a program in the sandbox described by `config`."""
    return [sys.executable, str(Path(__file__).resolve()), json.dumps(config)]


if __name__ == "__main__":
    sys.exit(main(sys.argv))
