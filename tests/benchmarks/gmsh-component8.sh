#!/usr/bin/env bash
# Issue 16's mesher-numbered mesh: gmsh's own demo part component8.step (Debian's gmsh-doc)
# meshed at -clmax 0.4 (about 1.32M tetrahedra, numbered as gmsh numbers them), then the
# suite gmsh-component8-t1.json on it. Usage: tests/benchmarks/gmsh-component8.sh OUT.jsonl
# [VOBENCH]. The mesh is made once into build/bench-data/ (not in git: 63 MB).
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:?usage: gmsh-component8.sh OUT.jsonl [path/to/vobench]}
vobench=${2:-build/harness/cli/vobench}
step=/usr/share/doc/gmsh-doc/doc/gmsh/demos/boolean/component8.step.gz
mesh=build/bench-data/component8-clmax0.4.msh
if [[ ! -f $mesh ]]; then
  [[ -f $step ]] || { echo "gmsh-component8.sh: $step not found (apt-get install gmsh-doc)" >&2; exit 2; }
  mkdir -p build/bench-data
  zcat "$step" > build/bench-data/component8.step
  gmsh build/bench-data/component8.step -3 -clmax 0.4 -nt 1 -format msh41 -bin -o "$mesh.tmp" > build/bench-data/gmsh.log
  mv "$mesh.tmp" "$mesh"
fi
exec "$vobench" run tests/benchmarks/gmsh-component8-t1.json -o "$out"
