#!/usr/bin/env bash
# Builds the libFuzzer harnesses of the mesh readers (clang, ASan + UBSan; test/fuzz/)
# and runs each one, seeded with small meshes the project writes in every format.
#
# usage: scripts/fuzz.sh [seconds-per-harness] [harness...]
#   scripts/fuzz.sh                    smoke: 8 s per harness, about a minute for all seven
#   scripts/fuzz.sh 600 gmsh vtu       ten minutes each for two harnesses
#   FUZZ_RUNS=1000000 scripts/fuzz.sh  a number of executions per harness instead of a time
# Harnesses: medit meshb gmsh vtu vtk tetgen (the readers, with round trips) and smooth
# (three iterations of the pipeline on small Medit meshes, with cavity insertion and edge
# contraction on for half the inputs each: finite coordinates,
# no inverted tetrahedron added, every subdomain's volume kept to 1e-10, at most 5%
# vertices added). Exits non-zero
# when a harness finds a crash, a leak, undefined behaviour or a broken promise; the
# input that did it is kept in build-fuzz/findings/HARNESS/.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
out="$here/build-fuzz"
seconds=${1:-8}
[ $# -gt 0 ] && shift
harnesses=("$@")
[ ${#harnesses[@]} -eq 0 ] && harnesses=(medit meshb gmsh vtu vtk tetgen smooth)

# clang and its libFuzzer/sanitizer runtimes come from Debian.
packages=(clang libclang-rt-14-dev libcgal-dev libeigen3-dev libgmp-dev libmpfr-dev zlib1g-dev libboost-dev libtbb-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "fuzz: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
fi

cxx=(clang++)
command -v ccache >/dev/null && cxx=(ccache clang++)
flags=(-std=c++17 -g -O1 -I"$here/include" -I/usr/include/eigen3 -DNDEBUG)
libs=(-lgmp -lmpfr -lz -ltbb)
mkdir -p "$out"

# Seeds: a generated grid and a piece of CGAL's Mesh_3-made sphere (from libcgal-demo, unpacked by setup.sh).
"${cxx[@]}" "${flags[@]}" "$here/test/fuzz/make_seeds.cpp" -o "$out/make_seeds" "${libs[@]}"
inputs=()
sphere="$here/build/data/sphere.mesh"
if [ ! -f "$sphere" ]; then
  mkdir -p "$out/data"
  tar -xzf /usr/share/doc/libcgal-dev/examples.tar.gz -C "$out/data" --strip-components=3 \
      examples/Tetrahedral_remeshing/data/sphere.mesh 2>/dev/null || true
  sphere="$out/data/sphere.mesh"
fi
[ -f "$sphere" ] && inputs+=("$sphere")
rm -rf "$out/seeds"
"$out/make_seeds" "$out/seeds" "${inputs[@]}"

pids=()
for h in "${harnesses[@]}"; do
  "${cxx[@]}" "${flags[@]}" -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
      "$here/test/fuzz/fuzz_$h.cpp" -o "$out/fuzz_$h" "${libs[@]}" &
  pids+=($!)
  # Two compilations at a time: the machine has two cores.
  if [ ${#pids[@]} -ge 2 ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p"; done

status=0
for h in "${harnesses[@]}"; do
  mkdir -p "$out/corpus/$h" "$out/findings/$h"
  limit=(-max_total_time="$seconds")
  [ -n "${FUZZ_RUNS:-}" ] && limit=(-runs="$FUZZ_RUNS")
  # The smoothing harness reads Medit files: it starts from the Medit seeds.
  format=$h
  [ "$h" = smooth ] && format=medit
  dict=()
  [ -f "$here/test/fuzz/$format.dict" ] && dict=(-dict="$here/test/fuzz/$format.dict")
  echo "fuzz: $h" >&2
  if ! "$out/fuzz_$h" "${limit[@]}" "${dict[@]}" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$out/findings/$h/" "$out/corpus/$h" "$out/seeds/$format" \
        > "$out/$h.log" 2>&1; then
    echo "fuzz: $h FAILED; see $out/$h.log and $out/findings/$h/" >&2
    tail -30 "$out/$h.log" >&2
    status=1
  fi
  grep -E "stat::number_of_executed_units|cov: " "$out/$h.log" | tail -2 >&2 || true
done
exit $status
