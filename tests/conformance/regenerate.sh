#!/usr/bin/env bash
# Regenerates the expected outputs of the conformance programs by running Debian's POV-Ray 3.7
# on each of them. For every <group>/<name>.pov it writes:
#   <name>.out   the Debug stream (#debug text), byte for byte;
#   <name>.err   when povray fails: "<file>:<line>: <message>" from the Fatal stream;
#   <name>.warn  when the program uses #warning: one "<file>:<line>: <message>" per warning.
# Usage: regenerate.sh [PROGRAM.pov...]   (no arguments: every program)
# The runner (tests::conformance::options in tests/src/conformance.rs) evaluates with the same
# image size and clock.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)

if ! command -v povray >/dev/null; then
    sudo_if_needed=""
    [ "$(id -u)" -ne 0 ] && sudo_if_needed="sudo"
    $sudo_if_needed apt-get update
    $sudo_if_needed apt-get install -y povray povray-includes
fi

# The image size and clock every program sees; keep in step with the runner.
options=(+W64 +H48 +K0.25)
include_dir=/usr/share/povray-3.7/include

export TZ=UTC LC_ALL=C

# Joins POV-Ray's console line wrapping back (a continuation line starts with a space) and turns
# its "File: F  Line: N" header plus message into "F:N: message". The File Context excerpt (up to
# five lines of the scene, ending at the error) is dropped.
located_messages() {
    awk '
        function flush() { if (msg != "") { print loc msg; loc = "" } msg = "" }
        /^File: .*  Line: [0-9]+$/ {
            flush()
            file = $0; sub(/^File: /, "", file); sub(/  Line: [0-9]+$/, "", file)
            line = $0; sub(/^.*  Line: /, "", line)
            loc = file ":" line ": "; context = 0; next
        }
        /^File Context \([0-9]+ lines\):$/ { context = 1; next }
        context && !/^(Parse|Possible Parse) Error: / { next }
        { context = 0 }
        /^ / && msg != "" { msg = msg $0; next }
        { flush(); msg = $0 }
        END { flush() }
    '
}

# Keeps only the warnings a #warning directive printed: POV-Ray adds its own at the end of every
# parse (no objects, no assumed_gamma), which are not part of what a program says.
user_warnings() {
    located_messages | grep -v -e ': Parse Warning: No objects in scene\.$' \
        -e '^Possible Parse Error: assumed_gamma not specified' || true
}

run_one() {
    local pov=$1
    local dir name work status
    # run_one runs in a fresh shell (xargs), without this script's `set -e`: a directory
    # that cannot be entered must stop it here, or the copy below would copy from `/`.
    dir=$(cd "$(dirname "$pov")" && pwd) || return 1
    [ -n "$dir" ] && [ -f "$pov" ] || { echo "no such program: $pov" >&2; return 1; }
    name=$(basename "$pov" .pov)
    work=$(mktemp -d /tmp/conformance.XXXXXX)
    # A private copy of the group, so that #write lands in the copy and runs do not collide.
    cp -r "$dir"/. "$work"/
    status=0
    (cd "$work" && timeout 60 povray "+I$name.pov" -D -F "${options[@]}" "+L$include_dir" \
        -GA "+GDdebug.txt" "+GFfatal.txt" "+GWwarning.txt" +WT1 >/dev/null 2>&1) || status=$?
    if [ -f "$work/debug.txt" ]; then cp "$work/debug.txt" "$dir/$name.out"; else : >"$dir/$name.out"; fi
    if [ "$status" -ne 0 ]; then
        if [ -s "$work/fatal.txt" ]; then
            located_messages <"$work/fatal.txt" >"$dir/$name.err"
        else
            echo "povray exited with status $status" >"$dir/$name.err"
        fi
    else
        rm -f "$dir/$name.err"
    fi
    if grep -q '#warning' "$pov"; then
        touch "$work/warning.txt"
        user_warnings <"$work/warning.txt" >"$dir/$name.warn"
    else
        rm -f "$dir/$name.warn"
    fi
    if awk 'length($0) >= 79 { found = 1 } END { exit !found }' "$dir/$name.out"; then
        echo "warning: $pov prints a line of 79+ characters, which POV-Ray wraps" >&2
    fi
    rm -rf "$work"
}

if [ "$#" -gt 0 ]; then
    programs=()
    # A program is named from the current directory or from this script's.
    for arg in "$@"; do
        case "$arg" in *.pov) ;; *) continue ;; esac
        if [ -f "$arg" ]; then
            programs+=("$(cd "$(dirname "$arg")" && pwd)/$(basename "$arg")")
        elif [ -f "$here/$arg" ]; then
            programs+=("$here/$arg")
        else
            echo "no such program: $arg" >&2
            exit 2
        fi
    done
else
    mapfile -t programs < <(find "$here" -mindepth 2 -name '*.pov' | sort)
fi

export -f run_one located_messages user_warnings
export include_dir
export options_string="${options[*]}"
# POV-Ray spends most of a run waiting, not computing, so run several per core.
printf '%s\0' "${programs[@]}" |
    xargs -0 -n 1 -P "$(( $(nproc) * 4 ))" bash -c 'read -r -a options <<<"$options_string"; run_one "$1"' _
echo "regenerated ${#programs[@]} programs"
