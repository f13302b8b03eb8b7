#!/bin/sh
# interruptible.sh LINE TOOL.py ARGS...: runs a Python tool so that Ctrl-C, SIGTERM or
# SIGHUP at any moment, even while Python is still starting, ends in one line.
#
# The tool runs in the background of this shell (so a terminal's Ctrl-C does not reach
# it directly), and the shell asks it to stop with SIGTERM: the tool stops its work,
# removes what it was writing and says so in its own line. A tool stopped before it
# could set that up (Python still starting) is killed by the SIGTERM before it wrote
# anything, and this shell prints LINE for it. A tool that had already ended keeps its
# own status and its own last line.
line=$1 tool=$2
shift 2
child=
interrupted=
trap 'interrupted=1; [ -n "$child" ] && kill -TERM "$child" 2>/dev/null' INT TERM HUP
python3 "$tool" "$@" &
child=$!
[ -n "$interrupted" ] && kill -TERM "$child" 2>/dev/null
while :; do
  wait "$child" 2>/dev/null  # (no "Terminated" from the shell)
  status=$?
  kill -0 "$child" 2>/dev/null || break  # a trapped signal ends the wait early: wait again
done
if [ -n "$interrupted" ] && [ "$status" -gt 128 ] && [ "$status" -ne 130 ]; then
  echo "$line" >&2  # killed before it could say so itself
  exit 130
fi
exit "$status"
