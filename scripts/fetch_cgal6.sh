#!/usr/bin/env bash
# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors
#
# Fetches CGAL 6 for a second build tree: downloads Debian 13 (trixie)'s libcgal-dev .deb with
# `apt-get download` and unpacks it (dpkg-deb -x) into a prefix, without installing it and
# without touching the system's apt configuration (a private sources list, package lists and
# cache under the prefix's parent). CGAL is header-only: the unpacked package is used in place,
#
#   bash scripts/fetch_cgal6.sh [PREFIX]          (default: build-cgal6/cgal6-prefix)
#   cmake -S . -B build-cgal6 -DCGAL_DIR=PREFIX/usr/lib/x86_64-linux-gnu/cmake/CGAL
#
# It prints the CGAL_DIR to use on its last line. Nothing is downloaded again when the prefix
# already holds the package. Needs apt-get, dpkg-deb and the Debian archive keyring (all on
# Debian 12), and network access to deb.debian.org (MBP_DEBIAN_MIRROR to change it).
set -euo pipefail
cd "$(dirname "$0")/.."

prefix="${1:-build-cgal6/cgal6-prefix}"
mirror="${MBP_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
suite=trixie
package=libcgal-dev
version_prefix=6.          # the major version expected from the suite

mkdir -p "$prefix"
prefix="$(cd "$prefix" && pwd)"
work="$prefix.apt"          # private apt state: sources list, package lists, cache, downloads

find_cgal_dir() {
  local config
  config="$(find "$prefix/usr" -name CGALConfig.cmake -path '*/cmake/CGAL/*' 2>/dev/null | head -n 1)"
  [ -n "$config" ] && dirname "$config"
}

if [ -f "$prefix/.fetched" ] && cgal_dir="$(find_cgal_dir)"; then
  echo "fetch_cgal6: $(cat "$prefix/.fetched") already unpacked in $prefix" >&2
  echo "$cgal_dir"
  exit 0
fi

keyring=/usr/share/keyrings/debian-archive-keyring.gpg
if [ ! -r "$keyring" ]; then
  echo "fetch_cgal6: $keyring is missing (package debian-archive-keyring)" >&2
  exit 1
fi

mkdir -p "$work/lists/partial" "$work/cache/archives/partial" "$work/etc/sources.list.d" \
         "$work/etc/preferences.d" "$work/download"
echo "deb [signed-by=$keyring] $mirror $suite main" > "$work/etc/sources.list"
apt_options=(
  -o "Dir::Etc::sourcelist=$work/etc/sources.list"
  -o "Dir::Etc::sourceparts=$work/etc/sources.list.d"
  -o "Dir::Etc::preferencesparts=$work/etc/preferences.d"
  -o "Dir::State::Lists=$work/lists"
  -o "Dir::Cache=$work/cache"
  -o "Dir::State::status=/dev/null"
  -o "Acquire::Languages=none"
  -o "APT::Get::List-Cleanup=false"
  -o "Debug::NoLocking=true"
  -o "APT::Sandbox::User=$(id -un)"
)

echo "fetch_cgal6: package lists of Debian $suite ($mirror)" >&2
apt-get "${apt_options[@]}" -qq update >&2
version="$(apt-cache "${apt_options[@]}" show "$package" | sed -n 's/^Version: //p' | head -n 1)"
case "$version" in
  "$version_prefix"*) ;;
  *) echo "fetch_cgal6: Debian $suite offers $package '$version', not CGAL $version_prefix*" >&2; exit 1 ;;
esac
echo "fetch_cgal6: $package $version" >&2
(cd "$work/download" && rm -f ./*.deb && apt-get "${apt_options[@]}" -qq download "$package=$version" >&2)
deb="$(ls "$work/download"/*.deb | head -n 1)"
dpkg-deb -x "$deb" "$prefix"
if ! cgal_dir="$(find_cgal_dir)"; then
  echo "fetch_cgal6: no CGALConfig.cmake in $deb" >&2
  exit 1
fi
echo "$package $version" > "$prefix/.fetched"
rm -rf "$work"              # the package lists are not needed any more
echo "fetch_cgal6: unpacked into $prefix" >&2
echo "$cgal_dir"
