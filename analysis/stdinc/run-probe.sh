#!/usr/bin/env bash
# Runs one probe scene with Debian's povray and prints its #debug output, finding the
# standard include files in INCLUDE_DIR only: POV-Ray's own (/usr/share/povray-3.7/include)
# to measure the expected output, or ours (analysis/stdinc) to check our files against it.
# Usage: run-probe.sh INCLUDE_DIR PROBE.pov
set -euo pipefail

include_dir=$(cd "$1" && pwd)
probe=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$probe" "$work/probe.pov"
# The include files are copied beside the probe because the scene's own directory is
# searched before any library path; that keeps the other set of files out of the way.
# An empty POVINI keeps the system povray.ini's library paths out as well.
cp "$include_dir"/*.inc "$work"/
# Fonts are data that scenes name, not include files; both sets of includes use POV-Ray's.
cp /usr/share/povray-3.7/include/*.ttf "$work"/
: >"$work/empty.ini"
(cd "$work" && POVINI="$work/empty.ini" timeout 300 povray +Iprobe.pov -D -F +W1 +H1 -GA +GDdebug.txt +GFfatal.txt >/dev/null 2>&1) || {
    echo "run-probe.sh: povray failed on $probe; its last output and error:" >&2
    tail -3 "$work/debug.txt" >&2 || true
    cat "$work/fatal.txt" >&2 || true
    exit 1
}
cat "$work/debug.txt"
