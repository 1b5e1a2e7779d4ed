# SPDX-License-Identifier: BSD-3-Clause
# Sourced by every script that installs Debian packages (setup.sh, setup-slurm.sh, arena/install.sh): one
# way to find what is missing and to install it.
#   mhplan_missing_debs PKG...            prints, one per line, the packages that are not installed
#   mhplan_apt_install WHO PKG...         installs PKG... (apt-get, no recommends, quiet), as root or through
#                                         sudo; without either it prints "WHO: need root (or sudo) to
#                                         install: PKG..." and returns 1. Nothing to do without PKG.
#   mhplan_ensure_debs WHO WHAT PKG...    installs those of PKG... that are missing, announcing
#                                         "WHO: installing WHAT: <the missing ones>"; returns 0 when nothing was
#                                         missing or all were installed, and sets MHPLAN_DEBS_INSTALLED=1 when
#                                         it installed something.

mhplan_missing_debs() {
  local p status
  for p in "$@"; do
    status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
    [ "$status" = "installed" ] || echo "$p"
  done
}

mhplan_apt_install() {
  local who="$1"; shift
  [ $# -gt 0 ] || return 0
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null 2>&1; then
      echo "$who: need root (or sudo) to install: $*" >&2
      return 1
    fi
    sudo="sudo"
  fi
  DEBIAN_FRONTEND=noninteractive $sudo apt-get update -qq >/dev/null
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "$@" >/dev/null
}

MHPLAN_DEBS_INSTALLED=0
mhplan_ensure_debs() {
  local who="$1" what="$2"; shift 2
  local need
  mapfile -t need < <(mhplan_missing_debs "$@")
  [ ${#need[@]} -gt 0 ] || return 0
  echo "$who: installing $what: ${need[*]}"
  mhplan_apt_install "$who" "${need[@]}" || return 1
  MHPLAN_DEBS_INSTALLED=1
}
