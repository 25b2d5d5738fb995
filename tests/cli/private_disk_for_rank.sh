#!/usr/bin/env bash
# private_disk_for_rank.sh RANK DIR COMMAND...: started by mpirun for every rank; the rank RANK
# runs COMMAND in its own mount namespace with an empty tmpfs over DIR, so that what it writes
# under DIR is invisible to the other ranks (a second machine without a shared file system).
# The other ranks run COMMAND as it is.
set -eu
private_rank=$1 dir=$2
shift 2
if [ "${OMPI_COMM_WORLD_RANK:-0}" = "$private_rank" ]; then
  exec unshare --mount sh -c 'mount -t tmpfs tmpfs "$0" && exec "$@"' "$dir" "$@"
fi
exec "$@"
