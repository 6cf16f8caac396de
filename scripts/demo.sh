#!/usr/bin/env bash
# Sets up and builds the command-line tool and the Python module, then smooths a
# real third-party mesh (CGAL's sphere.mesh, from Debian's libcgal-demo) and prints
# its quality before and after, with a JSON report and an HTML page (pictures of
# the mesh before and after) next to the output.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh" bodt _bodt
out="$here/build/demo"
mkdir -p "$out"
"$here/build/bodt" smooth "$here/build/data/sphere.mesh" -o "$out/sphere-bodt.mesh" --report "$out/sphere-bodt.json" --html "$out/sphere-bodt.html"
echo "smoothed mesh: $out/sphere-bodt.mesh; report: $out/sphere-bodt.json; page: $out/sphere-bodt.html"
echo "Python: PYTHONPATH=$here/build/python /usr/bin/python3 -c 'import bodt', or pip install . (README.md)"
