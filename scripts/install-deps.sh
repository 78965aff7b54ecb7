#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages antslam needs, and only those that are missing.
# Idempotent; works as root and through sudo.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libtbb-dev libnlopt-cxx-dev libceres-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev zlib1g-dev libpng-dev
  python3-matplotlib
  python3-dev python3-numpy python3-pytest pybind11-dev python3-pybind11  # import antslam
  r-cran-irace  # the irace scenario test (tests/scripts)
  clang libomp-14-dev libclang-rt-14-dev
  libopenmpi-dev openmpi-bin  # ANTSLAM_WITH_MPI: trials over ranks, island colonies
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "install-deps: missing ${missing[*]} and neither root nor sudo is available" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
"${sudo[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
