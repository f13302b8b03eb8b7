#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image. The zip
# (made by `exercises/autograder/make-zip`) is unpacked in /autograder/source: the
# instructor's tree, hidden tests included. Install the compilers and libraries, then
# build the graded labs once (their exercises stubbed), so that grading a submission
# recompiles only the files it changes.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq g++ cmake ninja-build python3 libglm-dev libstb-dev libgtest-dev >/dev/null
cd "$(dirname "$0")"
python3 exercises/tools/submission.py prepare
