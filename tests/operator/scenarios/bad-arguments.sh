# Bad command-line arguments: every tool refuses them at once, naming the argument and what is
# wrong with it, before it contacts a server; names are data and cannot forge an output line.
# The argument checks need no server. The unknown module, the name with a newline and the merge of
# regions the kernel does not have are asked of a small set of this scenario's own (an RG Mapping
# Kernel with nothing to map, on free ports, run dir in $WORK), brought down at the end.

# Region IDs, coordinates and counts are parsed strictly (no server needed: they are refused first).
run "$BIN/rgnav-rgmap" merge 2 3x
expect_refusal "region ID '3x' is not a whole number"
run "$BIN/rgnav-rgmap" name abc foo
expect_refusal "region ID 'abc' is not a whole number"
run "$BIN/rgnav-rgmap" name-object 1 nan 0 cab
expect_refusal "x 'nan' is not a finite number"
run "$BIN/rgnav-rgmap" path 1 0 0 0 1 1
expect_refusal "region ID '0' is not an ID"
run "$BIN/rgnav-rgmap" path 1 0 0 2 1 inf
expect_refusal "y 'inf' is not a finite number"
run "$BIN/rgnav-cat" laser --after -5
expect_refusal "--after '-5' is not a whole number"
run "$BIN/rgnav-cat" laser --batch 2x
expect_refusal "--batch '2x' is not a whole number"
run "$BIN/rgnav-plan" --from 1,2x --to 3,4
expect_refusal "--from '2x' is not a number"
run "$BIN/rgnav-plan" --from 1,2 --to 3,nan
expect_refusal "--to 'nan' is not a finite number"
run "$BIN/rgnav-plan" --from 1,2,3,4 --to 3,4
expect_refusal "--from '1,2,3,4' is not x,y or x,y,theta"
run "$BIN/rgnav-plan" --from 1,2 --to 3,4 --to-region 2
expect_refusal "give exactly one goal"
run "$BIN/rgnav-plan" --from 1,2 --to-region 0
expect_refusal "--to-region '0' is not an ID"
run "$BIN/rgnav-plan" --from 1,2 --to 3,4 --map "$WORK/no-such.rgmap.json"
expect_refusal "no-such\.rgmap\.json: cannot be read"

# rgctl: an unknown command and a map of a log that is not there (or is a directory) say so.
run "$RGCTL" bogus
expect_refusal "unknown command 'bogus'"
run "$RGCTL" map "$WORK/no-such.log"
expect_refusal "no log '.*no-such.log'"
mkdir -p "$WORK/logs"
run "$RGCTL" map "$WORK/logs"
expect_refusal "is a directory"
run "$RGCTL" map
expect_refusal "map wants a CARMEN log"

# A small set of this scenario's own, on free loopback ports.
read -r naming_port watchdog_port kernel_port < <(python3 -c '
import socket
socks = [socket.socket() for _ in range(3)]
for s in socks: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in socks])')
set_file="$WORK/bad-arguments.yaml"
cat >"$set_file" <<SET
robot: tumbot
host: 127.0.0.1
run_dir: "$WORK/run"
naming:
  host: 127.0.0.1
  port: $naming_port
  managed: true
watchdog:
  port: $watchdog_port
modules:
  - name: RGMappingKernel
    command: ["$BIN/rgnav-rgmappingkernel", "--config", "$ROOT/config/modules/rgmappingkernel.yaml",
              "--export-root", "$WORK/exports"]
    port: $kernel_port
    objects: [RGMappingKernel]
SET
mkdir -p "$WORK/run/logs" "$WORK/exports"
setsid "$BIN/rgnav-watchdog" --set "$set_file" </dev/null >>"$WORK/run/logs/watchdog.log" 2>&1 &
watchdog_pid=$!
trap '"$BIN/rgnav-ctl" --set "$set_file" shutdown >/dev/null 2>&1; wait "$watchdog_pid" 2>/dev/null' EXIT
# Up to 60 s: in the full test suite this runs beside the fault tests on two cores.
run --timeout 90 "$BIN/rgnav-ctl" --set "$set_file" wait-running --timeout 60
expect_ok
((RUN_RC == 0)) || sed 's/^/  | watchdog: /' "$WORK/run/logs/watchdog.log"
export RGNAV_NAMING="127.0.0.1:$naming_port"

# An unknown module is named as such, not as an unexpected exception.
run "$BIN/rgnav-ctl" --set "$set_file" restart Nope
expect_refusal "Nope"
if grep -qi "unexpected" <<<"$RUN_OUT"; then
  SILENT_FAILURES=$((SILENT_FAILURES + 1)); echo "  an unexpected exception instead of the cause: $RUN_WHAT"
fi
run "$BIN/rgnav-ctl" --set "$set_file" --timeout nan status
expect_refusal "--timeout 'nan' is not a finite number"

# A name with a newline is refused by the kernel; nothing injects a line into `regions`.
run "$BIN/rgnav-rgmap" name 1 $'lab\nregion 9 "forged"'
expect_refusal "control characters"
run "$BIN/rgnav-rgmap" regions
expect_ok
if grep -q "forged" <<<"$RUN_OUT"; then
  WRONG_SUCCESS=$((WRONG_SUCCESS + 1)); echo "  a name forged a line of the regions listing"
fi

# A merge of regions the kernel does not have is refused by it, naming them.
run "$BIN/rgnav-rgmap" merge 2 3
expect_refusal "cannot merge region 2 and region 3"
run "$BIN/rgnav-rgmap" merge 2 3 --force
expect_refusal "cannot merge region 2 and region 3"

"$BIN/rgnav-ctl" --set "$set_file" shutdown >/dev/null 2>&1
wait "$watchdog_pid" 2>/dev/null
trap - EXIT
