#!/usr/bin/env bash
# Runs a command beside busy loops that keep the CPU cores occupied, as on a developer's machine
# building something else, and stops the loops however the command ends. Exits with the command's
# status. Used to check that the GUI tests wait for state rather than for time (docs/testing.md).
#
# usage: tests/tools/under_load.sh [-n LOOPS] COMMAND [ARGUMENT…]
#   -n LOOPS  how many busy loops (default: one per core, `nproc`)
# example: cd build && ../tests/tools/under_load.sh ctest -L gui
set -u

loops=$(nproc)
if [[ ${1:-} == -n ]]; then
    [[ ${2:-} =~ ^[0-9]+$ ]] || { echo "under_load.sh: -n needs a number of loops, got '${2:-}'" >&2; exit 2; }
    loops=$2
    shift 2
fi
[[ $# -gt 0 ]] || { echo "usage: under_load.sh [-n LOOPS] COMMAND [ARGUMENT…]" >&2; exit 2; }

busy=()
command_pid=
stop_loops() {
    [[ ${#busy[@]} -gt 0 ]] && kill "${busy[@]}" 2>/dev/null
    wait "${busy[@]}" 2>/dev/null
    busy=()
}
# Interrupted or terminated: the command gets the same signal, then the loops stop.
pass_on() {
    [[ -n $command_pid ]] && kill "-$1" "$command_pid" 2>/dev/null && wait "$command_pid"
    exit "$2"
}
trap stop_loops EXIT
trap 'pass_on INT 130' INT
trap 'pass_on TERM 143' TERM

for ((i = 0; i < loops; i++)); do
    ( while :; do :; done ) &
    busy+=($!)
done
echo "under_load.sh: $loops busy loops beside: $*" >&2
"$@" &  # in the background, so that a signal reaches the traps at once
command_pid=$!
wait "$command_pid"
status=$?
echo "under_load.sh: the command exited with $status; load average: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
exit $status
