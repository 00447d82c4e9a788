#!/usr/bin/env python3
"""Coulomb friction as its regularisation goes to zero, and without one, on the motor scene with the
slider held: for each eps (m/s) of p_tau = mu |p_nu| v_tau / sqrt(|v_tau|^2 + eps^2), and for each
augmentation r (Pa s/m) of the exact law (coulomb_exact, an Alart-Curnier multiplier), the thrust (mean
force on the slider over the last 10 periods), its ripple (standard deviation), the share of pressed
node-steps that stick (slip at most eps; for the exact law at most 1e-6 m/s), Newton's iterations per step
and the run's wall time. It shows the accuracy that a smaller eps buys, what it costs, and where the
exact law lands.

Usage:  python3 benchmarks/stick_slip_study.py [OUT] [eps ...] [--exact r ...]
        (default OUT: results/stick_slip, eps: 1e-2 3e-3 1e-3 3e-4 1e-4, r: 1e6 3e6 1e7)
Writes OUT/stick_slip.csv and prints a markdown table. Needs build/release/examples/piezocontact.
"""
import csv
import json
import os
import shutil
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUNNER = os.path.join(ROOT, "build/release/examples/piezocontact")
SCENE = os.path.join(ROOT, "scenes/motor2d.json")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def measure(directory, window, threshold, overrides, scene=SCENE):
    subprocess.run([RUNNER, "run", scene, "--out", directory, "--quiet", "--set", "output.slip_threshold=%g" % threshold,
                    "--set", "output.contact_history=true", "--set", "output.vtu_every=100000"] + overrides, check=True)
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
    return (statistics.mean(force), statistics.pstdev(force), stick / max(pressed, 1),
            summary["newton_iterations_total"] / summary["steps"], summary["wall_s_total"])


def is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def exact_scene(scene, r, directory):
    """The motor scene with coulomb_exact at augmentation r, next to a copy of its mesh."""
    os.makedirs(directory, exist_ok=True)
    variant = json.loads(json.dumps(scene))
    contact = variant["contact"]
    contact.pop("eps")
    contact["law_tangential"] = "coulomb_exact"
    contact["r"] = r
    shutil.copy(os.path.join(ROOT, "scenes", scene["mesh"]["gmsh"]), directory)
    path = os.path.join(directory, "motor2d.json")
    with open(path, "w") as f:
        json.dump(variant, f, indent=1)
    return path


def main():
    args = sys.argv[1:]
    out = os.path.abspath(args.pop(0) if args and args[0] != "--exact" and not is_number(args[0])
                          else os.path.join(ROOT, "results/stick_slip"))
    exact_at = args.index("--exact") if "--exact" in args else len(args)
    epsilons = [float(x) for x in args[:exact_at]] or [1e-2, 3e-3, 1e-3, 3e-4, 1e-4]
    augmentations = [float(x) for x in args[exact_at + 1:]] or [1e6, 3e6, 1e7]
    with open(SCENE) as f:
        scene = json.load(f)
    frequency = scene["electrodes"][0]["voltage"]["frequency"]
    steps_per_period = round(scene["time"]["steps"] / (scene["time"]["T"] * frequency))
    window = 10 * steps_per_period
    results = []
    # The slip threshold of the regularised law's contact state is eps itself: "sticking" is its
    # near-linear zone, which shrinks with eps.
    for eps in epsilons:
        directory = os.path.join(out, "eps_%g" % eps)
        results.append(("coulomb eps=%g" % eps,) + measure(directory, window, eps, ["--set", "contact.eps=%g" % eps]))
    for r in augmentations:
        directory = os.path.join(out, "exact_r_%g" % r)
        results.append(("coulomb_exact r=%g" % r,) + measure(directory, window, 1e-6, [],
                                                             exact_scene(scene, r, directory + "_scene")))
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "stick_slip.csv"), "w") as f:
        f.write("law,thrust,ripple,stick_share,newton_per_step,wall_s\n")
        for r in results:
            f.write(r[0] + "," + ",".join("%.10g" % x for x in r[1:]) + "\n")
    print("| law | force on the slider [N/m] | ripple [N/m] | sticking share of pressed node-steps | Newton per step | wall [s] |")
    print("|---|---|---|---|---|---|")
    for r in results:
        print("| %s | %.4g | %.4g | %.3f | %.2f | %.1f |" % r)


if __name__ == "__main__":
    main()
