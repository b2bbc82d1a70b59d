# A wrong merge undone, as an operator would: a set of its own (free ports, run dir in $WORK) maps
# the Intel log (910 scans); two regions with no gateway between them (one named) are
# refused a plain merge, merged with --force, and `rgnav-rgmap unmerge` gives them back: the
# `regions` and `gateways` listings equal those before the merge, the undo is an event of its own,
# and a second undo is refused, naming why. The same after a restart of the kernel between the
# merge and the undo (the undo survives the checkpoint). Arguments are strict, as merge's.
# The set is brought down at the end, also when the scenario fails half-way.

free_ports() {
  python3 -c 'import socket
socks = [socket.socket() for _ in range(6)]
for s in socks: s.bind(("127.0.0.1", 0))
print(" ".join(str(s.getsockname()[1]) for s in socks))'
}

# poll_until SECONDS CMD...: runs CMD every 0.2 s until it succeeds; false after SECONDS.
poll_until() {
  local limit=$1; shift
  local end=$((SECONDS + limit))
  until "$@" >/dev/null 2>&1; do
    ((SECONDS < end)) || return 1
    sleep 0.2
  done
}

read -r P_NAMING P_WATCHDOG P_PLAYBACK P_SCANMAPPER P_DETECTION P_KERNEL <<<"$(free_ports)"
SET="$WORK/unmerge.yaml" RUN="$WORK/run"
cat >"$SET" <<EOF
robot: tumbot
host: 127.0.0.1
run_dir: $RUN
naming:
  host: 127.0.0.1
  port: $P_NAMING
  managed: true
watchdog:
  port: $P_WATCHDOG
modules:
  - name: LogPlayback
    command: ["\${RGNAV_BIN}/rgnav-carmen-playback", "--log", "\${RGNAV_SHARED}/data/laser/corrected/intel-corrected.log.gz",
              "--speed", "max"]
    port: $P_PLAYBACK
    objects: [Laser, Base]
  - name: ScanMapper
    command: ["\${RGNAV_BIN}/rgnav-scanmapper", "--config", "\${RGNAV_ROOT}/config/modules/scanmapper.yaml"]
    port: $P_SCANMAPPER
    objects: [ScanMapper]
    after: [LogPlayback]
  - name: GatewayDetection
    command: ["\${RGNAV_BIN}/rgnav-gatewaydetection",
              "--config", "\${RGNAV_ROOT}/config/modules/gatewaydetection.yaml",
              "--models", "\${RGNAV_ROOT}/config/gateways/gateway-hmms.txt"]
    port: $P_DETECTION
    objects: [GatewayDetection]
    after: [LogPlayback]
  - name: RGMappingKernel
    command: ["\${RGNAV_BIN}/rgnav-rgmappingkernel", "--config", "\${RGNAV_ROOT}/config/modules/rgmappingkernel.yaml",
              "--export-root", "$WORK/out"]
    port: $P_KERNEL
    objects: [RGMappingKernel]
    after: [ScanMapper, GatewayDetection]
EOF

export RGNAV_BIN="$BIN" RGNAV_ROOT="$ROOT" RGNAV_SHARED="$SHARED"
CTL=("$BIN/rgnav-ctl" --set "$SET")
setsid "$BIN/rgnav-watchdog" --set "$SET" </dev/null >"$WORK/watchdog.log" 2>&1 &
WATCHDOG_PID=$!
bring_down() {
  "${CTL[@]}" shutdown >/dev/null 2>&1
  poll_until 60 bash -c "! kill -0 $WATCHDOG_PID" || kill -TERM "$WATCHDOG_PID" 2>/dev/null
}
trap bring_down EXIT
RGMAP=("$BIN/rgnav-rgmap" --naming "127.0.0.1:$P_NAMING")

# The map of the whole log: its answer comes when the map is done.
SLOW_S=120
run --timeout 60 "${CTL[@]}" wait-running --timeout 60
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
  expect_refusal "no merge into region $HIGH can be undone"
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
  poll_until 60 kernel_restarted
  NEW_KERNEL=$(kernel_pid)
  run test -n "$OLD_KERNEL" -a -n "$NEW_KERNEL" -a "$NEW_KERNEL" != "$OLD_KERNEL"
  expect_ok
  undo_checked
fi

run --timeout 60 "${CTL[@]}" shutdown
expect_ok
poll_until 60 bash -c "! kill -0 $WATCHDOG_PID" || echo "  the watchdog did not stop within 60 s"
trap - EXIT
