#!/usr/bin/env bash
# Tests rgctl's path handling: a log path and an export directory with YAML and sed specials go
# into the map set as YAML strings, paths with "${" are refused, and the state of a run dir is
# removed only for a non-empty path below run/.
set -u
RGCTL="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/rgctl"
# shellcheck source=rgctl
source "$RGCTL"
set +e
ROOT=$(mktemp -d)
trap 'rm -rf "$ROOT"' EXIT
failures=0
check() { if ! eval "$2"; then echo "FAIL: $1" >&2; failures=$((failures + 1)); fi; }

mkdir -p "$ROOT/config/sets/templates"
cp "$(dirname "$RGCTL")/../config/sets/templates/map.yaml" "$ROOT/config/sets/templates/"
file=$(map_set_file '/logs/a "b" & c\d|e.log' '/maps/x&y')
check "the log is one YAML string" "grep -qF '\"--log\", \"/logs/a \\\"b\\\" & c\\\\d|e.log\"' '$file'"
check "the export root is one YAML string" "grep -qF '\"--export-root\", \"/maps/x&y\"' '$file'"
check "no placeholder is left" "! grep -q '\"@LOG@\"\\|\"@OUT@\"' '$file'"
check "a path with \${ is refused" "! (map_set_file '/logs/\${HOME}.log' /maps) 2>/dev/null"

mkdir -p "$ROOT/run/demo/state" "$ROOT/keep/state"
check "an empty run dir is refused" "! (clear_state '') 2>/dev/null"
check "a run dir outside run/ is refused" "! (clear_state '$ROOT/keep') 2>/dev/null && [[ -d '$ROOT/keep/state' ]]"
check "a run dir with .. is refused" "! (clear_state '$ROOT/run/../keep') 2>/dev/null && [[ -d '$ROOT/keep/state' ]]"
check "the state below run/ goes" "clear_state '$ROOT/run/demo' && [[ ! -e '$ROOT/run/demo/state' ]]"

[[ $failures -eq 0 ]] && echo "rgctl_test: all checks passed"
exit "$failures"
