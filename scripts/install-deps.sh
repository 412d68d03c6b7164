#!/usr/bin/env bash
# Installs the Debian packages metalfit needs, only those that are missing.
# The list below is the single place where the project's system dependencies are named.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config     # toolchain
  ninja-build                          # the presets' generator: one scheduler for the whole build
  ccache                               # compiler cache (the build uses it when present; CMakeLists.txt)
  libgtest-dev                         # tests
  libceres-dev libeigen3-dev           # fitting, linear algebra
  libopencolorio-dev opencolorio-tools # colour management (ociocheck is used by a test)
  libopenexr-dev libpng-dev            # glpreview's EXR and PNG files
  libopenimageio-dev                   # glpreview's OpenImageIO module: other environment formats, the sheet's labels
  nlohmann-json3-dev                   # JSON
  libyaml-cpp-dev                      # refractiveindex.info YAML
  libcli11-dev                         # command line
  libssl-dev                           # SHA-256 of data files (OpenSSL libcrypto)
  libpugixml-dev                       # XML: MaterialX exports written and checked with pugixml
  glslang-tools                        # glslangValidator: the models' GLSL → SPIR-V for the MSL (build), tests
  spirv-cross                          # SPIRV-Cross: the models' MSL, translated at build time (required)
  pngcheck                             # reads back the colour chunks of glpreview's PNGs (a test)
  libbenchmark-dev                     # Google Benchmark: bench/ (metalfit_benchmarks)
  libopengl-dev libegl-dev             # glpreview: GL 4.5 core through libglvnd, headless EGL
  libegl-mesa0 libgl1-mesa-dri         # Mesa's EGL and llvmpipe: the preview runs without a GPU
  fonts-dejavu-core                    # DejaVu Sans: glpreview's sheet labels (OpenImageIO render_text finds it)
  chromium                             # metalfit report: the browser test opens the pages headless
  clang libclang-rt-14-dev             # the optional fuzz preset: clang with libFuzzer and the sanitizers (fuzz/)
  clang-format                         # scripts/check-format.sh and the ctest format.check (.clang-format)
  python3-dev pybind11-dev python3-numpy # the Python module `metalfit` (python/; built when they are found)
  python3-pytest                       # its tests (ctest python.module)
  blender                              # the Blender export's scripts run headless in the tests (ctest export.blender_headless)
)
# npm (from Debian's nodejs + npm unless a node with its own npm is already on PATH): installs the report's chart
# libraries (vega, vega-lite, vega-embed), playwright-core and the export consumer of the tests (@needle-tools/materialx:
# MaterialX 1.39.4 as WebAssembly; three.js, whose GLTFLoader loads the glTF exports in chromium), and the JSON Schema validator of the records' test (ajv), pinned in package.json +
# package-lock.json.
command -v npm >/dev/null 2>&1 || PACKAGES+=(nodejs npm)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The npm packages, exactly as package-lock.json pins them, into node_modules/ (again only when it differs).
cd "$(dirname "$0")/.."
if ! cmp -s package-lock.json node_modules/.metalfit-installed-lock 2>/dev/null; then
  echo "install-deps: npm ci (package-lock.json)"
  npm ci --no-audit --no-fund --loglevel=error
  cp package-lock.json node_modules/.metalfit-installed-lock
fi
