#!/usr/bin/env bash
# Regenerates doc/results.md, doc/results.json and the histograms doc/results/*.svg:
# installs and builds what is needed with setup.sh, then runs the side-by-side
# comparison at the benchmark size. Takes a long while: CGAL's
# optimizers are slow. Extra arguments go to the comparison (e.g. more mesh files).
# Usage: bash scripts/results.sh [compare options or mesh files...]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)

bash "$here/scripts/setup.sh" bodt-compare
# Relative paths, so that the command recorded in doc/results.md is the same on every machine.
cd "$here"
build/bodt-compare --output-dir doc "$@"
