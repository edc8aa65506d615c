#!/usr/bin/env bash
# The repository's commit-msg hook (.githooks/commit-msg) accepts a message of the project's form
# and refuses a long subject or a body without the blank line.
set -euo pipefail
hook="$1/.githooks/commit-msg"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check() {  # check accept|refuse MESSAGE
  printf '%s' "$2" >"$work/message"
  if "$hook" "$work/message" 2>"$work/err"; then result=accept; else result=refuse; fi
  [[ $result == "$1" ]] || { echo "expected $1 for: $2 ($(cat "$work/err"))"; exit 1; }
}
long=$(printf 'x%.0s' {1..73})
check accept $'Shaders: one light loop for every count\n\nThe body says why.\n'
check accept "$(printf 'é%.0s' {1..72})"$'\n'  # characters, not bytes
check accept $'A subject alone\n'
check accept $'Subject\n\n# a comment git strips\n'
check refuse "$long"$'\n'
check refuse $'Subject\nbody on the second line\n'
check refuse $'\n\nbody without a subject\n'
echo "commit-msg hook: 7 messages judged as expected"
