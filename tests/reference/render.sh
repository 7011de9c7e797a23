#!/usr/bin/env bash
# Renders the reference images of the fidelity scenes listed in scenes.txt with Debian's
# POV-Ray 3.7, one thread (+WT1), at each scene's settings, into png/NAME.png, and records
# POV-Ray's own parse and trace times in povray-times.txt for the benchmark: the CPU
# seconds it reports, which other work on the machine disturbs less than wall time (the
# trace time includes the radiosity pretrace and the photon pass, which POV-Ray reports
# apart).
#
# Scenes that include standard include files get ours (analysis/stdinc), not POV-Ray's:
# the designs in them are our own, and the references must show what our files describe.
# An empty POVINI keeps POV-Ray's library path out.
#
#   tests/reference/render.sh            every scene
#   tests/reference/render.sh basic csg  only these
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"

if ! command -v povray >/dev/null; then
    if [ "$(id -u)" = 0 ]; then
        apt-get update -qq && apt-get install -y -qq povray >/dev/null
    else
        echo "render.sh: povray is not installed (apt-get install povray)" >&2
        exit 1
    fi
fi

mkdir -p "$here/png"
times="$here/povray-times.txt"
[ -f "$times" ] || echo "# scene parse_cpu_seconds trace_cpu_seconds (povray +WT1)" > "$times"
log="$(mktemp)"
no_ini="$(mktemp --suffix=.ini)"
trap 'rm -f "$log" "$no_ini"' EXIT

while read -r line; do
    line="${line%%|*}"
    [[ -z "${line// }" || "$line" == \#* ]] && continue
    read -r name scene options <<<"$line"
    if [ $# -gt 0 ] && [[ ! " $* " == *" $name "* ]]; then
        continue
    fi
    # shellcheck disable=SC2086 # the options are separate words on purpose
    POVINI="$no_ini" povray "+I$root/$scene" "+O$here/png/$name.png" +FN -D -V +WT1 $options \
        "+L$(dirname "$root/$scene")" "+L$root/analysis/stdinc" >"$log" 2>&1 || { cat "$log" >&2; exit 1; }
    # The CPU seconds follow each "Parse Time", "Photon Time", "Radiosity Time" and "Trace
    # Time" line.
    cpu() { grep -A1 -m1 "$1" "$log" | sed -nE 's/.* ([0-9.]+) CPU-seconds.*/\1/p'; }
    parse=$(cpu 'Parse Time:')
    radiosity=$(cpu 'Radiosity Time:')
    photons=$(cpu 'Photon Time:')
    trace=$(awk -v t="$(cpu 'Trace Time:')" -v r="${radiosity:-0}" -v p="${photons:-0}" \
        'BEGIN { printf "%.3f", t + r + p }')
    grep -v "^$name " "$times" > "$times.new" || true
    echo "$name $parse $trace" >> "$times.new"
    mv "$times.new" "$times"
    echo "$name: parse ${parse}s trace ${trace}s"
done < "$here/scenes.txt"
