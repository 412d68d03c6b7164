#!/usr/bin/env bash
# report.browser: writes a report of gold and zinc (renders through glpreview when it can; else the pages say why)
# and two of filmed titanium, and checks them in headless chromium (tests/report_browser.mjs). The report and the screenshots stay in OUT.
# Usage: tests/report_browser.sh METALFIT NODE CHROMIUM OUT
set -euo pipefail
metalfit="$1" node="$2" chromium="$3" out="$4"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$out"
mkdir -p "$out"
"$metalfit" report Au,Zn --renders auto -o "$out/report"
# A filmed material's page (the renderers' thin films scored), and the same film under a coat (why they are not).
"$metalfit" report Ti --film TiO2:80nm --model schlick --renders off -o "$out/filmed" > /dev/null
"$metalfit" report Ti --film TiO2:80nm --coat 1.5 --model schlick --renders off -o "$out/filmed-under-coat" > /dev/null
# ESM imports resolve from the script's folder upwards: the repository's node_modules/.
"$node" "$here/report_browser.mjs" "$out/report" "$out/screenshots" "$chromium" "$out/filmed" "$out/filmed-under-coat"
