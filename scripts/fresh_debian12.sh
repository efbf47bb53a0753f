#!/bin/bash
# Checks the README's promise on a fresh Debian 12: a minimal bookworm
# (debootstrap minbase, plus make, which a fresh install may lack) gets a
# clean clone of HEAD and runs exactly `make run` and `make test` as root.
# Needs root, debootstrap and network access to deb.debian.org; took under
# five minutes and about 2 GB here.  Usage: scripts/fresh_debian12.sh [DIR] (default
# /var/tmp/fragsim-deb12, reused when it already holds a bookworm tree).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
root=${1:-/var/tmp/fragsim-deb12}
[ "$(id -u)" = 0 ] || { echo "fresh_debian12: must run as root (debootstrap, chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null || { echo "fresh_debian12: install debootstrap first" >&2; exit 2; }

if [ ! -x "$root/usr/bin/make" ]; then
    mkdir -p "$root"
    debootstrap --variant=minbase --include=make,ca-certificates bookworm "$root" http://deb.debian.org/debian
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
mounted=()
cleanup() {
    for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount "${mounted[i]}" || true; done
}
trap cleanup EXIT
for d in proc sys dev dev/pts dev/shm; do
    if ! mountpoint -q "$root/$d"; then
        mount --bind "/$d" "$root/$d"
        mounted+=("$root/$d")
    fi
done

rm -rf "$root/root/fragsim"
git clone -q "$top" "$root/root/fragsim"
chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    /bin/bash -c 'cd /root/fragsim && make run && make test'
echo "fresh_debian12: make run and make test passed on a fresh bookworm in $root"
