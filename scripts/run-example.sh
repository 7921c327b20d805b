#!/usr/bin/env bash
# Quick start 1: installs what is missing, builds the apps (Release: simcli,
# simgen, simcheck) and runs simcli on a bundled scene (default:
# examples/default.in). Extra arguments go to simcli.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/ensure-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target simcli simgen simcheck -j "$(nproc)" >/dev/null
if [ $# -eq 0 ]; then set -- examples/default.in; fi
exec build/apps/simcli "$@"
