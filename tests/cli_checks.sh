# What the command-line test scripts share; each sources it with its own arguments (GLINT
# OUTPUT_DIR [more]): $glint and $out from them, $here (the tests folder), a fresh output folder,
# counting passes and failures, the exit-code-2 check and the summary. Sourced, never run; the
# scripts keep their own checks beside these.
set -u
glint=$1
out=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rm -rf "$out" && mkdir -p "$out"
failures=0
passes=0
pass() { echo "ok   $1"; passes=$((passes + 1)); }
fail() { echo "FAIL $1"; failures=$((failures + 1)); }

# expect_error NAME REGEX [--] ARGS...: `glint ARGS` exits with code 2 and its stderr matches REGEX.
expect_error() {
  local name=$1 pattern=$2
  shift 2
  [[ ${1-} == -- ]] && shift
  "$glint" "$@" >"$out/$name.stdout" 2>"$out/$name.stderr"
  local code=$?
  if [[ $code -eq 2 ]] && grep -Eq -- "$pattern" "$out/$name.stderr"; then
    pass "$name: $(head -n 1 "$out/$name.stderr")"
  else
    fail "$name: exit code $code (expected 2), stderr (expected to match /$pattern/):"; cat "$out/$name.stderr"
  fi
}

# progress_lines LABEL FILE: FILE (stderr off a terminal) holds LABEL's progress as
# app/runtime/progress_line.h writes it there: whole lines without carriage returns, rising, at
# most 25 of them, the last at 100%.
progress_lines() {
  local lines
  lines=$(grep -F "$1" "$2")
  ! grep -q $'\r' "$2" && [[ -n $lines ]] && (($(wc -l <<<"$lines") <= 25)) &&
    [[ $(tail -n1 <<<"$lines") == "$1 100%" ]] &&
    sed "s/^.* \([0-9]*\)%$/\1/" <<<"$lines" | sort -n -u -c 2>/dev/null
}

# The counts; the script's exit status is 0 when nothing failed.
summary() {
  echo "$passes passed, $failures failed"
  [[ $failures -eq 0 ]]
}
