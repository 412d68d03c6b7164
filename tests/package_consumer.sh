#!/usr/bin/env bash
# package.find_package_consumer (tests/CMakeLists.txt): metalfit as a CMake package, from an install prefix.
#  1. `cmake --install` this build into a fresh temporary prefix, then move the prefix elsewhere (nothing may point
#     back at the first prefix, the build tree's install paths or the source tree's data);
#  2. configure, build and install tests/package_consumer into the moved prefix with find_package(metalfit 0.1)
#     (and COMPONENTS preview when glpreview is installed): every installed header compiles;
#  3. run the installed consumer with $METALFIT_DATA unset: it must find <moved prefix>/share/metalfit from its own
#     directory and print the F0 of gold and its f82-tint fit as this build's `metalfit show|fit gold --json` do
#     (within 1e-6); the installed metalfit must find the moved database too.
# Usage: package_consumer.sh BUILD_DIR CONSUMER_SOURCE METALFIT_EXE CMAKE CXX BUILD_TYPE CXX_FLAGS PYTHON
set -euo pipefail
build=$1 consumer=$2 metalfit=$3 cmake=$4 cxx=$5 build_type=$6 flags=$7 python=$8

work=$(mktemp -d "${TMPDIR:-/tmp}/metalfit-package.XXXXXX")
trap 'rm -rf "$work"' EXIT
unset METALFIT_DATA OCIO

step() { echo "package_consumer: $*"; }
step "install $build into $work/prefix"
"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log"
mv "$work/prefix" "$work/moved"
prefix="$work/moved"
for f in lib/cmake/metalfit/metalfitConfig.cmake lib/cmake/metalfit/metalfitConfigVersion.cmake \
         lib/cmake/metalfit/metalfitTargets.cmake include/libfit/base/version.hpp include/libfit/base/data_dir.hpp \
         share/metalfit/catalog.json share/metalfit/ocio/config.ocio share/metalfit/cie/SOURCES.md bin/metalfit; do
  [[ -e "$prefix/$f" ]] || { echo "package_consumer: not installed: $f" >&2; exit 1; }
done
if find "$prefix/include" -name '*.cpp' | grep -q .; then
  echo "package_consumer: .cpp files installed under include/:" >&2; find "$prefix/include" -name '*.cpp' >&2; exit 1
fi
if grep -rlF -e "$build" -e "$work/prefix" "$prefix/lib/cmake"; then
  echo "package_consumer: the installed CMake files name the build tree or the install prefix (not relocatable)" >&2
  exit 1
fi

preview=OFF
[[ -e "$prefix/lib/cmake/metalfit/metalfitPreviewTargets.cmake" ]] && preview=ON
step "configure and build the consumer against $prefix (preview component: $preview)"
"$cmake" -S "$consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_BUILD_TYPE="$build_type" -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" \
  -DCONSUMER_PREVIEW=$preview > "$work/configure.log" || { cat "$work/configure.log" >&2; exit 1; }
grep -- "-- metalfit " "$work/configure.log"
"$cmake" --build "$work/consumer" -j2 > "$work/build.log" || { cat "$work/build.log" >&2; exit 1; }
"$cmake" --install "$work/consumer" --prefix "$prefix" > /dev/null

step "run $prefix/bin/consumer (METALFIT_DATA unset) from /"
(cd / && "$prefix/bin/consumer") > "$work/consumer.txt"
cat "$work/consumer.txt"
(cd / && "$prefix/bin/metalfit" show gold --json) > "$work/installed-show.json"
"$metalfit" show gold --json > "$work/show.json"
"$metalfit" fit gold --model f82-tint --json > "$work/fit.json"
"$python" - "$work" "$prefix" <<'PY'
import json, os, sys
work, prefix = sys.argv[1], sys.argv[2]
values = {}
for line in open(os.path.join(work, "consumer.txt")):
    key, *rest = line.split()
    values.setdefault(key, []).append(rest)
expected_data = os.path.join(prefix, "share", "metalfit")
show = json.load(open(os.path.join(work, "show.json")))
installed = json.load(open(os.path.join(work, "installed-show.json")))
data = values["data_dir"][0][0]
if os.path.realpath(data) != os.path.realpath(expected_data):
    sys.exit(f"package_consumer: the consumer used the database {data}, not the installed {expected_data}")
# Records name the database's files relative to the database the run used ("data:nk/Au/Johnson.yml", docs/fit-record.md
# "Paths in records"): they must be files of the installed one.
for key in ("file", "ocio_config"):
    used = installed["provenance"][key]
    if not used.startswith("data:") or not os.path.isfile(os.path.join(expected_data, used[len("data:"):])):
        sys.exit(f"package_consumer: the installed metalfit read {used}, not a file of {expected_data}")
def channels(key):
    got = {int(c): float(v) for c, v in values[key]}
    return [got[c] for c in range(3)]
fit = json.load(open(os.path.join(work, "fit.json")))["materials"]["Au"]["models"]["f82-tint"]["fit"]["params"]
checks = [("F0 vs metalfit show", channels("F0"), show["F0"]),
          ("F0 vs the installed metalfit show", channels("F0"), installed["F0"]),
          ("f82-tint F0 vs metalfit fit", channels("fit_F0"), fit["F0"]),
          ("f82-tint tint vs metalfit fit", channels("fit_tint"), fit["tint"])]
bad = False
for name, got, want in checks:
    worst = max(abs(g - w) for g, w in zip(got, want))
    print(f"package_consumer: {name}: max |difference| {worst:.3g}")
    bad |= not worst <= 1e-6
sys.exit(1 if bad else 0)
PY
step "ok"
