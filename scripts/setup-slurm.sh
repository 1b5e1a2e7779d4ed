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
cd "$(dirname "$0")/.."
. scripts/debian-packages.sh
mhplan_ensure_debs setup-slurm "missing Debian packages" "${PACKAGES[@]}"
