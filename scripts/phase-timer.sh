# Sourced by scripts/build.sh and scripts/test.sh: `timed_phase NAME COMMAND...` runs COMMAND and prints the wall time
# of the phase ("phase 'release build': 412 s wall"), also when it fails (then with its exit code), so that CI's log
# (.ci/run) says where the time went.
timed_phase() {
  local name="$1"
  shift
  local start status=0
  start=$(date +%s.%N)
  "$@" || status=$?
  local seconds
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  if [ "$status" -eq 0 ]; then
    echo "phase '$name': $seconds s wall"
  else
    echo "phase '$name': $seconds s wall, failed (exit $status)"
  fi
  return "$status"
}
