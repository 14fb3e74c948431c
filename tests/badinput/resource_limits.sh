#!/usr/bin/env bash
# glider_plan under resource limits (ulimit -t, -v, -u): a clear message and exit status, never a crash or a core.
# Usage: resource_limits.sh GLIDER_PLAN
set -u
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# run NAME LIMITS GRID PHRASE ALLOWED_STATUSES... : runs glider_plan on the built-in mission with --grid-size GRID
# under the limits (bash -c 'ulimit ...; exec ...')
run() {
    local name=$1 limits=$2 grid=$3 phrase=$4
    shift 4
    local out rc
    out=$(cd "$work" && bash -c "$limits; exec \"$exe\" --grid-size $grid --no-refine --out \"$work/$name\"" 2>&1)
    rc=$?
    local ok=0
    for s in "$@"; do [ "$rc" = "$s" ] && ok=1; done
    if [ $ok = 0 ]; then
        echo "FAIL $name: exit $rc, expected one of $*"; echo "$out" | tail -3; failures=$((failures + 1)); return
    fi
    if [ "$rc" != 0 ] && ! grep -qi -- "$phrase" <<<"$out"; then
        echo "FAIL $name: exit $rc without '$phrase'"; echo "$out" | tail -3; failures=$((failures + 1)); return
    fi
    echo "ok   $name (exit $rc): $(tail -1 <<<"$out" | cut -c1-160)"
}

# CPU time: two seconds of CPU (soft and hard) for a plan that needs more: glider_plan lowers the soft limit by a
# second, and SIGXCPU is answered with a message (exit 128 + 24), not the hard limit's SIGKILL
run cpu-time "ulimit -t 2" 0.004 "the CPU time limit (ulimit -t) was reached" 152
# address space: too small for the lattice: refused with the estimate, or out of memory named as such (the plan needs
# between 300 and 400 MB of address space since GDAL is loaded only when needed, src/io/GdalModule.h)
run address-space "ulimit -v 250000" 0.004 "memory" 2
# threads: no new thread may start (the user's processes already fill the limit): done with fewer threads, or a
# message that names the thread limit
run threads "ulimit -u 1" 0.05 "ulimit -u" 0 2
[ $failures = 0 ] && echo "resource limits: all pass" || exit 1
