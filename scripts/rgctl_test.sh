#!/usr/bin/env bash
# Tests rgctl's path handling: a log path and an export directory with YAML and sed specials go
# into the map set as YAML strings, paths with "${" are refused, each map run has its own run dir
# and ports, export names are the log's file name made safe, and the state of a run dir is
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
file=$(map_set_file '/logs/a "b" & c\d|e.log' '/maps/x&y' "$ROOT/run/map/r_d" 40001 40002 40003 40004 40005 40006)
check "the log is one YAML string" "grep -qF '\"--log\", \"/logs/a \\\"b\\\" & c\\\\d|e.log\"' '$file'"
check "the export root is one YAML string" "grep -qF '\"--export-root\", \"/maps/x&y\"' '$file'"
check "the set file is in its run dir" "[[ '$file' == '$ROOT/run/map/r_d/map.yaml' ]]"
check "the run dir is the set's" "grep -qF 'run_dir: \"$ROOT/run/map/r_d\"' '$file'"
check "no placeholder is left" "! grep -q '\"@LOG@\"\\|\"@OUT@\"\\|\"@RUN_DIR@\"' '$file'"
check "the ports are the given ones" "[[ \$(grep -o 'port: [0-9]*' '$file' | tr -dc '0-9\\n' | tr '\\n' ' ') == '40001 40002 40003 40004 40005 40006 ' ]]"
check "a path with \${ is refused" "! (map_set_file '/logs/\${HOME}.log' /maps \"$ROOT/run/map/x\") 2>/dev/null"
read -ra ports <<<"$(free_ports 6)"
check "six distinct free ports" "[[ \$(printf '%s\\n' ${ports[*]} | sort -u | wc -l) == 6 ]]"

check "the name drops .log" "[[ \$(map_export_name /x/intel.2003-run1.log) == intel.2003-run1 ]]"
check "two runs, two names" "[[ \$(map_export_name intel.2003-run2.log) == intel.2003-run2 ]]"
check "the name drops .log.gz" "[[ \$(map_export_name /x/intel-corrected.log.GZ) == intel-corrected ]]"
check "an unknown extension stays" "[[ \$(map_export_name /x/a.b.c) == a.b.c ]]"
check "specials become _" "[[ \$(map_export_name '/x/r&d.log') == r_d && \$(map_export_name 'p|q.log') == p_q && \$(map_export_name 'q\"uote.log') == q_uote ]]"
check "no leading dot or dash" "[[ \$(map_export_name '/x/.hidden.log') == _hidden && \$(map_export_name -x.log) == _x ]]"

mkdir -p "$ROOT/run/demo/state" "$ROOT/keep/state"
check "an empty run dir is refused" "! (clear_state '') 2>/dev/null"
check "a run dir outside run/ is refused" "! (clear_state '$ROOT/keep') 2>/dev/null && [[ -d '$ROOT/keep/state' ]]"
check "a run dir with .. is refused" "! (clear_state '$ROOT/run/../keep') 2>/dev/null && [[ -d '$ROOT/keep/state' ]]"
check "the state below run/ goes" "clear_state '$ROOT/run/demo' && [[ ! -e '$ROOT/run/demo/state' ]]"

[[ $failures -eq 0 ]] && echo "rgctl_test: all checks passed"
exit "$failures"
