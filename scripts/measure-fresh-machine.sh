#!/usr/bin/env bash
# The README's first-start figures on a fresh Debian 12 user space: a minimal bookworm made by
# debootstrap, entered with chroot (so packages, build and run start from nothing, on this
# machine's cores and network). Needs root and network; leaves the chroot in WORK for a look.
#   sudo bash scripts/measure-fresh-machine.sh [run|test] [WORK]
#     run:  DRYTWIN_HEADLESS=1 bash scripts/run.sh (packages, program, demo, pipeline)
#     test: bash scripts/test.sh (packages, everything, CTest)
# Prints the wall-clock seconds of the whole command and when configuring and building ended.
set -euo pipefail
what="${1:-run}"
work="${2:-/tmp/drytwin-fresh}"
here="$(cd "$(dirname "$0")/.." && pwd)"
case "$what" in
  run) command="DRYTWIN_HEADLESS=1 bash scripts/run.sh" ;;
  test) command="bash scripts/test.sh" ;;
  *) echo "measure-fresh-machine: the first argument is run or test, not '$what'" >&2; exit 2 ;;
esac
if [ "$(id -u)" -ne 0 ]; then
  echo "measure-fresh-machine: debootstrap and chroot need root" >&2
  exit 2
fi
command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap
if [ -e "$work" ]; then
  echo "measure-fresh-machine: $work exists; remove it (umount $work/proc $work/dev first) or name another" >&2
  exit 2
fi
debootstrap --variant=minbase bookworm "$work" http://deb.debian.org/debian >/dev/null
cp /etc/resolv.conf "$work/etc/resolv.conf"
mount -t proc proc "$work/proc"
mount --bind /dev "$work/dev"
trap 'umount "$work/proc" "$work/dev" 2>/dev/null || true' EXIT
mkdir -p "$work/root/src"
git clone -q "$here" "$work/root/src/main"
echo "measure-fresh-machine: $command in a fresh bookworm at $work (commit $(git -C "$here" rev-parse --short HEAD))"
start=$(date +%s)
chroot "$work" /bin/bash -c "cd /root/src/main && $command" >"$work/root/$what.log" 2>&1 && rc=0 || rc=$?
end=$(date +%s)
build="$work/root/src/main/build"
echo "exit code $rc after $((end - start)) s (log: $work/root/$what.log)"
[ -f "$build/CMakeCache.txt" ] && echo "configured after $(($(stat -c %Y "$build/CMakeCache.txt") - start)) s"
[ -f "$build/app/drytwin" ] && echo "program built after $(($(stat -c %Y "$build/app/drytwin") - start)) s"
exit "$rc"
