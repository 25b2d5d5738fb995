#!/usr/bin/env bash
# Makes `import sloshsph` work in Debian's Python (/usr/bin/python3, which has NumPy) without
# setting PYTHONPATH: writes sloshsph-build.pth, naming this checkout's build/python, into the
# user's site-packages (python3 -m site --user-site). Run by quickstart.sh; remove the file to undo.
# Another checkout's quickstart points it at that checkout instead. PYTHONPATH still wins.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SLOSHSPH_BUILD_DIR:-$root/build}
python=/usr/bin/python3
[ -x "$python" ] || python=python3
if [ ! -d "$build/python/sloshsph" ]; then
  echo "install-python-path: $build/python/sloshsph is not built (scripts/build.sh builds it)" >&2
  exit 1
fi
site=$("$python" -m site --user-site)
if mkdir -p "$site" 2>/dev/null && echo "$build/python" > "$site/sloshsph-build.pth" 2>/dev/null; then
  echo "Python: 'import sloshsph' now works in $python ($site/sloshsph-build.pth -> $build/python)."
else
  echo "Python: could not write to $site; use PYTHONPATH=$build/python $python" >&2
fi
