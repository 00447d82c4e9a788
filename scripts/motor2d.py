#!/usr/bin/env python3
"""The 2D motor scene from one command: its modes, a run with the slider held, the thrust-speed sweep and
the figures.

Usage:  python3 scripts/motor2d.py [OUT]        (default OUT: results/motor2d)

Runs build/release/examples/piezocontact (build it with scripts/build.sh release piezocontact_cli):
    OUT/motor2d/modes/            piezocontact modes: the stator's first eigenfrequencies and shapes
    OUT/speed_<s>/insulated/      one run per slider speed s (m/s) along the direction the stator drives it
    OUT/thrust_speed.csv          speed, thrust (mean force on the slider over the last 10 periods), its
                                  ripple (standard deviation over those periods), electrical power in, mechanical power out
    OUT/figures/                  motor_shape.png, motor_contact_state.png, motor_thrust_speed.png,
                                  motor_energy.png
Two runs at a time (the machine's two cores). Needs numpy and matplotlib (python3-numpy python3-matplotlib).
"""
import csv
import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

from plot_support import require_plotting

require_plotting("numpy", "matplotlib")
import numpy as np  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUNNER = os.path.join(ROOT, "build/release/examples/piezocontact")
SCENE = os.path.join(ROOT, "scenes/motor2d.json")
SPEEDS = [0.0, 0.0005, 0.001, 0.002, 0.004, 0.01, 0.03]  # m/s, along the drive
LAST_PERIODS = 10


def scene():
    with open(SCENE) as f:
        return json.load(f)


def velocity_override(speed):
    """contact.foundation_velocity with the slider's speed along x and the scene's approach along y."""
    approach = scene()["contact"]["foundation_velocity"][1]
    return "contact.foundation_velocity=" + json.dumps([speed, approach])


def run(out, speed, extra=()):
    args = [RUNNER, "run", SCENE, "--out", out, "--quiet", "--set", velocity_override(speed)] + list(extra)
    subprocess.run(args, check=True)
    return os.path.join(out, "insulated")


def table(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:]])


def last_periods(history_dir):
    header, rows = table(os.path.join(history_dir, "history.csv"))
    s = scene()
    frequency = s["electrodes"][0]["voltage"]["frequency"]
    steps_per_period = round(s["time"]["steps"] / (s["time"]["T"] * frequency))
    return header, rows[-LAST_PERIODS * steps_per_period:], steps_per_period


def summary(history_dir, speed_along_x):
    header, rows, _ = last_periods(history_dir)
    col = {name: i for i, name in enumerate(header)}
    force_on_slider = -rows[:, col["contact_fx"]]
    electrodes = [name[2:] for name in header if name.startswith("V_")]
    power_in = np.mean(sum(rows[:, col["V_" + e]] * rows[:, col["I_" + e]] for e in electrodes))
    return np.mean(force_on_slider), np.std(force_on_slider), power_in


