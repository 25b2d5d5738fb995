#!/usr/bin/env bash
# One command from a fresh machine to a finished simulation:
# installs the Debian packages, builds, and runs the built-in default case into out/default/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
cd "$root"
./build/app/sloshsph run --out out/default --force "$@"
echo
echo "Done. The run directory is out/default/: timeseries.csv, summary.json, particles.pvd (open in ParaView)."
"$root/scripts/install-python-path.sh"
