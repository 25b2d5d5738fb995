#!/usr/bin/env bash
# Installs every build and run dependency of sloshsph from Debian packages.
# Idempotent: packages already present are skipped, so a second run is quick.
# Nothing is downloaded from anywhere but the Debian archive configured in apt.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config   # compiler and build
  libtomlplusplus-dev                            # case files (TOML)
  libcli11-dev                                   # command line
  libeigen3-dev                                  # sparse Krylov solvers, FEM, small matrices
  nlohmann-json3-dev                             # summary.json / run.json
  libfftw3-dev                                   # spectra (Welch PSD, admittance)
  libgtest-dev libgmock-dev libbenchmark-dev     # tests and benchmarks
  python3 python3-numpy python3-scipy python3-matplotlib  # plots and reports
  python3-dev pybind11-dev python3-pytest        # the Python module (docs/python.md) and its tests
  libopenmpi-dev openmpi-bin                     # sweeps across machines (mpirun)
  chromium                                       # headless check of report.html (test only)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} Debian packages already installed"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
