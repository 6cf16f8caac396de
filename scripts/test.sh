#!/usr/bin/env bash
# Sets up and builds everything, then runs the whole test suite.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
ctest --test-dir "$here/build" -j2 --output-on-failure
