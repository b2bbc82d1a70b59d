# lib.sh: what an operator scenario (tests/operator/scenarios/*.sh) uses to drive RG Nav's tools as
# a user would and to judge their answers. A scenario is a bash script sourced by
# scripts/rgnav-faulttest-operator in a fresh temporary directory ($WORK); it calls `run` for each
# command a user types and then one of the verdicts on that command's answer:
#   expect_ok                   the command was to succeed (exit 0)
#   expect_refusal PATTERN      the command was to fail (exit != 0) with a message matching PATTERN
#                               (an extended regex, case-insensitive) that names the cause
#   expect_output PATTERN       the command's output matches PATTERN, whatever its exit code
# A wrong success is exit 0 where a refusal was due; a silent failure is a refusal or an output
# without the message that names the cause; a slow answer is one that took over $SLOW_S seconds
# (2 s: a tool that cannot do what it was asked says so at once). Each verdict counts into the
# scenario's figures, which `scenario_end` prints.
# Tools: $RGCTL (scripts/rgctl), $BIN (the built programs), $ROOT (the project), $SHARED (the data).

SLOW_S=${SLOW_S:-2}
WRONG_SUCCESS=0 SILENT_FAILURES=0 SLOW_ANSWERS=0 VERDICTS=0
RUN_OUT="" RUN_RC=0 RUN_SECONDS=0 RUN_WHAT=""

# run [--timeout S] CMD...: runs CMD (stdin from /dev/null), keeps its output, exit code and time.
# A command still running after S seconds (default 60) is ended and counts as a failure.
run() {
  local limit=60
  if [[ $1 == --timeout ]]; then limit=$2; shift 2; fi
  RUN_WHAT="$*"
  local start end
  start=$(date +%s.%N)
  RUN_OUT=$(timeout --kill-after=5 "$limit" "$@" </dev/null 2>&1)
  RUN_RC=$?
  end=$(date +%s.%N)
  RUN_SECONDS=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
}

_judge_time() {
  if awk -v s="$RUN_SECONDS" -v l="$SLOW_S" 'BEGIN { exit !(s > l) }'; then
    SLOW_ANSWERS=$((SLOW_ANSWERS + 1))
    echo "  slow (${RUN_SECONDS} s > ${SLOW_S} s): $RUN_WHAT"
  fi
}

_show() { printf '  | %s\n' "${RUN_OUT//$'\n'/$'\n'  | }" | head -n 8; }

expect_ok() {
  VERDICTS=$((VERDICTS + 1))
  if ((RUN_RC != 0)); then
    SILENT_FAILURES=$((SILENT_FAILURES + 1))
    echo "  failed (exit $RUN_RC) where it should work: $RUN_WHAT"; _show
  fi
}

expect_refusal() {
  VERDICTS=$((VERDICTS + 1))
  _judge_time
  if ((RUN_RC == 0)); then
    WRONG_SUCCESS=$((WRONG_SUCCESS + 1))
    echo "  wrong success (exit 0): $RUN_WHAT"; _show
  elif ! grep -qiE -- "$1" <<<"$RUN_OUT"; then
    SILENT_FAILURES=$((SILENT_FAILURES + 1))
    echo "  refused without naming the cause (/$1/ not found, exit $RUN_RC): $RUN_WHAT"; _show
  fi
}

expect_output() {
  VERDICTS=$((VERDICTS + 1))
  _judge_time
  if ! grep -qiE -- "$1" <<<"$RUN_OUT"; then
    SILENT_FAILURES=$((SILENT_FAILURES + 1))
    echo "  output lacks /$1/ (exit $RUN_RC): $RUN_WHAT"; _show
  fi
}

scenario_end() {
  echo "scenario: $SCENARIO verdicts=$VERDICTS wrong_success=$WRONG_SUCCESS silent_failures=$SILENT_FAILURES slow_answers=$SLOW_ANSWERS"
}