def main():
    out = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "results/motor2d"))
    if not os.path.exists(RUNNER):
        sys.exit("error: %s is missing: build it with scripts/build.sh release piezocontact_cli" % RUNNER)
    os.makedirs(os.path.join(out, "figures"), exist_ok=True)
    subprocess.run([RUNNER, "modes", SCENE, "--count", "6", "--out", out], check=True)

    # The slider held: its thrust says which way the stator drives it; the run keeps the shapes of the
    # last period (u every quarter period, as text VTU) and the contact state at every step.
    s = scene()
    frequency = s["electrodes"][0]["voltage"]["frequency"]
    steps_per_period = round(s["time"]["steps"] / (s["time"]["T"] * frequency))
    held = run(os.path.join(out, "speed_0"), 0.0,
               ["--set", "output.contact_history=true", "--set", "output.vtu_format=ascii",
                "--set", 'output.vtu_fields=["u"]', "--set", "output.vtu_every=%d" % (steps_per_period // 4)])
    thrust0, _, _ = summary(held, 0.0)
    direction = 1.0 if thrust0 >= 0 else -1.0
    print("slider held: force on it %.4g N/m, so the stator drives it toward %sx" % (thrust0, "+" if direction > 0 else "-"))

    def sweep_point(speed):
        directory = held if speed == 0 else run(os.path.join(out, "speed_%g" % speed), direction * speed,
                                                ["--set", "output.vtu_every=100000"])
        thrust, ripple, power_in = summary(directory, direction * speed)
        return speed, direction * thrust, ripple, power_in, direction * thrust * speed

    with ThreadPoolExecutor(max_workers=2) as pool:
        points = list(pool.map(sweep_point, SPEEDS))
    with open(os.path.join(out, "thrust_speed.csv"), "w") as f:
        f.write("speed,thrust,ripple,power_in,power_out\n")
        for p in points:
            f.write(",".join("%.17g" % x for x in p) + "\n")
    for p in points:
        print("speed %-7.4g m/s: thrust %9.4g N/m, ripple %9.4g N/m, power in %9.4g W/m, out %9.4g W/m" % p)
    figures(out, held, points, steps_per_period)


def read_ascii_vtu(path):
    """Points and the u array of a text VTU."""
    text = open(path).read()

    def array(name):
        # The array's text starts after its <DataArray ...> tag: the one named, or the first in <Points>.
        start = text.index('Name="%s"' % name) if name != "Points" else text.index("<DataArray", text.index("<Points>"))
        begin = text.index(">", start) + 1
        return np.array(text[begin:text.index("</DataArray>", begin)].split(), dtype=float).reshape(-1, 3)
    return array("Points"), array("u")


def figures(out, held, points, steps_per_period):
    fig_dir = os.path.join(out, "figures")
    # 1. The stator's shape at four phases of the last period (top and bottom faces, amplified).
    with open(os.path.join(held, "motor2d.pvd")) as f:
        files = [line.split('file="')[1].split('"')[0] for line in f if 'file="' in line]
    plt.figure(figsize=(8, 3.2))
    xyz, _ = read_ascii_vtu(os.path.join(held, files[-1]))
    height = xyz[:, 1].max()
    amplify = None
    for k, name in enumerate(files[-4:]):
        xyz, u = read_ascii_vtu(os.path.join(held, name))
        if amplify is None:
            amplify = 0.2 * height / max(np.abs(u[:, :2]).max(), 1e-300)
        for y in (0.0, height):
            on = np.where(np.abs(xyz[:, 1] - y) < 1e-9)[0]
            on = on[np.argsort(xyz[on, 0])]
            plt.plot(1e3 * (xyz[on, 0] + amplify * u[on, 0]), 1e3 * (xyz[on, 1] + amplify * u[on, 1]),
                     color="C%d" % k, label="phase %d/4" % k if y == 0 else None)
    plt.xlabel("x [mm]")
    plt.ylabel("y [mm]")
    plt.title("stator at four phases of the last period (displacement x %.0f)" % amplify)
    plt.legend(fontsize=7, ncol=4)
    plt.tight_layout()
    plt.savefig(os.path.join(fig_dir, "motor_shape.png"), dpi=120)
    plt.close()

    # 2. The contact state along the interface over the last two periods.
    _, states = table(os.path.join(held, "contact_state.csv"))
    _, where = table(os.path.join(held, "contact_nodes.csv"))
    tail = states[-2 * steps_per_period:]
    plt.figure(figsize=(7, 3.5))
    plt.pcolormesh(1e3 * where[:, 0], 1e6 * tail[:, 0], tail[:, 1:], shading="nearest", cmap="viridis", vmin=0, vmax=2)
    bar = plt.colorbar(ticks=[0, 1, 2])
    bar.ax.set_yticklabels(["separated", "sticking", "slipping"])
    plt.xlabel("x [mm]")
    plt.ylabel("t [us]")
    plt.title("contact state over two periods, slider held")
    plt.tight_layout()
    plt.savefig(os.path.join(fig_dir, "motor_contact_state.png"), dpi=120)
    plt.close()

    # 3. Thrust against speed.
    p = np.array(points)
    plt.figure(figsize=(5, 3.5))
    plt.errorbar(p[:, 0], p[:, 1], yerr=p[:, 2], marker="o", capsize=3)
    plt.axhline(0, color="grey", lw=0.8)
    plt.xlabel("slider speed [m/s]")
    plt.ylabel("thrust [N/m]")
    plt.title("thrust-speed (bars: ripple, one standard deviation)")
    plt.tight_layout()
    plt.savefig(os.path.join(fig_dir, "motor_thrust_speed.png"), dpi=120)
    plt.close()

    # 4. The energy books over time, slider held.
    header, rows = table(os.path.join(held, "history.csv"))
    col = {name: i for i, name in enumerate(header)}
    t = 1e3 * rows[:, 0]
    plt.figure(figsize=(7, 4))
    stored = rows[:, col["E_kinetic"]] + rows[:, col["E_elastic"]] + rows[:, col["E_electric"]]
    for label, values in [("stored (kinetic + elastic + electric)", stored),
                          ("viscous dissipation", rows[:, col["W_viscous"]]),
                          ("contact dissipation", rows[:, col["W_contact"]]),
                          ("numerical dissipation", rows[:, col["W_numerical"]]),
                          ("electrodes' work (boundary)", rows[:, col["W_boundary"]]),
                          ("|balance|", np.abs(rows[:, col["E_balance"]]))]:
        plt.semilogy(t, np.maximum(np.abs(values), 1e-30), label=label)
    plt.xlabel("t [ms]")
    plt.ylabel("energy [J/m]")
    plt.title("energy books, slider held")
    plt.legend(fontsize=7)
    plt.tight_layout()
    plt.savefig(os.path.join(fig_dir, "motor_energy.png"), dpi=120)
    plt.close()
    print("figures in", fig_dir)


if __name__ == "__main__":
    main()
