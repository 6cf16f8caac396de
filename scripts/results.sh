#!/usr/bin/env bash
# Regenerates doc/results.md, doc/results.json and the histograms doc/results/*.svg:
# installs and builds what is needed with setup.sh, then runs the side-by-side
# comparison at the benchmark size. Takes a long while: CGAL's
# optimizers are slow. Extra arguments go to the comparison (e.g. more mesh files).
# Usage: [STELLAR=1] bash scripts/results.sh [compare options or mesh files...]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)

bash "$here/scripts/setup.sh" bodt-compare
# Relative paths, so that the command recorded in doc/results.md is the same on every machine.
cd "$here"
# Stellar, when built (scripts/build_stellar.sh), runs on a --small run, or with
# STELLAR=1: at the benchmark size it takes many CPU minutes per input (doc/stellar.md).
stellar=()
if [ -x build/stellar/Stellar ]; then
  for a in "$@"; do [ "$a" = --small ] && stellar=(--stellar build/stellar/Stellar); done
  [ "${STELLAR:-0}" = 1 ] && stellar=(--stellar build/stellar/Stellar)
fi
build/bodt-compare --output-dir doc "${stellar[@]}" "$@"
