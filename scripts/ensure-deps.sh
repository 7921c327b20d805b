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
required=()
command -v cmake >/dev/null 2>&1 || required+=(cmake)
command -v g++ >/dev/null 2>&1 || required+=(g++)
command -v ninja >/dev/null 2>&1 || required+=(ninja-build)
[ -f /usr/include/eigen3/Eigen/Core ] || required+=(libeigen3-dev)
extras=()
for extra in "$@"; do
  case "$extra" in
    gnuplot-nox) command -v gnuplot >/dev/null 2>&1 || extras+=(gnuplot-nox) ;;
    clang-format) command -v clang-format >/dev/null 2>&1 || extras+=(clang-format) ;;
    *) dpkg -s "$extra" >/dev/null 2>&1 || extras+=("$extra") ;;
  esac
done
missing=("${required[@]}" "${extras[@]}")
[ ${#missing[@]} -eq 0 ] && exit 0

# Without --optional every package is needed; with it, only the build's own.
needed=("${missing[@]}")
$optional && needed=("${required[@]}")
if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "Installing missing Debian packages: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  if apt-get update -qq && apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; then
    exit 0
  fi
  if [ ${#needed[@]} -eq 0 ]; then
    # One at a time, so that one that cannot be had does not keep the others out.
    for extra in "${extras[@]}"; do
      apt-get install -y -qq --no-install-recommends "$extra" >/dev/null ||
        echo "Could not install $extra; the tests that need it will say SKIPPED" >&2
    done
    exit 0
  fi
  echo "Could not install: ${missing[*]}" >&2
  exit 1
fi
echo "particlesim needs these Debian packages: ${missing[*]}" >&2
echo "Install them with: sudo apt-get install ${missing[*]}" >&2
if [ ${#needed[@]} -eq 0 ]; then
  echo "(optional: the tests that need them will say SKIPPED)" >&2
  exit 0
fi
exit 1
