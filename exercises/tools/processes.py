"""processes: the one place the tools start and stop a program with all it starts.

On a POSIX system (Linux, macOS, WSL) a program the grader or the kit check starts
gets a session of its own, and stopping it kills its whole process group: compilers
under a build, children of a test. Elsewhere (Windows) there are no process groups to
kill; the program itself is killed, and what it started may run on (said by the
grader's note, since the sandbox is not there either). POSIX is a plain flag so that
a test can force the other path on Linux.
"""
import os
import signal
import subprocess

POSIX = os.name == "posix"


def own_group():
    """Keyword arguments for subprocess.Popen: the program leads a group of its own."""
    if POSIX:
        return {"start_new_session": True}
    return {"creationflags": getattr(subprocess, "CREATE_NEW_PROCESS_GROUP", 0)}


def kill_group(process):
    """Kills the program and, where the system has groups, everything in its group."""
    try:
        if POSIX:
            os.killpg(process.pid, signal.SIGKILL)
        else:
            process.kill()
    except OSError:  # gone already, or (as root in a container) not ours to signal any more
        pass
