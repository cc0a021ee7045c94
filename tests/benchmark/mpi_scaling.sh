#!/usr/bin/env bash
# Strong and weak scaling of the distributed 3D solve: not a test (CTest
# never runs it); its numbers and their reading are in results/FINDINGS.md,
# section 10. Run from the repository root after a Release build:
#
#   tests/benchmark/mpi_scaling.sh [scene.prm] [--set 'Subsection/Entry=value' ...]
#
# Strong scaling: the scene on 1 and on 2 processes. Weak scaling: the
# scene on 1 process against the scene with twice Geometry/Face length (and
# so twice the slices and DoFs) on 2 processes. Every run forces the same
# linear solver on 1 and 2 processes (Solver/Linear solver, default
# iterative: GMRES + ML AMG, distributed; the one-process default keeps
# UMFPACK factors, which several processes do not have). Prints one
# markdown row per run: processes, face length, DoFs, Newton iterations,
# the whole process's wall time and the solver's own sections (TimerOutput,
# as fem.json records them).
set -euo pipefail
cd "$(dirname "$0")/../.."

scene=params/plane_strain_3d.prm
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  scene=$1
  shift
fi
extra=("$@")
linear_solver=${LINEAR_SOLVER:-iterative}
floorblock=build/floorblock
launcher=(env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  mpiexec --oversubscribe -n)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# The scene's face length (m), as the parameter file sets it.
face_length=$(sed -n 's/^ *set Face length *= *\([0-9.eE+-]*\).*/\1/p' "$scene" | head -1)
face_length=${face_length:-4.5}

# A number from fem.json by key (the file is pretty-printed, one key a
# line): a top-level key, or with a third argument a key of the object
# named there (wall_time_s: the solver's TimerOutput sections).
json_number() {
  if [ $# -eq 2 ]; then
    sed -n "s/^  \"$2\": \([0-9.eE+-]*\),\{0,1\}$/\1/p" "$1"
  else
    sed -n "/^  \"$3\": {/,/^  }/s/^    \"$2\": \([0-9.eE+-]*\),\{0,1\}$/\1/p" "$1"
  fi
}

run() { # processes face_length
  local n=$1 length=$2 out="$scratch/run_$1_$2"
  local start end
  start=$(date +%s.%N)
  "${launcher[@]}" "$n" "$floorblock" solve "$scene" \
    --set "Geometry/Face length=$length" \
    --set "Solver/Linear solver=$linear_solver" \
    "${extra[@]}" --output "$out" > "$out.log" 2>&1 \
    || { echo "run on $n processes failed: $out.log" >&2; cat "$out.log" >&2; exit 1; }
  end=$(date +%s.%N)
  printf '| %s | %s | %s | %s | %.1f | %.1f | %.1f | %.1f |\n' \
    "$n" "$length" "$(json_number "$out/fem.json" n_dofs)" \
    "$(json_number "$out/fem.json" newton_iterations)" \
    "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" \
    "$(json_number "$out/fem.json" 'Contact: linear solve' wall_time_s)" \
    "$(json_number "$out/fem.json" 'Contact: assemble' wall_time_s)" \
    "$(json_number "$out/fem.json" 'Contact: setup' wall_time_s)"
}

echo "scene $scene, Solver/Linear solver = $linear_solver ${extra[*]}"
echo
echo "| processes | face length (m) | DoFs | Newton iterations | process wall (s) | linear solve (s) | assemble (s) | setup (s) |"
echo "|---|---|---|---|---|---|---|---|"
run 1 "$face_length"
run 2 "$face_length"
run 2 "$(awk -v l="$face_length" 'BEGIN { print 2 * l }')"
