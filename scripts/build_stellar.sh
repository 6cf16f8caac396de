#!/usr/bin/env bash
# Builds Klingner and Shewchuk's Stellar (BSD licence) from a copy of its sources
# that you fetched yourself (https://people.eecs.berkeley.edu/~jrs/stellar/, or a
# public mirror of Stellar 1.0): SRC_DIR holds src/Stellar.c and src/Starbase.c.
# Nothing is downloaded and no Stellar code enters this project: the program goes
# to build/stellar/Stellar, which `bodt-compare --stellar` runs (doc/stellar.md).
# Usage: bash scripts/build_stellar.sh SRC_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)

if [ $# -ne 1 ] || [ ! -f "$1/src/Stellar.c" ] || [ ! -f "$1/src/Starbase.c" ]; then
  echo "usage: bash scripts/build_stellar.sh SRC_DIR   (SRC_DIR/src/Stellar.c and SRC_DIR/src/Starbase.c)" >&2
  exit 2
fi
src=$(cd "$1/src" && pwd)
out="$here/build/stellar"
mkdir -p "$out"
# As Stellar's makefile ("make linux"), but with its assertions and self-checks off,
# as any timed program; gnu99 because its top.c defines `bool` as an enum of false and true.
flags=(-std=gnu99 -O3 -DNDEBUG -fno-strict-aliasing -w -I"$src")
cc "${flags[@]}" -DLINUX -DNOMAIN -c "$src/Starbase.c" -o "$out/Starbase.o"
cc "${flags[@]}" -o "$out/Stellar" "$src/Stellar.c" "$out/Starbase.o" -lm
echo "build_stellar: built $out/Stellar" >&2
