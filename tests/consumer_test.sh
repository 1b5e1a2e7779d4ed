#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Install mhplan into a temporary prefix, build tests/consumer against it as a separate CMake project, run
# it, and build the Debian package. Usage: consumer_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src="$1"
build="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/lib/cmake/mhplan/mhplanConfig.cmake"
test -f "$work/prefix/include/mhplan/ompl_planners/population/SlimeMould.h"
test -f "$work/prefix/include/mhplan/src/base/VersionConfig.h"
test -f "$work/prefix/include/mhplan/src/draw/GifWriter.h"
# A layer's detail/ headers are shared by its own sources only: not installed.
test ! -e "$work/prefix/include/mhplan/src/optimum/detail"
test ! -e "$work/prefix/include/mhplan/src/draw/detail"
test -x "$work/prefix/bin/mhplan"
# The installed program finds its installed worlds (not the source tree's).
worlds=$(env -u MHPLAN_ENVIRONMENTS "$work/prefix/bin/mhplan" worlds)
grep -q bfo_case2 <<<"$worlds"
# The consumer project, plus the README's complete main.cpp (the ```cpp block of "Use from your OMPL
# program"), built against the non-system prefix through CMAKE_PREFIX_PATH.
cp -r "$src/tests/consumer" "$work/consumer_src"
awk '/^## Use from your OMPL program/ {section = 1; next}
     /^## / {section = 0}
     section && /^```cpp$/ {code = 1; next}
     code && /^```$/ {exit}
     code {print}' "$src/README.md" >"$work/consumer_src/readme_example.cpp"
grep -q "int main" "$work/consumer_src/readme_example.cpp"
cmake -S "$work/consumer_src" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" -j 2 >/dev/null
"$work/consumer/consumer"
# (Into a file, not a pipe: grep -q stops reading at the first match and the example, still writing, would
# die of SIGPIPE.)
"$work/consumer/readme_example" >"$work/readme_example.out"
grep -q "allocated LRSMA" "$work/readme_example.out"
grep -q "exact set-up: SMA path length" "$work/readme_example.out"
# The Debian package, with its dependencies.
(cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" >/dev/null)
deb=$(ls "$work"/mhplan_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
contents=$(dpkg-deb -c "$deb")
grep -q libompl-dev <<<"$depends"
grep -q libgif7 <<<"$depends" # libmhplan links giflib (src/draw/GifWriter.cpp)
grep -q libpagmo8 <<<"$depends" # libmhplan links pagmo2 (ompl_planners/pagmo)
grep -q "usr/lib/cmake/mhplan/mhplanConfig.cmake" <<<"$contents"
grep -q "usr/bin/mhplan" <<<"$contents"
echo "consumer project built and ran against the installed package; $(basename "$deb") built"
