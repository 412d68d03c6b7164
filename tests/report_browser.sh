#!/usr/bin/env bash
# report.browser: writes a report of gold and zinc (renders through glpreview when it can; else the pages say why)
# and checks it in headless chromium (tests/report_browser.mjs). The report and the screenshots stay in OUT.
# Usage: tests/report_browser.sh METALFIT NODE CHROMIUM OUT
set -euo pipefail
metalfit="$1" node="$2" chromium="$3" out="$4"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$out"
mkdir -p "$out"
"$metalfit" report Au,Zn --renders auto -o "$out/report"
# ESM imports resolve from the script's folder upwards: the repository's node_modules/.
"$node" "$here/report_browser.mjs" "$out/report" "$out/screenshots" "$chromium"
