#!/usr/bin/env bash
# Builds examples/user_project the two ways a CGAL user would: with the package's
# source tree through add_subdirectory, and installed, through find_package.
# Usage: user_project_test.sh SOURCE_DIR BUILD_DIR SCRATCH_DIR
set -euo pipefail
src=$1 build=$2 scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

cmake -S "$src/examples/user_project" -B "$scratch/by_subdirectory" -DCMAKE_BUILD_TYPE=Release \
      -DBODT_SOURCE_DIR="$src" "${launcher[@]}" >/dev/null
cmake --build "$scratch/by_subdirectory" >/dev/null
"$scratch/by_subdirectory/my_mesher"

cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
cmake -S "$src/examples/user_project" -B "$scratch/by_find_package" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$scratch/prefix" "${launcher[@]}" >/dev/null
cmake --build "$scratch/by_find_package" >/dev/null
"$scratch/by_find_package/my_mesher"
test -x "$scratch/prefix/bin/bodt"
