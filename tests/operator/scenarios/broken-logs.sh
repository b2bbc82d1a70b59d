# Broken and oddly named logs through `rgctl map`, and two maps at once. The logs are made in
# $WORK from the first lines of the Intel log: a .gz cut inside its compressed stream and a log
# with every other FLASER line cut in half must be refused at the end of the map (exit 3) naming
# the skipped lines or the early end with their first file:line; two maps of different logs at
# once each export their own log's map; the same name twice at once, or while a watchdog runs
# that name's set, is refused; a log named r&d.log maps; a second log of an existing map's name
# is refused at once. The logs' names start "bl-", and so their sets' run dirs (removed at the end).
intel="$SHARED/data/laser/corrected/intel-corrected.log.gz"
out="$WORK/out"
lastSet=$(cat "$ROOT/run/.last-set" 2>/dev/null)
trap '"$RGCTL" down map/bl-twin >/dev/null 2>&1; rm -rf -- "$ROOT"/run/map/bl-*
      if [[ -n $lastSet ]]; then echo "$lastSet" >"$ROOT/run/.last-set"; else rm -f "$ROOT/run/.last-set"; fi' EXIT
mkdir -p "$WORK/a" "$WORK/b" "$out"
zcat "$intel" | head -n 3000 >"$WORK/bl-small.log"
zcat "$intel" | head -n 1500 >"$WORK/bl-other.log"
zcat "$intel" | head -n 4000 | gzip -c >"$WORK/whole.log.gz"
head -c $(($(stat -c %s "$WORK/whole.log.gz") * 2 / 3)) "$WORK/whole.log.gz" >"$WORK/bl-trunc.log.gz"
awk '/^FLASER / { if (n++ % 2 == 0) $0 = substr($0, 1, int(length($0) / 2)) } { print }' "$WORK/bl-small.log" >"$WORK/bl-garbled.log"
cp "$WORK/bl-other.log" "$WORK/bl-r&d.log"
cp "$WORK/bl-other.log" "$WORK/a/bl-twin.log"
cp "$WORK/bl-other.log" "$WORK/b/bl-twin.log"
cp "$WORK/bl-other.log" "$WORK/a/bl-small.log"
smallScans=$(grep -c '^FLASER ' "$WORK/bl-small.log")
otherScans=$(grep -c '^FLASER ' "$WORK/bl-other.log")

# A map's answer comes when the map is done: the time limit of these verdicts is the map's.
SLOW_S=120

run --timeout 300 "$RGCTL" map "$WORK/bl-trunc.log.gz" --out "$out"
expect_refusal "truncated=yes"
expect_output "log ends early.*bl-trunc\.log\.gz:[0-9]+: gzip data ends early"

run --timeout 300 "$RGCTL" map "$WORK/bl-garbled.log" --out "$out"
expect_refusal "skipped_lines=[1-9][0-9]* truncated=no"
expect_output "[0-9]+ malformed lines skipped, the first .*bl-garbled\.log:[0-9]+: FLASER"

SLOW_S=2
run "$RGCTL" logs LogPlayback
expect_output "malformed lines skipped, the first .*bl-garbled\.log:[0-9]+"

SLOW_S=120
run --timeout 300 "$RGCTL" map "$WORK/bl-garbled.log" --out "$out" --overwrite --accept-partial
expect_ok
expect_output "map bl-garbled: scans=[0-9]+ .*skipped_lines=[1-9][0-9]* truncated=no"

# Two maps of different logs at once: each its own set, ports and map.
run --timeout 300 bash -c '"$1" map "$2" --out "$4" & first=$!; "$1" map "$3" --out "$4"; second=$?
                           wait "$first"; exit $(($? | second))' _ "$RGCTL" "$WORK/bl-small.log" "$WORK/bl-other.log" "$out"
expect_ok
expect_output "map bl-small: scans=$smallScans .*skipped_lines=0 truncated=no"
expect_output "map bl-other: scans=$otherScans .*skipped_lines=0 truncated=no"

# The same name twice at once: one maps, the other is refused, saying why.
run --timeout 300 bash -c '"$1" map "$2" --out "$4" & first=$!; "$1" map "$3" --out "$4"; second=$?
                           wait "$first"; exit $(($? & second))' _ "$RGCTL" "$WORK/a/bl-twin.log" "$WORK/b/bl-twin.log" "$out"
expect_output "map bl-twin: scans=$otherScans "
expect_output "a map named 'bl-twin' is being made now|bl-twin\.rgmap\.json exists"

SLOW_S=2
# A watchdog already runs the set of that name: refused at once, the running set left alone.
run --timeout 60 "$RGCTL" up map/bl-twin
expect_ok
run "$RGCTL" map "$WORK/a/bl-twin.log" --out "$out" --overwrite
expect_refusal "another watchdog already runs the set map/bl-twin"
run --timeout 60 "$RGCTL" down map/bl-twin
expect_ok

SLOW_S=120

run --timeout 300 "$RGCTL" map "$WORK/bl-r&d.log" --out "$out"
expect_ok
expect_output "map bl-r_d: scans=$otherScans "

SLOW_S=2
# Another log whose name is that of an existing map: refused at once, not overwritten.
run "$RGCTL" map "$WORK/a/bl-small.log" --out "$out"
expect_refusal "bl-small\.rgmap\.json exists.*--name"
