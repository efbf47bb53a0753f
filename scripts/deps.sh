#!/bin/sh
# Installs the Debian packages fragsim needs when run as root; otherwise
# prints the exact apt-get line.  Quiet when everything is there.
set -e
PKGS="build-essential pkg-config libosmesa6-dev libopenimageio-dev openimageio-tools \
libsnappy-dev zlib1g-dev libinih-dev libjansson-dev libcmocka-dev apitrace xvfb xauth mesa-utils gnuplot-nox parallel clang \
python3 python3-opengl libgpiod-dev gtkwave"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
    echo "deps: installing:$missing" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q >/dev/null
    apt-get install -y -q --no-install-recommends $missing >/dev/null
else
    echo "deps: missing packages; run as root:" >&2
    echo "  apt-get install -y$missing" >&2
    exit 1
fi
