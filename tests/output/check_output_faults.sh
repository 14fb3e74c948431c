#!/usr/bin/env bash
# Faults around glider_plan's output directory, on the real program: SIGINT and SIGTERM during a long run leave the
# earlier outputs and no staging directory; a second run into a directory in use is refused (exit 2); a dangling
# --out link and a directory where a file goes are refused before anything is replaced; a full device (a 64 kB
# tmpfs) and a read-only one give exit 2 with the system's reason and keep the earlier outputs. The two device
# cases need a private mount namespace (unshare -rm); without one they are skipped, said on stdout.
# Usage: check_output_faults.sh GLIDER_PLAN
set -u
G=$(readlink -f "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; cat ./*.err 2>/dev/null | tail -5; fi; }
digest() { (cd "$1" && find . -type f | sort | xargs sha256sum) ; }
staging() { ls -a "$1" | grep -c '\.tmp-' ; }

quick=(--grid-size 0.8 --no-refine)
"$G" "${quick[@]}" --out out >/dev/null 2>&1 || { echo "FAIL first run"; exit 1; }
before=$(digest out)

# --- signals during a long run (RRT* runs until its time limit), and a second run meanwhile ---------------------
for sig in INT TERM; do
  # a script's background job starts with SIGINT ignored; the run gets the default disposition, as from a terminal
  env --default-signal=INT "$G" --planner RRTstar --time-limit 60 --out out >/dev/null 2>long.err &
  pid=$!
  sleep 1.5
  "$G" "${quick[@]}" --out out >second.out 2>second.err
  rc=$?
  check "second run while one runs: exit 2 ($rc)" "[ $rc -eq 2 ]"
  check "second run says the directory is in use" "grep -q 'in use by another glider_plan run' second.err"
  kill -$sig $pid
  wait $pid
  rc=$?
  check "SIG$sig ends the long run by the signal ($rc)" "[ $rc -gt 128 ]"
  check "SIG$sig: the earlier outputs are unchanged" "[ \"\$(digest out)\" = \"\$before\" ]"
  check "SIG$sig: no staging directory" "[ $(staging .) -eq 0 ]"
done

# --- a staging directory a killed run left is removed by the next run ----------------------------------------------
mkdir .out.tmp-99999-0 && echo old > .out.tmp-99999-0/summary.json
mkdir .out2.tmp-1-0     # another directory's: not touched
"$G" "${quick[@]}" --out out >/dev/null 2>&1
check "a killed run's staging directory is removed" "[ ! -e .out.tmp-99999-0 ]"
check "another directory's staging is left" "[ -d .out2.tmp-1-0 ]"
rmdir .out2.tmp-1-0
before=$(digest out)

# --- a dangling link, a directory where a file goes ----------------------------------------------------------------
ln -s missing/place dangling
"$G" "${quick[@]}" --out dangling >/dev/null 2>err.txt
rc=$?
check "dangling --out link: exit 2 ($rc)" "[ $rc -eq 2 ]"
check "dangling --out link: says where it points" "grep -q \"symbolic link to 'missing/place', which does not exist\" err.txt"
cp -r out blocked && rm blocked/path.csv && mkdir blocked/path.csv
b=$(digest blocked)
"$G" "${quick[@]}" --out blocked >/dev/null 2>err.txt
rc=$?
check "directory where a file goes: exit 2 ($rc)" "[ $rc -eq 2 ]"
check "directory where a file goes: named" "grep -q \"holds a directory 'path.csv'\" err.txt"
check "directory where a file goes: nothing replaced" "[ \"\$(digest blocked)\" = \"\$b\" ]"

# --- an output directory whose parent the user may not write (a home directory's parent) ----------------------------
# (as root: the run is made as nobody, into a directory nobody owns inside one only root may write)
if [ "$(id -u)" -eq 0 ] && command -v runuser >/dev/null; then
  mkdir -p locked/own && chmod 755 . locked && chown nobody locked/own
  asNobody=(runuser -u nobody -- "$G")
  if ! runuser -u nobody -- test -x "$G"; then
    # a clone in a folder other users cannot enter (/root, a mktemp -d): the binary and its library copied where
    # nobody reaches them, found through LD_LIBRARY_PATH (the binary's own RPATH is closed to nobody)
    mkdir -p bin && cp "$G" bin/ && cp "$(ldd "$G" | awk '/libompl_glider/ {print $3}')" bin/ && chmod -R a+rX bin
    asNobody=(runuser -u nobody -- env LD_LIBRARY_PATH="$work/bin" "$work/bin/$(basename "$G")")
    echo "note parent not writable: $G is closed to user nobody; running a copy from $work/bin"
  fi
  "${asNobody[@]}" "${quick[@]}" --out locked/own >/dev/null 2>err.txt
  rc=$?
  check "parent not writable: the run writes into its own directory ($rc)" "[ $rc -eq 0 ] && [ -s locked/own/summary.json ]"
  "${asNobody[@]}" "${quick[@]}" --out locked/own >/dev/null 2>err.txt
  rc=$?
  check "parent not writable: a second run replaces the files ($rc)" "[ $rc -eq 0 ] && [ $(staging locked/own) -eq 0 ]"
  check "parent not writable: nothing beside the directory" "[ \"\$(ls -A locked)\" = own ]"
else
  echo "skip parent not writable: needs root and runuser"
fi

# --- a full and a read-only device ----------------------------------------------------------------------------------
if unshare -rm true 2>/dev/null; then
  cat >m.yaml <<'EOF'
name: small
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
vehicle: {speed: 0.5}
planner: {name: zastartve, grid_size: 0.5}
outputs: {files: [summary, csv]}
EOF
  sed 's/files: \[summary, csv\]/files: [summary, csv, map]/' m.yaml >big.yaml
  mkdir dev
  unshare -rm bash -c "
    mount -t tmpfs -o size=64k tmpfs dev || exit 77
    '$G' --mission m.yaml --out dev/out >/dev/null 2>&1 || exit 3
    find dev/out -type f | sort | xargs sha256sum >sums.before
    '$G' --mission big.yaml --out dev/out >/dev/null 2>full.err; echo \$? >full.rc
    find dev/out -type f | sort | xargs sha256sum >sums.full
    ls -a dev >ls.full
    mount -o remount,ro dev
    '$G' --mission big.yaml --out dev/out >/dev/null 2>ro.err; echo \$? >ro.rc
    find dev/out -type f | sort | xargs sha256sum >sums.ro
  "
  rc=$?
  if [ $rc -eq 77 ]; then
    echo "skip full and read-only device: tmpfs cannot be mounted here"
  else
    check "device runs started ($rc)" "[ $rc -eq 0 ]"
    check "full device: exit 2 ($(cat full.rc))" "[ \"\$(cat full.rc)\" = 2 ]"
    check "full device: the system's reason" "grep -q 'No space left on device' full.err"
    check "full device: the earlier outputs stay" "cmp -s sums.before sums.full"
    check "full device: no staging directory" "! grep -q tmp- ls.full"
    check "read-only device: exit 2 ($(cat ro.rc))" "[ \"\$(cat ro.rc)\" = 2 ]"
    check "read-only device: the system's reason" "grep -q 'Read-only file system' ro.err"
    check "read-only device: the earlier outputs stay" "cmp -s sums.before sums.ro"
  fi
else
  echo "skip full and read-only device: no private mount namespace (unshare -rm)"
fi
exit $fail
