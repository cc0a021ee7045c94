#!/usr/bin/env bash
# Builds FloorBlock (installing what is missing) and runs the main job:
#   ./run.sh [scene.prm] [--set "Subsection/Entry=value" ...]
# Default scene: params/default.prm. Results go to results/<scene>/.
set -euo pipefail
cd "$(dirname "$0")"
.ci/setup.sh floorblock
scene=params/default.prm
if [ $# -gt 0 ] && [[ "$1" != --* ]]; then
  scene=$1
  shift
fi
exec build/floorblock run "$scene" "$@"
