# Supervision as an operator meets it: a set of its own (omniNames and a simulator on free ports,
# run dir in $WORK). Status of a set that is not up; a second set on the same ports (port clash);
# a SIGSTOPped watchdog; a SIGKILLed watchdog whose modules keep running (status and down find
# them from the state file); and `up` after the run dir was deleted while those modules still hold
# the ports; a new watchdog adopting the modules of a killed one (their real uptime); a module
# whose program does not exist (the cause, not an exit code). Every refusal must name its cause
# within 2 s. Every process started here is ended by
# its PID at the end, also when the scenario fails half-way.

STARTED_PIDS=()
# `rgctl up` remembers the set it started in run/.last-set: the user's own is put back afterwards.
LAST_SET_FILE="$ROOT/run/.last-set"
LAST_SET_SAVED=$(cat "$LAST_SET_FILE" 2>/dev/null)
cleanup_supervision() {
  local pid
  for pid in "${STARTED_PIDS[@]}"; do kill -CONT "$pid" 2>/dev/null; kill -KILL "$pid" 2>/dev/null; done
  if [[ -n $LAST_SET_SAVED ]]; then echo "$LAST_SET_SAVED" >"$LAST_SET_FILE"; else rm -f -- "$LAST_SET_FILE"; fi
  return 0
}
trap cleanup_supervision EXIT

# Free loopback ports: naming service, watchdog, simulator; and the naming service, watchdog and
# module of a set whose module cannot be spawned.
read -r NAMING_PORT WATCHDOG_PORT SIM_PORT NAMING_PORT_C WATCHDOG_PORT_C MISSING_PORT < <(python3 -c '
import socket
socks = [socket.socket() for _ in range(6)]
for s in socks: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in socks])')

# write_set FILE RUN_DIR: a set on the ports above.
write_set() {
  cat >"$1" <<EOF
robot: tumbot
host: 127.0.0.1
run_dir: $2
naming: {host: 127.0.0.1, port: $NAMING_PORT, managed: true}
watchdog: {port: $WATCHDOG_PORT}
modules:
  - name: Simulator
    command: ["\${RGNAV_BIN}/rgnav-sim", "--world", "\${RGNAV_ROOT}/config/worlds/office.yaml",
              "--config", "\${RGNAV_ROOT}/config/sim/default.yaml", "--start", "1.5,7,0"]
    port: $SIM_PORT
    objects: [Laser, Base, GroundTruth]
EOF
}
SET_A="$WORK/sets/opa.yaml" SET_B="$WORK/sets/opb.yaml"
mkdir -p "$WORK/sets"
write_set "$SET_A" "$WORK/run-a"
write_set "$SET_B" "$WORK/run-b"

# The PIDs in the PID column of a status table (modules, leftovers).
remember_table_pids() {
  local pid
  while read -r pid; do STARTED_PIDS+=("$pid"); done < <(awk 'NR > 1 && $3 ~ /^[0-9]+$/ && $3 > 0 { print $3 }' <<<"$RUN_OUT")
}
# The watchdog PID `rgctl up` reports.
remember_watchdog_pid() {
  WATCHDOG_PID=$(grep -oE 'watchdog pid [0-9]+' <<<"$RUN_OUT" | grep -oE '[0-9]+' | head -n 1)
  [[ -n $WATCHDOG_PID ]] && STARTED_PIDS+=("$WATCHDOG_PID")
}
wait_gone() { for _ in $(seq 1 100); do kill -0 "$1" 2>/dev/null || return 0; sleep 0.05; done; }

# Nothing runs yet: said at once, with the address tried.
run "$RGCTL" status "$SET_A"
expect_refusal "set 'opa' is not up \(no watchdog at 127\.0\.0\.1:$WATCHDOG_PORT\)"

run "$RGCTL" up "$SET_A"
remember_watchdog_pid
expect_ok
run "$RGCTL" status "$SET_A"
remember_table_pids
expect_output "Simulator +RUNNING"

