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
#   bash scripts/mirror_checkout.sh DESTINATION
#
# Makes DESTINATION what a fresh clone of this checkout holds: the files tracked by git, with
# their content in the working tree (uncommitted changes included, untracked files left out).
# Unchanged files keep their time stamps, so that a build inside DESTINATION stays
# incremental; files no longer tracked are removed (DESTINATION/build* and .git are kept). Outside a git
# checkout every file but the build folders is copied.
set -euo pipefail
cd "$(dirname "$0")/.."
dst="$1"
mkdir -p "$dst"
dst="$(cd "$dst" && pwd)"
list="$(mktemp)"
trap 'rm -f "$list" "$list.old"' EXIT
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  git ls-files -z --cached | tr '\0' '\n' > "$list"
else
  find . -path './build*' -prune -o -type f -print | sed 's|^\./||' > "$list"
fi
copied=0
while IFS= read -r f; do
  [ -f "$f" ] || continue                  # deleted in the working tree
  if ! cmp -s "$f" "$dst/$f"; then
    mkdir -p "$dst/$(dirname "$f")"
    cp -p "$f" "$dst/$f"
    copied=$((copied + 1))
  fi
done < "$list"
# files of an earlier mirror that are no longer tracked
(cd "$dst" && find . \( -path './build*' -o -path ./.git \) -prune -o -type f -print | sed 's|^\./||' | sort) > "$list.old"
sort "$list" | comm -23 "$list.old" - | while IFS= read -r f; do rm -f "$dst/$f"; done
echo "mirror_checkout: $dst ($(wc -l < "$list") files, $copied copied)"
