#!/usr/bin/env bash
# Builds FloorBlock (installing what is missing) and runs the whole test suite.
set -euo pipefail
cd "$(dirname "$0")"
.ci/setup.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
