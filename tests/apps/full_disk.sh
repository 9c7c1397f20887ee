#!/usr/bin/env bash
# The issue's fault as it happens: a run on a 2 MiB file system that fills up in the middle of the
# run must stop with exit status 1 and one line naming the file the disk refused ("No space left
# on device"), with every file whole and as many stats.csv rows as meshes. Needs a private mount
# namespace (unshare -m, as root) for the 2 MiB tmpfs; exits 77 (skipped) without one.
# usage: full_disk.sh TISSU SCENARIO OUT_DIR
set -u
tissu=$1 scenario=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
if [ "${TISSU_IN_NAMESPACE:-}" != 1 ]; then
  mkdir -p "$out"
  unshare -m true 2>/dev/null || { echo "skipped: no private mount namespace (unshare -m)"; exit 77; }
  TISSU_IN_NAMESPACE=1 exec unshare -m "$0" "$@"
fi
. "$here/complete_outputs.sh"
. "$here/one_line_error.sh"
mount -t tmpfs -o size=2m tissu_full_disk "$out" || { echo "skipped: cannot mount a tmpfs"; exit 77; }
dir=$out/run
stderr=$("$tissu" run "$scenario" --out "$dir" --quiet --frames 60 \
  --set "cloth.grid.resolution=[20,20]" 2>&1 >/dev/null)
status=$?
echo "files: $(ls "$dir" | grep -c '^frame_.*\.obj$') meshes, $(($(wc -l < "$dir/stats.csv") - 1)) stats rows"
check_one_line_error "$status" "$stderr" 1 ": No space left on device" || exit 1
case "$stderr" in
  *"$dir/"*": cannot write "*": No space left on device"*) ;;
  *) echo "FAIL: stderr does not name a file of $dir and 'No space left on device'"; exit 1 ;;
esac
check_complete_outputs "$dir" || { echo "FAIL: an output is not whole"; exit 1; }
meshes=$(ls "$dir" | grep -c '^frame_.*\.obj$')
rows=$(($(wc -l < "$dir/stats.csv") - 1))
[ "$meshes" -eq "$rows" ] || { echo "FAIL: $meshes meshes but $rows stats rows"; exit 1; }
[ "$meshes" -lt 61 ] || { echo "FAIL: the 2 MiB did not fill up"; exit 1; }
echo ok
