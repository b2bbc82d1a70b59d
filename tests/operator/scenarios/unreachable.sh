# Tools that cannot reach their servers: within 2 s a refusal that names the naming service's
# address and the object looked up (RGNav/<robot>/<Object>), and what to do; and a map exported
# over existing files, or onto a file that cannot be written, against a real set of our own
# (free ports, run directory in $WORK), where the user sees the kernel's cause.

free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }

# Nothing listens on this port: every tool says so at once, naming the address and the object.
nowhere=$(free_port)
run env RGNAV_NAMING="127.0.0.1:$nowhere" "$BIN/rgnav-rgmap" regions
expect_refusal "RGNav/tumbot/RGMappingKernel in the naming service at 127\.0\.0\.1:$nowhere"
expect_output "is the set up\?.*rgctl up"
run env RGNAV_NAMING="127.0.0.1:$nowhere" "$BIN/rgnav-rgmap" export "" again
expect_refusal "RGNav/tumbot/RGMappingKernel in the naming service at 127\.0\.0\.1:$nowhere"
run "$BIN/rgnav-cat" laser --naming "127.0.0.1:$nowhere"
expect_refusal "RGNav/tumbot/Laser in the naming service at 127\.0\.0\.1:$nowhere"
run "$BIN/rgnav-plan" --naming "127.0.0.1:$nowhere" --from 1,1 --to 9,4
expect_refusal "RGNav/tumbot/PathPlanning in the naming service at 127\.0\.0\.1:$nowhere"
run env RGNAV_NAMING="127.0.0.1:$nowhere" RGNAV_ROBOT=scout "$BIN/rgnav-cat" gateways
expect_refusal "RGNav/scout/GatewayDetection in the naming service at 127\.0\.0\.1:$nowhere"
# An address that is no host:port is refused as such, not handed to the ORB to abort on.
run "$BIN/rgnav-rgmap" regions --naming "a b:$nowhere"
expect_refusal "'a b:$nowhere' has no valid host"
# Without RGNAV_NAMING the default address is tried and named (a robot nobody runs, so that a
# naming service someone else may run there has no such name either).
run env -u RGNAV_NAMING "$BIN/rgnav-rgmap" regions --robot "nobody-$$"
expect_refusal "RGNav/nobody-$$/RGMappingKernel in the naming service at 127\.0\.0\.1:2809"

# A set of our own on free ports: the map set on the Intel log.
naming=$(free_port) watchdog=$(free_port)
ports=() && for _ in 1 2 3 4; do ports+=("$(free_port)"); done
mkdir -p "$WORK/out"
sed -e "s|port: 12859|port: $naming|; s|port: 12860|port: $watchdog|" \
    -e "s|port: 12861|port: ${ports[0]}|; s|port: 12862|port: ${ports[1]}|" \
    -e "s|port: 12863|port: ${ports[2]}|; s|port: 12864|port: ${ports[3]}|" \
    -e "s|\"@LOG@\"|\"$SHARED/data/laser/corrected/intel-corrected.log.gz\"|; s|\"@OUT@\"|\"$WORK/out\"|" \
    -e "s|\"@RUN_DIR@\"|\"$WORK/run\"|" "$ROOT/config/sets/templates/map.yaml" >"$WORK/set.yaml"
# A watchdog (rgnav-ctl) that is not up yet is named by its address, at once.
run "$BIN/rgnav-ctl" --set "$WORK/set.yaml" restart ScanMapper
expect_refusal "127\.0\.0\.1:$watchdog"
export RGNAV_BIN="$BIN" RGNAV_ROOT="$ROOT"
setsid "$BIN/rgnav-watchdog" --set "$WORK/set.yaml" </dev/null >"$WORK/watchdog.log" 2>&1 &
set_watchdog=$!
trap '"$BIN/rgnav-ctl" --set "$WORK/set.yaml" shutdown >/dev/null 2>&1 || kill -TERM "$set_watchdog" 2>/dev/null; wait "$set_watchdog" 2>/dev/null' EXIT
run "$BIN/rgnav-ctl" --set "$WORK/set.yaml" wait-running --timeout 30
expect_ok
export RGNAV_NAMING="127.0.0.1:$naming"
run --timeout 300 "$BIN/rgnav-rgmap" build --quiet --label intel --name intel
expect_ok
# Exporting over the files just written replaces them.
run "$BIN/rgnav-rgmap" export "" intel
expect_ok
# A file in the way: the kernel's cause, not a bare exception name.
mkdir "$WORK/out/blocked.rgmap.json"
run "$BIN/rgnav-rgmap" export "" blocked
expect_refusal "blocked\.rgmap\.json.*Is a directory"
# A module that is not registered in a naming service that answers: named, at once.
run "$BIN/rgnav-rgmap" regions --robot nobody
expect_refusal "RGNav/nobody/RGMappingKernel in the naming service at 127\.0\.0\.1:$naming \(last: the name is not bound"
run "$BIN/rgnav-ctl" --set "$WORK/set.yaml" shutdown
expect_ok
wait "$set_watchdog" 2>/dev/null
trap - EXIT
