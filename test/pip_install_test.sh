#!/usr/bin/env bash
# `pip install .` as README.md says it, into a fresh virtual environment that sees
# the system's packages (Debian's NumPy and meshio; offline), then the README's
# Python lines, run as they are written there, outside the repository.
# usage: pip_install_test.sh SOURCE_DIR SCRATCH_DIR PYTHON BODT_BINARY MESH
set -euo pipefail
src=$1 scratch=$2 python=$3 bodt=$4 mesh=$5
[ -f "$mesh" ] || { echo "missing $mesh: run scripts/setup.sh, which unpacks it" >&2; exit 1; }
rm -rf "$scratch"
mkdir -p "$scratch/run"
unset PYTHONPATH

"$python" -m venv --system-site-packages "$scratch/venv"
(cd "$src" && "$scratch/venv/bin/python" -m pip install --no-build-isolation .)

# The first python block of the README's "Use it from Python" section.
sed -n '/^## Use it from Python/,/^## /p' "$src/README.md" | sed -n '/^```python$/,/^```$/p' | sed '1d;$d' \
    > "$scratch/run/readme.py"
grep -q "bodt.smooth" "$scratch/run/readme.py" || { echo "no bodt.smooth in the README's Python block" >&2; exit 1; }
cd "$scratch/run"
"$bodt" convert "$mesh" in.msh
"$scratch/venv/bin/python" readme.py

# The package came from the environment, and its result is the smoothed mesh.
"$scratch/venv/bin/python" - "$scratch/venv" <<'EOF'
import os, sys
import bodt, meshio
venv = os.path.realpath(sys.argv[1])
assert os.path.realpath(bodt.__file__).startswith(venv + os.sep), "bodt imported from " + bodt.__file__
before, after = bodt.quality(meshio.read("in.msh")), bodt.quality(meshio.read("out.vtu"))
assert after["min_dihedral_deg"] > before["min_dihedral_deg"] + 1, (before["min_dihedral_deg"], after["min_dihedral_deg"])
print("bodt %s from %s: min dihedral %.2f -> %.2f" % (bodt.__version__, bodt.__file__, before["min_dihedral_deg"],
                                                     after["min_dihedral_deg"]))
EOF
