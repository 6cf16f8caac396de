#!/usr/bin/env bash
# Installs what the package needs from Debian, then configures and builds it.
# Usage: scripts/setup.sh [cmake-target...]   (default: everything)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)

packages=(build-essential cmake ccache libcgal-dev libcgal-demo libeigen3-dev libboost-dev
          libgmp-dev libmpfr-dev libtbb-dev libgtest-dev googletest zlib1g-dev chromium
          libcli11-dev nlohmann-json3-dev pybind11-dev python3-dev python3-numpy python3-meshio
          python3-pip python3-setuptools python3-wheel python3-venv   # pip install . (setup.py)
          gmsh tetgen)   # the I/O tests read files these tools write
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# A real third-party mesh for the demo: CGAL's own sphere.mesh, shipped in Debian's libcgal-demo;
# and CGAL's surfaces that the comparison (bench/compare) meshes.
data="$here/build/data"
if [ ! -f "$data/sphere.mesh" ] || [ ! -f "$data/double-torus-example.off" ]; then
  mkdir -p "$data"
  tar -xzf /usr/share/doc/libcgal-dev/examples.tar.gz -C "$data" --strip-components=3 \
      examples/Tetrahedral_remeshing/data/sphere.mesh
  tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$data" --strip-components=2 \
      data/meshes/fandisk.off data/meshes/elephant.off data/meshes/anchor.off \
      data/meshes/double-torus-example.off
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Debian's Python, for which python3-numpy and python3-meshio are installed (not another one on PATH).
cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 \
      "${launcher[@]}" >/dev/null
if [ $# -gt 0 ]; then
  cmake --build "$here/build" -j2 --target "$@"
else
  cmake --build "$here/build" -j2
fi
