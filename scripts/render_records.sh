#!/bin/bash
# Render the calculation records (CASE.html) of the README's two example decks in a real
# browser: headless chromium draws each page as a screen shot (PNG) and prints it to A4 (PDF),
# and pdftoppm (poppler-utils), when installed, turns the PDF's pages into PNGs.
#
#   bash scripts/render_records.sh [OUT_DIR]       (default output/records)
#
# Installs nothing: it needs Debian's chromium (`apt-get install chromium`) and, for the
# print view as PNG, poppler-utils (`apt-get install poppler-utils`). The run's time is fixed
# (SOURCE_DATE_EPOCH) so that the pictures change only when the records do. Not part of
# `fpm test` (the browser is heavy); the test suite checks the HTML's structure instead.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/output/records}
decks=(input/tank_raft.dat input/strip_footing.dat)

browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    echo "render_records.sh: chromium not found (apt-get install chromium)" >&2
    exit 1
fi

cd "$root"
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fpm build >/dev/null
SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1795000000} \
    fpm run -- --quiet -o "$work" "${decks[@]}" >/dev/null

for deck in "${decks[@]}"; do
    stem=$(basename "$deck" .dat)
    page="$work/$stem.html"
    [ -f "$page" ] || { echo "render_records.sh: $page was not written" >&2; exit 1; }
    # the screen view: a window as wide as an A4 page at 96 dpi (794 px), tall enough for
    # the whole record
    "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
        --window-size=900,4200 --screenshot="$out/${stem}_screen.png" \
        "file://$page" >/dev/null 2>&1
    # the print view on A4 (the page's own @page rules), without the browser's header and
    # footer lines
    "$browser" --headless --no-sandbox --disable-gpu --no-pdf-header-footer \
        --print-to-pdf="$work/$stem.pdf" "file://$page" >/dev/null 2>&1
    if command -v pdftoppm >/dev/null; then
        rm -f "$out/${stem}_print"-*.png
        pdftoppm -png -r 80 "$work/$stem.pdf" "$out/${stem}_print"
    else
        cp "$work/$stem.pdf" "$out/$stem.pdf"
        echo "render_records.sh: pdftoppm not found (apt-get install poppler-utils):" \
             "the print view is left as $out/$stem.pdf" >&2
    fi
    echo "$deck -> $(cd "$out" && ls "${stem}"_*.png | tr '\n' ' ')"
done
