#!/bin/sh
# SPDX-License-Identifier: LGPL-3.0-or-later
# Installs what the JavaScript peers need: Debian's nodejs and npm (apt-get, as root or with
# sudo) and the pinned npm packages of bench/peers (csg, @jscad/modeling) and bench/peers/vector
# (three, jsdom) from their committed package-lock.json files. A quick no-op when all is there.
# Exit status 0 when node and npm are usable afterwards, 1 when they could not be installed.
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO="sudo"
    echo "bench/peers: installing nodejs and npm" >&2
    if ! { $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq nodejs npm >/dev/null; }; then
        echo "bench/peers: could not install nodejs and npm (apt-get install nodejs npm)" >&2
        exit 1
    fi
fi
for dir in "$HERE" "$HERE/vector"; do
    [ -d "$dir/node_modules" ] || (cd "$dir" && npm ci --no-audit --no-fund >/dev/null)
done
