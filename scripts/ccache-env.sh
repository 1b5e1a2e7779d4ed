# SPDX-License-Identifier: BSD-3-Clause
# Sourced by setup.sh, sanitize.sh and fuzz.sh: use ccache when it is installed, with paths below the
# repository rewritten to relative ones and the working directory left out of the hash, so that another clone
# of the same sources (a CI checkout, a worktree) hits the same cache entries. Sets MHPLAN_LAUNCHER to the
# CMake option that turns it on (empty without ccache). MHPLAN_NO_CCACHE=1 turns it off.
MHPLAN_LAUNCHER=()
if [ "${MHPLAN_NO_CCACHE:-0}" != "1" ] && command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="$PWD"
  export CCACHE_NOHASHDIR=1
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-include_file_mtime,include_file_ctime,time_macros}"
  MHPLAN_LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
