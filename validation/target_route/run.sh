#!/usr/bin/env bash
# Solve/Target's condensed route (README.md): inputs/target_torque_sweep.prm (the demo pair at
# ten torques with a target) run as it is (the sweeps on one condensed cycle of the delivered
# model) and with `Target route = full FE`, each twice in a row (the smaller CPU kept); check.py
# compares the two routes' results over all 400 rows, the condensation error the run measured
# on itself, and their CPU. About 20 s on the 2-core machine.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
check --gearfem "$gearfem" --input "$root/inputs/target_torque_sweep.prm" --out "$out"
