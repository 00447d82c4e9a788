#!/usr/bin/env bash
# The main job: installs what is missing, builds (Release), runs the paper's scene for both foundations
# (and the phi_f sweep of Figure 5) into results/paper2d/, and draws Figures 2-5 into
# results/paper2d/figures/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_dependencies.sh
scripts/build.sh release piezocontact_cli
build/release/examples/piezocontact run scenes/paper2d.json --out results/paper2d "$@"
python3 scripts/plot_paper2d.py results/paper2d
