#!/usr/bin/env bash
# Checks our include files with the reference implementation: runs every probe scene with
# Debian's povray reading analysis/stdinc's files instead of POV-Ray's, and compares the
# output with the expected output that measure.sh recorded from POV-Ray's own files.
# Usage: analysis/stdinc/check-with-povray.sh [PROBE.pov...]
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
command -v povray >/dev/null || { echo "check-with-povray.sh: needs povray (apt-get install povray)" >&2; exit 1; }
[ $# -gt 0 ] || set -- "$here"/probes/*.pov
failed=0
actual=$(mktemp)
trap 'rm -f "$actual"' EXIT
for probe in "$@"; do
    name=$(basename "$probe")
    if ! "$here/run-probe.sh" "$here" "$probe" >"$actual" 2>&1; then
        echo "FAILS   $name"
        sed 's/^/        /' "$actual" | head -8
        failed=1
    elif diff -u "${probe%.pov}.out" "$actual" >"$actual.diff"; then
        echo "ok      $name"
    else
        echo "DIFFERS $name"
        head -40 "$actual.diff"
        failed=1
    fi
    rm -f "$actual.diff"
done
exit $failed
