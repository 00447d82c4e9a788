#!/usr/bin/env python3
"""Coulomb friction as its regularisation goes to zero, on the motor scene with the slider held: for each
eps (m/s) of p_tau = mu |p_nu| v_tau / sqrt(|v_tau|^2 + eps^2), the thrust (mean force on the slider over
the last 10 periods), its ripple (standard deviation), the share of pressed node-steps that stick
(slip at most eps), Newton's iterations per step and the run's wall time. It shows the accuracy that a
smaller eps buys and what it costs.

Usage:  python3 benchmarks/stick_slip_study.py [OUT] [eps ...]    (default OUT: results/stick_slip,
        eps: 1e-2 3e-3 1e-3 3e-4 1e-4)
Writes OUT/stick_slip.csv and prints a markdown table. Needs build/release/examples/piezocontact.
"""
import csv
import json
import os
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUNNER = os.path.join(ROOT, "build/release/examples/piezocontact")
SCENE = os.path.join(ROOT, "scenes/motor2d.json")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    out = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "results/stick_slip"))
    epsilons = [float(x) for x in sys.argv[2:]] or [1e-2, 3e-3, 1e-3, 3e-4, 1e-4]
    with open(SCENE) as f:
        scene = json.load(f)
    frequency = scene["electrodes"][0]["voltage"]["frequency"]
    steps_per_period = round(scene["time"]["steps"] / (scene["time"]["T"] * frequency))
    window = 10 * steps_per_period
    results = []
    for eps in epsilons:
        directory = os.path.join(out, "eps_%g" % eps)
        # The slip threshold of the contact state is eps itself: "sticking" is the regularised law's
        # near-linear zone, which shrinks with eps.
        subprocess.run([RUNNER, "run", SCENE, "--out", directory, "--quiet", "--set", "contact.eps=%g" % eps,
                        "--set", "output.slip_threshold=%g" % eps, "--set", "output.contact_history=true",
                        "--set", "output.vtu_every=100000"], check=True)
        run = os.path.join(directory, "insulated")
        history = rows(os.path.join(run, "history.csv"))[-window:]
        force = [-float(r["contact_fx"]) for r in history]
        states = rows(os.path.join(run, "contact_state.csv"))[-window:]
        pressed = stick = 0
        for r in states:
            for key, value in r.items():
                if key == "t":
                    continue
                pressed += value != "0"
                stick += value == "1"
        with open(os.path.join(run, "summary.json")) as f:
            summary = json.load(f)
        results.append((eps, statistics.mean(force), statistics.pstdev(force), stick / max(pressed, 1),
                        summary["newton_iterations_total"] / summary["steps"], summary["wall_s_total"]))
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "stick_slip.csv"), "w") as f:
        f.write("eps,thrust,ripple,stick_share,newton_per_step,wall_s\n")
        for r in results:
            f.write(",".join("%.10g" % x for x in r) + "\n")
    print("| eps [m/s] | thrust [N/m] | ripple [N/m] | sticking share of pressed node-steps | Newton per step | wall [s] |")
    print("|---|---|---|---|---|---|")
    for r in results:
        print("| %g | %.4g | %.4g | %.3f | %.2f | %.1f |" % r)


if __name__ == "__main__":
    main()
