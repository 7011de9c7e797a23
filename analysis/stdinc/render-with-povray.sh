#!/usr/bin/env bash
# Renders each scene of analysis/stdinc/renders/ with Debian's povray twice, once with
# POV-Ray's own include files and once with ours, and reports how far the two images
# differ: the share of pixels that differ at all and the mean and largest difference per
# channel (0-255).  Where the files must behave alike (screen.inc's placement) the images
# must agree; where ours are our own designs (the textures) the figures say how far our
# looks are from POV-Ray's.
# Textures with crand differ from run to run even in POV-Ray; --baseline renders with
# POV-Ray's files twice, to show how much.  --keep DIR keeps both images of each scene
# (DIR/NAME.theirs.ppm and DIR/NAME.ours.ppm), to look at.
# Usage: analysis/stdinc/render-with-povray.sh [--baseline] [--keep DIR] [SCENE.pov...]
# (every scene renders at 240x180 without antialiasing)
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
std=${POVRAY_INCLUDE_DIR:-/usr/share/povray-3.7/include}
command -v povray >/dev/null || { echo "render-with-povray.sh: needs povray (apt-get install povray)" >&2; exit 1; }
ours=$here
keep=""
while [ $# -gt 0 ]; do
    case $1 in
        --baseline) ours=$std; shift ;;
        --keep) keep=$(mkdir -p "$2" && cd "$2" && pwd); shift 2 ;;
        *) break ;;
    esac
done
[ $# -gt 0 ] || set -- "$here"/renders/*.pov
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
: >"$work/empty.ini"

render() { # render INCLUDE_DIR SCENE OUTPUT
    local dir
    dir=$(mktemp -d -p "$work")
    cp "$1"/*.inc "$dir"/
    cp "$std"/*.ttf "$std"/*.map "$std"/*.png "$dir"/ 2>/dev/null || true
    cp "$2" "$dir/scene.pov"
    (cd "$dir" && POVINI="$work/empty.ini" timeout 600 povray +Iscene.pov +O"$3" +FP +W240 +H180 -A -D \
        >"$dir/log.txt" 2>&1) || { echo "povray failed on $2:"; grep -A3 'Error' "$dir/log.txt" | head -8; return 1; }
}

for scene in "$@"; do
    name=$(basename "$scene" .pov)
    render "$std" "$scene" "$work/$name.theirs.ppm" && render "$ours" "$scene" "$work/$name.ours.ppm" || continue
    [ -z "$keep" ] || cp "$work/$name.theirs.ppm" "$work/$name.ours.ppm" "$keep"/
    python3 - "$name" "$work/$name.theirs.ppm" "$work/$name.ours.ppm" <<'PY'
import sys

def read_ppm(path):
    data = open(path, 'rb').read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b'#':  # a comment runs to the end of its line
            pos = data.index(b'\n', pos)
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    return int(fields[1]), int(fields[2]), data[pos + 1:]

name, theirs, ours = sys.argv[1], read_ppm(sys.argv[2]), read_ppm(sys.argv[3])
a, b = theirs[2], ours[2]
pixels = len(a) // 3
differing = sum(1 for i in range(0, len(a), 3) if a[i:i + 3] != b[i:i + 3])
diffs = [abs(x - y) for x, y in zip(a, b)]
print(f"{name:24} differing pixels {100 * differing / pixels:6.2f}%  mean {sum(diffs) / len(diffs):6.2f}  max {max(diffs):3}")
PY
done
