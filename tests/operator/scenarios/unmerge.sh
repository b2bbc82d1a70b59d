# A wrong merge undone, as an operator would: the set `rgctl map` runs (free ports of its own,
# run dir in $WORK) maps the Intel log (910 scans); two regions with no gateway between them (one
# named) are refused a plain merge, merged with --force, and `rgnav-rgmap unmerge` gives them
# back: the `regions` and `gateways` listings equal those before the merge, the undo is an event
# of its own, and a second undo is refused, naming why. The same after a restart of the kernel
# between the merge and the undo (the undo survives the checkpoint). Arguments are strict, as
# merge's. The set is brought down at the end, also when the scenario fails half-way.

# The set `rgctl map` runs (config/sets/templates/map.yaml), made by rgctl's own functions with
# free ports of its own and the run dir in $WORK; started and stopped with rgctl up/down.
RUN="$WORK/run"
read -r -a PORTS <<<"$(bash -c 'source "$1"; free_ports 6' _ "$RGCTL")"
SET=$(bash -c 'source "$1"; shift; map_set_file "$@"' _ "$RGCTL" \
  "$SHARED/data/laser/corrected/intel-corrected.log.gz" "$WORK/out" "$RUN" "${PORTS[@]}")
mkdir -p "$WORK/out"
CTL=("$BIN/rgnav-ctl" --set "$SET")
RGMAP=("$BIN/rgnav-rgmap" --naming "127.0.0.1:${PORTS[0]}")
# `rgctl up` remembers the set it started in run/.last-set: the user's own is put back afterwards.
lastSet=$(cat "$ROOT/run/.last-set" 2>/dev/null)
trap '"$RGCTL" down "$SET" >/dev/null 2>&1
      if [[ -n $lastSet ]]; then echo "$lastSet" >"$ROOT/run/.last-set"; else rm -f "$ROOT/run/.last-set"; fi' EXIT

# The map of the whole log: its answer comes when the map is done.
SLOW_S=120
run --timeout 60 "$RGCTL" up "$SET"
expect_ok
run --timeout 300 "${RGMAP[@]}" build --quiet --name um
expect_output "^map: scans=[0-9]+ regions=[0-9]+ "
SLOW_S=2

# Two regions no gateway joins: the first pair of the `regions` listing that no line of the
# `gateways` listing names as its two sides.
run "${RGMAP[@]}" gateways
GATEWAYS_BEFORE=$RUN_OUT
run "${RGMAP[@]}" regions
read -r LOW HIGH < <(awk -v gateways="$GATEWAYS_BEFORE" '
  BEGIN {
    n = split(gateways, lines, "\n")
    for (i = 1; i <= n; ++i)
      if (match(lines[i], /regions=[0-9]+\|[0-9]+/)) {
        split(substr(lines[i], RSTART + 8, RLENGTH - 8), side, "|")
        joined[side[1] " " side[2]] = joined[side[2] " " side[1]] = 1
      }
  }
  /^region / { ids[++count] = $2 }
  END {
    for (a = 1; a <= count; ++a)
      for (b = a + 1; b <= count; ++b)
        if (!((ids[a] " " ids[b]) in joined)) { print ids[a], ids[b]; exit }
  }' <<<"$RUN_OUT")
run test -n "$HIGH"
expect_ok
if [[ -n $HIGH ]]; then
  run "${RGMAP[@]}" name "$HIGH" "um lab"
  expect_ok
  run "${RGMAP[@]}" regions
  expect_output "^region $HIGH \"um lab\" "
  REGIONS_BEFORE=$RUN_OUT

  # undo_checked: `unmerge $LOW` gives back region $HIGH, and the map is as before the merge.
  undo_checked() {
    run "${RGMAP[@]}" unmerge "$LOW"
    expect_ok
    expect_output "^region $HIGH restored from region $LOW$"
    run "${RGMAP[@]}" regions
    run diff <(echo "$REGIONS_BEFORE") <(echo "$RUN_OUT")
    expect_ok
    run "${RGMAP[@]}" gateways
    run diff <(echo "$GATEWAYS_BEFORE") <(echo "$RUN_OUT")
    expect_ok
  }

  run "${RGMAP[@]}" merge "$LOW" "$HIGH"
  expect_refusal "share no gateway.*force"
  run "${RGMAP[@]}" merge "$LOW" "$HIGH" --force
  expect_output "^merged into region $LOW$"
  run "${RGMAP[@]}" regions
  expect_output "^region $LOW \"um lab\" "
  run "${RGMAP[@]}" unmerge "${LOW}x"
  expect_refusal "region ID.*${LOW}x"
  run "${RGMAP[@]}" unmerge
  expect_refusal "unmerge wants 1 arguments"
  run "${RGMAP[@]}" unmerge "$HIGH"
  expect_refusal "no merge into region $HIGH can be undone.*region $HIGH was merged into region $LOW"
  undo_checked
  run "${RGMAP[@]}" events
  expect_output "RegionsUnmerged region=$LOW other=$HIGH "
  run "${RGMAP[@]}" unmerge "$LOW"
  expect_refusal "no merge into region $LOW can be undone"

  # Merged, the kernel restarted, then undone: the kernel's checkpoint holds what the undo needs.
  run "${RGMAP[@]}" merge "$LOW" "$HIGH" --force
  expect_ok
  kernel_pid() { "${CTL[@]}" status | awk '$1 == "RGMappingKernel" && $2 == "RUNNING" { print $3 }'; }
  OLD_KERNEL=$(kernel_pid)
  kernel_restarted() { local pid; pid=$(kernel_pid); [[ -n $pid && $pid != "$OLD_KERNEL" ]]; }
  run "${CTL[@]}" restart RGMappingKernel
  expect_ok
  for _ in $(seq 1 300); do kernel_restarted && break; sleep 0.2; done
  NEW_KERNEL=$(kernel_pid)
  run test -n "$OLD_KERNEL" -a -n "$NEW_KERNEL" -a "$NEW_KERNEL" != "$OLD_KERNEL"
  expect_ok
  undo_checked
fi

SLOW_S=60
run --timeout 90 "$RGCTL" down "$SET"
expect_ok
