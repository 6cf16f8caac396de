#!/usr/bin/env bash
# The entry header CGAL/bodt_optimize_mesh_3.h must reach no header of
# CGAL/BODT_3/IO/ (file formats), as CGAL's odt_optimize_mesh_3.h reaches none.
# Usage: entry_header_includes.sh SOURCE_DIR CXX [include flags...]
set -euo pipefail
src=$1
cxx=$2
shift 2
status=0
tree=$(echo '#include <CGAL/bodt_optimize_mesh_3.h>' |
       "$cxx" -std=c++17 -fsyntax-only -H -x c++ - -I"$src/include" "$@" 2>&1 >/dev/null) || status=$?
if [ "$status" -ne 0 ]; then
  echo "CGAL/bodt_optimize_mesh_3.h does not compile on its own:"; grep -m 20 ': error:' <<<"$tree"; exit 1
fi
count=$(grep -c 'CGAL/BODT_3/' <<<"$tree" || true)
if [ "$count" -eq 0 ]; then
  echo "the include tree was not read (no CGAL/BODT_3 header in it):"; echo "$tree" | head -20; exit 1
fi
if grep 'CGAL/BODT_3/IO/' <<<"$tree"; then
  echo "CGAL/bodt_optimize_mesh_3.h reaches the IO headers above"; exit 1
fi
echo "CGAL/bodt_optimize_mesh_3.h reaches $count package headers, none of them in IO/"
