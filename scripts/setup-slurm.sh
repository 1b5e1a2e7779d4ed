#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Install what the cluster tests need (only what is missing): Debian's Slurm (slurm-wlm: slurmctld, slurmd,
# the client commands) and GNU parallel. Nothing is configured or started here: tests/slurm/slurm_test.sh
# starts its own one-node cluster in a temporary directory (scripts/slurm/start-cluster.sh) and stops it.
# Costs about 25 s on a fresh Debian 12 (measured: apt-get update + install, 22 s). Skipped when
# MHPLAN_NO_SLURM=1 (the tests then report themselves skipped). Usage: scripts/setup-slurm.sh
set -euo pipefail
[ "${MHPLAN_NO_SLURM:-0}" = 1 ] && exit 0
PACKAGES=(slurm-wlm parallel)
missing=()
for p in "${PACKAGES[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "setup-slurm: installing missing Debian packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "setup-slurm: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