# A second set on the same ports: refused before it starts, naming the port and who holds it;
# its status and wait-running name the clash instead of showing the other set's modules.
run "$RGCTL" up "$SET_B"
expect_refusal "port $WATCHDOG_PORT \(its watchdog\) is held by pid $WATCHDOG_PID"
run "$RGCTL" status "$SET_B"
expect_refusal "port $WATCHDOG_PORT .* is held by pid $WATCHDOG_PID .*not by this set's watchdog"
run "$BIN/rgnav-ctl" --set "$SET_B" wait-running --timeout 5
expect_refusal "held by pid $WATCHDOG_PID"

# A stopped watchdog: said at once, with its PID, its state and what to do.
kill -STOP "$WATCHDOG_PID"
run "$RGCTL" status "$SET_A"
expect_refusal "pid $WATCHDOG_PID .*does not answer: it is stopped.*kill -CONT $WATCHDOG_PID"
run "$RGCTL" down "$SET_A"
expect_refusal "pid $WATCHDOG_PID .*does not answer: it is stopped.*kill -CONT $WATCHDOG_PID"
kill -CONT "$WATCHDOG_PID"

# A killed watchdog: its modules keep running; status finds them from the state file, and a new
# watchdog adopts them, showing how long they have really run.
kill -KILL "$WATCHDOG_PID"
wait_gone "$WATCHDOG_PID"
run "$RGCTL" status "$SET_A"
remember_table_pids
expect_refusal "set 'opa' is not up .*2 of its modules still run"
LEFTOVER_AGE=$(awk '$1 == "Simulator" { print $4 }' <<<"$RUN_OUT")
run "$RGCTL" up "$SET_A"
remember_watchdog_pid
expect_ok
run "$RGCTL" status "$SET_A"
expect_output "Simulator +RUNNING"
ADOPTED_UPTIME=$(awk '$1 == "Simulator" { print $4 }' <<<"$RUN_OUT")
run awk -v a="${ADOPTED_UPTIME:-0}" -v l="${LEFTOVER_AGE:-1}" 'BEGIN { print (a >= l ? "adopted uptime is the process uptime" : "adopted uptime " a " s < " l " s") }'
expect_output "adopted uptime is the process uptime"

# Killed again: down stops what it left running.
kill -KILL "$WATCHDOG_PID"
wait_gone "$WATCHDOG_PID"
run "$RGCTL" down "$SET_A"
expect_output "stopping the 2 modules it left running.*NameService \(pid [0-9]+\).*Simulator \(pid [0-9]+\)"
run "$RGCTL" status "$SET_A"
expect_refusal "set 'opa' is not up \(no watchdog at 127\.0\.0\.1:$WATCHDOG_PORT\)$"

# Killed again, and the run dir deleted: the leftovers still hold the ports; up names them.
run "$RGCTL" up "$SET_A"
remember_watchdog_pid
expect_ok
run "$RGCTL" status "$SET_A"
remember_table_pids
SIM_PID=$(awk '$1 == "Simulator" { print $3 }' <<<"$RUN_OUT")
kill -KILL "$WATCHDOG_PID"
wait_gone "$WATCHDOG_PID"
rm -rf -- "$WORK/run-a"
run "$RGCTL" up "$SET_A"
expect_refusal "port $SIM_PORT \(its Simulator\) is held by pid $SIM_PID"

# A module whose program does not exist: up fails, and the status says why.
SET_C="$WORK/sets/opc.yaml"
cat >"$SET_C" <<EOF
robot: tumbot
host: 127.0.0.1
run_dir: $WORK/run-c
naming: {host: 127.0.0.1, port: $NAMING_PORT_C, managed: true}
watchdog: {port: $WATCHDOG_PORT_C}
modules:
  - name: Missing
    command: ["$WORK/no-such-program"]
    port: $MISSING_PORT
    objects: [Missing]
    max_restarts: 1
    backoff_initial_s: 0.05
EOF
run "$RGCTL" up "$SET_C"
remember_watchdog_pid
expect_refusal "Missing is FATAL: .*cannot exec '$WORK/no-such-program': No such file or directory"
run "$RGCTL" status "$SET_C"
remember_table_pids
expect_output "Missing +FATAL +0 +[0-9.]+ +1  FATAL: .*after 1 restarts"
run "$RGCTL" down "$SET_C"
expect_ok
