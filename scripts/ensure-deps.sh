#!/usr/bin/env bash
# Makes sure the build dependencies are present on a Debian machine: installs
# the missing Debian packages when run as root, otherwise names them and the
# command that installs them. Usage: scripts/ensure-deps.sh [--optional] [extra-package...]
# With --optional, packages that cannot be installed are named and the script
# still succeeds: the tests that need them then report themselves skipped.
set -euo pipefail

optional=false
if [ "${1:-}" = "--optional" ]; then
  optional=true
  shift
fi
missing=()
command -v cmake >/dev/null 2>&1 || missing+=(cmake)
command -v g++ >/dev/null 2>&1 || missing+=(g++)
[ -f /usr/include/eigen3/Eigen/Core ] || missing+=(libeigen3-dev)
for extra in "$@"; do
  case "$extra" in
    gnuplot-nox) command -v gnuplot >/dev/null 2>&1 || missing+=(gnuplot-nox) ;;
    clang-format) command -v clang-format >/dev/null 2>&1 || missing+=(clang-format) ;;
    *) dpkg -s "$extra" >/dev/null 2>&1 || missing+=("$extra") ;;
  esac
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "Installing missing Debian packages: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "particlesim needs these Debian packages: ${missing[*]}" >&2
  echo "Install them with: sudo apt-get install ${missing[*]}" >&2
  exit 1
fi
