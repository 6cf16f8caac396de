#!/usr/bin/env bash
# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (GCC), in
# build-asan/: any memory error, leak or undefined behaviour fails the test it happens in.
#
# usage: scripts/sanitize.sh [--all] [ctest arguments...]   e.g. scripts/sanitize.sh --all -R Smoothing
#   (default)  the tests that mesh nothing with Mesh_3 (ctest label `light`: readers and
#              writers, quality, utilities, classification, moves, the smoothing steps,
#              flips on constructed configurations, the shape of labelled boxes,
#              parameters, reports); CI runs neither set (doc/manual.md, section 4)
#   --all      every test that runs the package's code (labels `light` and `mesh_3`: also
#              the pipeline on the Mesh_3-generated inputs, the conversions, the flips
#              through the pipeline, insertion, the command line and the example)
# Left out either way: the compile checks (parameters_refused_*), the package's CMake
# check (user_project) and the Python test, which run compilers, CMake and Python on
# code the other tests run; the Python module is not built with the sanitizers.
# doc/manual.md (section 4) has the times and the findings of the last runs.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
labels=light
targets=bodt_tests_light
if [ "${1:-}" = --all ]; then
  labels='light|mesh_3'
  targets=bodt_tests
  shift
fi
bash "$here/scripts/setup.sh" bodt   # the packages, and the data bodt-compare reads (build/data)
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# Sanitized code runs several times slower: each test case gets an hour.
cmake -S "$here" -B "$here/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBODT_BUILD_PYTHON=OFF \
      -DBODT_TEST_TIMEOUT=3600 \
      -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags" \
      $(command -v ccache >/dev/null && echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache) > /dev/null
cmake --build "$here/build-asan" -j2 --target "$targets"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$here/build-asan" -j2 --output-on-failure -L "$labels" "$@"
