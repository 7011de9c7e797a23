#!/usr/bin/env bash
# Makes analysis/fonts/DejaVuSerif-Latin1.ttf, the font `text` uses when a scene names a
# font the caller did not supply: DejaVu Serif (Debian's fonts-dejavu-core) cut down to
# printable ASCII and Latin-1, without hinting, its kerning kept as a legacy kern table
# (the table POV-Ray reads). Needs fonttools (pip install fonttools).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
pyftsubset /usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf \
    --unicodes="U+0020-007E,U+00A0-00FF" --legacy-kern --no-hinting \
    --drop-tables+=GPOS,GSUB,GDEF,MATH,FFTM --name-IDs='*' \
    --output-file="$root/analysis/fonts/DejaVuSerif-Latin1.ttf"
