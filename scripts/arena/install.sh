#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Make OMPL's Planner Arena (the R/Shiny app of Debian's ompl-plannerarena, OMPL 1.5.2) runnable, without
# editing any system file, and print the directory of the app on the last line of stdout.
#
#   scripts/arena/install.sh [--check] [--browser]
#
# 1. Debian's R packages the app loads are installed when missing (apt-get; needs root).
# 2. Where the Debian package ompl-plannerarena is installed and R has its package 'pool', the installed app
#    (/usr/share/ompl/plannerarena) is used as it is.
# 3. Else (Debian 12: the package does not install next to a nodejs that is not Debian's, its r-cran-v8
#    dependency conflicts; and Debian does not ship R's 'pool' that its server.R loads) the package is
#    downloaded with 'apt-get download', unpacked with 'dpkg -x' into a private directory and its server.R is
#    patched in a private copy: library(pool) -> library(DBI), dbPool( -> DBI::dbConnect(.
# The private directory is $MHPLAN_ARENA_DIR, default ${XDG_CACHE_HOME:-$HOME/.cache}/mhplan/arena. A second
# run finds everything in place and only checks it (about a second: one Rscript).
#   --check    install nothing; exit 3 (with the reason on stderr) when something is missing.
#   --browser  also Debian's chromium and, into $MHPLAN_ARENA_DIR/node, puppeteer-core from npm (the browser
#              test, tests/arena/, drives Planner Arena with them).
set -euo pipefail

CHECK=0
BROWSER=0
for a in "$@"; do
  case "$a" in
    --check) CHECK=1 ;;
    --browser) BROWSER=1 ;;
    *) echo "arena/install.sh: unknown option '$a' (accepted: --check, --browser)" >&2; exit 1 ;;
  esac
done

ARENA_DIR="${MHPLAN_ARENA_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/mhplan/arena}"
SYSTEM_APP=/usr/share/ompl/plannerarena
# What the app's server.R, ui.R and global.R load (V8 and pool only in the unpatched app), by Debian name.
R_PACKAGES=(r-base-core r-cran-shiny r-cran-shinyjs r-cran-dplyr r-cran-dbplyr r-cran-tidyr r-cran-ggplot2
            r-cran-hmisc r-cran-rsqlite r-cran-markdown r-cran-dbi r-cran-rlang)
R_LIBRARIES="shiny shinyjs dplyr dbplyr tidyr ggplot2 Hmisc RSQLite markdown DBI rlang"
BROWSER_PACKAGES=(chromium)
PUPPETEER_VERSION=23.9.0    # engines: node >= 18 (Debian 12 has 18; later lines need 22)

. "$(dirname "$0")/../debian-packages.sh"

apt_install() {
  [ $# -gt 0 ] || return 0
  if [ "$CHECK" = 1 ]; then
    echo "arena: missing Debian packages: $* (run scripts/setup.sh --arena, or scripts/arena/install.sh)" >&2
    exit 3
  fi
  echo "arena: installing Debian packages: $*" >&2
  mhplan_apt_install arena "$@" || exit 3
}

mapfile -t need < <(mhplan_missing_debs "${R_PACKAGES[@]}")
apt_install "${need[@]}"
if [ "$BROWSER" = 1 ]; then
  mapfile -t need < <(mhplan_missing_debs "${BROWSER_PACKAGES[@]}")
  apt_install "${need[@]}"
fi

# The app: the installed one where it runs as it is, else the private patched copy.
APP=""
if [ -f "$SYSTEM_APP/server.R" ] && Rscript -e 'suppressPackageStartupMessages(library(pool))' >/dev/null 2>&1; then
  APP="$SYSTEM_APP"
else
  APP="$ARENA_DIR/app"
  STAMP="$APP/.mhplan-arena"
  if [ ! -f "$STAMP" ]; then
    if [ "$CHECK" = 1 ]; then
      echo "arena: Planner Arena is not installed in $ARENA_DIR (run scripts/setup.sh --arena)" >&2
      exit 3
    fi
    echo "arena: unpacking Debian's ompl-plannerarena into $ARENA_DIR (private; no system file changes)" >&2
    mkdir -p "$ARENA_DIR"
    WORK=$(mktemp -d "$ARENA_DIR/.work.XXXXXX")
    trap 'rm -rf "$WORK"' EXIT
    # apt-get download writes into the working directory; as root it warns that _apt cannot write there.
    (cd "$WORK" && apt-get download -qq ompl-plannerarena 2>&1 | grep -v "unsandboxed" >&2 || true)
    DEB=$(ls "$WORK"/ompl-plannerarena_*.deb 2>/dev/null | head -1 || true)
    [ -n "$DEB" ] || { echo "arena: 'apt-get download ompl-plannerarena' failed (run apt-get update?)" >&2; exit 3; }
    dpkg -x "$DEB" "$WORK/root"
    SRC="$WORK/root/usr/share/ompl/plannerarena"
    [ -f "$SRC/server.R" ] || { echo "arena: $DEB holds no plannerarena/server.R" >&2; exit 3; }
    # The two changes, each checked: a server.R of another version must fail here, not in the browser.
    grep -q '^library(pool)$' "$SRC/server.R" || { echo "arena: $DEB: server.R has no 'library(pool)' line" >&2; exit 3; }
    grep -q 'dbPool(' "$SRC/server.R" || { echo "arena: $DEB: server.R has no 'dbPool(' call" >&2; exit 3; }
    sed -i -e 's/^library(pool)$/library(DBI)/' -e 's/dbPool(/DBI::dbConnect(/g' "$SRC/server.R"
    ! grep -q 'pool' "$SRC/server.R" || { echo "arena: server.R still mentions pool after the patch" >&2; exit 3; }
    rm -rf "$APP"
    cp -r "$SRC" "$APP"
    dpkg-deb -f "$DEB" Version > "$STAMP"
    rm -rf "$WORK"
    trap - EXIT
  fi
fi

# Every library the app loads must load (a half-installed R would otherwise fail only in the browser).
if ! out=$(Rscript -e "for (p in strsplit('$R_LIBRARIES', ' ')[[1]]) suppressPackageStartupMessages(library(p, character.only = TRUE))" 2>&1); then
  echo "arena: R cannot load the app's packages: $out" >&2
  exit 3
fi

if [ "$BROWSER" = 1 ]; then
  NODE_DIR="$ARENA_DIR/node"
  if [ ! -f "$NODE_DIR/node_modules/puppeteer-core/package.json" ]; then
    if [ "$CHECK" = 1 ]; then
      echo "arena: puppeteer-core is not installed in $NODE_DIR (run scripts/setup.sh --arena)" >&2
      exit 3
    fi
    command -v npm >/dev/null 2>&1 || apt_install npm
    echo "arena: installing puppeteer-core $PUPPETEER_VERSION from npm into $NODE_DIR" >&2
    mkdir -p "$NODE_DIR"
    # puppeteer-core downloads no browser (Debian's chromium is used); --ignore-scripts all the same.
    (cd "$NODE_DIR" && [ -f package.json ] || echo '{"name": "mhplan-arena-test", "private": true}' > package.json)
    (cd "$NODE_DIR" && npm install --silent --no-audit --no-fund --ignore-scripts \
        "puppeteer-core@$PUPPETEER_VERSION" >/dev/null)
  fi
fi
echo "$APP"
