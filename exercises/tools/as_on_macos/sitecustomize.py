"""Python as macOS ships it, for the grader's test on Linux: no os.pipe2 and no
`resource` module (so no resource limits). With GI_SANDBOX_OFF=all (no namespaces,
no user of its own, no subreaper, no seccomp) the grader then runs as it would on a
Mac. Put on PYTHONPATH, this file is read by every Python process the grader starts."""
import os
import sys

if hasattr(os, "pipe2"):
    del os.pipe2
sys.modules["resource"] = None  # `import resource` now raises ImportError
