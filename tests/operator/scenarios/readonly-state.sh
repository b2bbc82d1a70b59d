# Checkpoints that cannot be written, while a set maps the Intel log: a failed checkpoint is not
# silent. Each of the three checkpointing modules turns DEGRADED with the reason in
# `rgnav-ctl status`, its log says so, the kernel's scan journal gets each scan once (it used to
# append all pending scans again at every failed attempt: quadratic growth), and once the state
# can be written again every module is healthy again.
# Writes are made to fail in ways that hold for root too (root ignores chmod): the kernel's map
# file is replaced by a directory (its journal stays appendable: the case that grew it), the
# ScanMapper's state directory by a regular file, and GatewayDetection's is deleted.
# The set runs on free ports of its own under $WORK and is brought down at the end.

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
SET="$WORK/readonly-state.yaml" RUN="$WORK/run"
STATE="$RUN/state" JOURNAL="$WORK/run/state/RGMappingKernel/rgmap.state.scans"
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
    command: ["\${RGNAV_BIN}/rgnav-carmen-playback",
              "--log", "\${RGNAV_SHARED}/data/laser/corrected/intel-corrected.log.gz", "--speed", "x2"]
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

degraded() { "${CTL[@]}" status | grep -qE "^$1 +DEGRADED"; }
none_degraded() { ! "${CTL[@]}" status | grep -q DEGRADED; }
journal_lines() { wc -l <"$JOURNAL"; }
journal_grew_past() { (($(journal_lines) > $1)); }

RGMAP=("$BIN/rgnav-rgmap" --naming "127.0.0.1:$P_NAMING")
first_region() { "${RGMAP[@]}" regions | awk '/^region /{ print $2; exit }'; }
has_region() { [[ -n $(first_region) ]]; }

run "${CTL[@]}" wait-running --timeout 60
expect_ok
poll_until 60 has_region || echo "  the kernel mapped no region within 60 s"
REGION=$(first_region)
# Naming a region makes the kernel checkpoint at once, as every name, merge and new region does.
run "${RGMAP[@]}" name "$REGION" lab-0
expect_ok
poll_until 20 test -f "$STATE/RGMappingKernel/rgmap.state" || echo "  the kernel wrote no checkpoint within 20 s"

# Break the three modules' state.
rm -f "$STATE/RGMappingKernel/rgmap.state" && mkdir "$STATE/RGMappingKernel/rgmap.state"
mv "$STATE/ScanMapper" "$WORK/ScanMapper.state" && echo "not a directory" >"$STATE/ScanMapper"
rm -rf "$STATE/GatewayDetection"

for name in lab-1 lab-2 lab-3; do
  run "${RGMAP[@]}" name "$REGION" "$name"
  expect_ok
done
for module in RGMappingKernel ScanMapper GatewayDetection; do
  poll_until 20 degraded "$module" || echo "  $module not DEGRADED within 20 s"
done
run "${CTL[@]}" status
expect_output "RGMappingKernel +DEGRADED .*checkpoint: .*rgmap.state: cannot replace: Is a directory"
expect_output "ScanMapper +DEGRADED .*checkpoint: .*slam.state: .*Not a directory"
expect_output "GatewayDetection +DEGRADED .*checkpoint: .*gateways.state: .*No such file or directory"
run grep -h "checkpoint failed" "$RUN/logs/RGMappingKernel.log" "$RUN/logs/ScanMapper.log" "$RUN/logs/GatewayDetection.log"
expect_output "checkpoint failed .*next attempt in .*rgmap.state: cannot replace: Is a directory"
expect_output "checkpoint failed .*next attempt in .*slam.state"
expect_output "checkpoint failed .*next attempt in .*gateways.state"

# While the map cannot be written the kernel's journal still gets each new scan, once.
lines=$(journal_lines)
for name in lab-4 lab-5 lab-6; do
  run "${RGMAP[@]}" name "$REGION" "$name"
  expect_ok
done
poll_until 30 journal_grew_past "$lines" || echo "  the journal got no scan in 30 s"
# A repeated scan: a journal line whose scan ID an earlier line has already.
run bash -c "echo \"journal lines=\$(wc -l <'$JOURNAL') repeated scans=\$(grep -o '\"id\":[0-9]*' '$JOURNAL' | sort | uniq -d | wc -l)\""
expect_output "repeated scans=0$"

# Writable again: every module checkpoints again and is healthy.
rmdir "$STATE/RGMappingKernel/rgmap.state"
rm -f "$STATE/ScanMapper" && mv "$WORK/ScanMapper.state" "$STATE/ScanMapper"
mkdir "$STATE/GatewayDetection"
poll_until 30 none_degraded || echo "  still DEGRADED 30 s after the state became writable"
run "${CTL[@]}" status
expect_output "RGMappingKernel +RUNNING"
expect_output "ScanMapper +RUNNING"
expect_output "GatewayDetection +RUNNING"
run grep -h "checkpoint written again" "$RUN/logs/RGMappingKernel.log"
expect_output "checkpoint written again after [0-9]+ failed attempt"
run test -f "$STATE/RGMappingKernel/rgmap.state" -a -f "$STATE/GatewayDetection/gateways.state"
expect_ok

run "${CTL[@]}" shutdown
expect_ok
poll_until 60 bash -c "! kill -0 $WATCHDOG_PID" || echo "  the watchdog did not stop within 60 s"
trap - EXIT
