#!/usr/bin/env python3
"""Speed against accuracy on the paper's scene: the Pareto plot and the README table.

Usage:  python3 scripts/plot_speed_accuracy.py CSV PNG [MARKDOWN]

CSV is the table written by
    nice build/release/benchmarks/speed_accuracy_study OUT      (OUT/speed_accuracy.csv)
PNG receives error against wall time (log-log): one colour per sweep axis, circles P1, squares P2, the
baseline (the scene as shipped) as a star and the Pareto front of all completed runs as a line.
The markdown goes to stdout (and to MARKDOWN if given): for each target error 10 %, 1 %, 0.1 % the
cheapest completed run (least wall time) meeting it, in all of u, v, phi and in u and phi only, then
every run, axis by axis.
"error" is the study's column: max of the relative L2 errors of u, v, phi at the final time against
the reference run. When the CSV holds a setting twice under one axis (the study appends to an existing
CSV), the last row counts. Needs matplotlib only.
"""
import csv
import math
import os
import sys

from plot_support import require_plotting

require_plotting("matplotlib")
import matplotlib.pyplot as plt  # noqa: E402

TARGETS = (0.1, 0.01, 0.001)
AXES = ("mesh", "order", "steps", "scheme", "c_nu", "tolerance", "condensation", "linear", "joint")
COLOURS = dict(zip(AXES, ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown",
                          "tab:cyan", "tab:pink", "tab:gray")))
NUMBERS = ("baseline", "nx", "ny", "order", "steps", "c_nu", "tolerance", "completed", "dofs", "steps_done",
           "newton_iterations", "wall_s", "peak_rss_mib", "err_u", "err_v", "err_phi", "err_uy_corner_t",
           "err_phi_center_t", "error")
RUN_HINT = "produce it with: nice build/release/benchmarks/speed_accuracy_study OUT"


# ----------------------------------------------------------------------------------------- input
def read_rows(path):
    """The CSV's rows as dicts with numbers parsed; the last row of each (axis, label) wins."""
    if not os.path.isfile(path):
        sys.exit(f"error: no file {path} ({RUN_HINT})")
    rows = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            lacking = [c for c in NUMBERS + ("axis", "label", "scheme", "linear", "condensation") if c not in row]
            if lacking:
                sys.exit(f"error: {path} lacks column(s) {', '.join(lacking)}")
            for c in NUMBERS:
                row[c] = float(row[c])
            rows[(row["axis"], row["label"])] = row
    if not rows:
        sys.exit(f"error: {path} has no data rows ({RUN_HINT})")
    return list(rows.values())


def usable(row):
    return row["completed"] == 1 and math.isfinite(row["error"]) and row["wall_s"] > 0


# ----------------------------------------------------------------------------------------- table
def settings(row):
    """What a user sets, in words."""
    scheme = {"backward_euler": "backward Euler", "bdf2": "BDF2", "theta": "Crank-Nicolson"}.get(row["scheme"],
                                                                                                   row["scheme"])
    return (f"{int(row['nx'])} x {int(row['ny'])} P{int(row['order'])}, {int(row['steps'])} steps, {scheme}, "
            f"c_nu {num(row['c_nu'])}, tol {num(row['tolerance'])}, {row['linear']}, {row['condensation']}")


def pct(x):
    return f"{100 * x:.2g} %" if math.isfinite(x) else "n/a"


def num(x):
    """1e12 rather than 1e+12."""
    return f"{x:g}".replace("e+", "e")


def unique_runs(rows):
    """One row per setting (a setting on several axes was run once)."""
    seen = {}
    for r in rows:
        seen.setdefault(r["label"], r)
    return list(seen.values())


def targets_table(rows, fields):
    """For each target, the cheapest completed run whose error in `fields` (max over them) meets it."""
    def error(r):
        return max(r[f] for f in fields)
    runs = [r for r in unique_runs(rows) if usable(r) and math.isfinite(error(r))]
    names = " / ".join(f[4:] for f in fields)
    lines = [f"| target error in {names} | cheapest run meeting it | dofs | Newton its | wall [s] | peak RSS [MiB] | "
             f"error ({names}) |", "|---|---|--:|--:|--:|--:|---|"]
    for target in TARGETS:
        meeting = [r for r in runs if error(r) <= target]
        if not meeting:
            best = min(runs, key=error) if runs else None
            lines.append(f"| {pct(target)} | no run of the study meets it"
                         + (f" (best: {pct(error(best))}, {settings(best)})" if best else "") + " | | | | | |")
            continue
        r = min(meeting, key=lambda r: r["wall_s"])
        lines.append(f"| {pct(target)} | {settings(r)} | {int(r['dofs'])} | {int(r['newton_iterations'])} | "
                     f"{r['wall_s']:.2f} | {r['peak_rss_mib']:.0f} | "
                     + " / ".join(pct(r[f]) for f in fields) + " |")
    return lines


def sweeps_table(rows):
    lines = ["| axis | settings | dofs | Newton its | wall [s] | peak RSS [MiB] | err u | err v | err phi | "
             "err uy_corner(t) | err phi_center(t) |", "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|"]
    for a in AXES:
        for r in (r for r in rows if r["axis"] == a):
            stopped = "" if r["completed"] == 1 else " (stopped)"
            lines.append(f"| {a} | {settings(r)}{stopped} | {int(r['dofs'])} | {int(r['newton_iterations'])} | "
                         f"{r['wall_s']:.2f} | {r['peak_rss_mib']:.0f} | "
                         + " | ".join(f"{r[c]:.1e}" for c in ("err_u", "err_v", "err_phi", "err_uy_corner_t",
                                                               "err_phi_center_t")) + " |")
    return lines


# ----------------------------------------------------------------------------------------- plot
def pareto(runs):
    """Runs that no other run beats in both wall time and error, by increasing wall time."""
    front, best = [], math.inf
    for r in sorted(runs, key=lambda r: (r["wall_s"], r["error"])):
        if r["error"] < best:
            front.append(r)
            best = r["error"]
    return front


def short(row):
    """A Pareto point's annotation: mesh, order, steps and what differs from backward Euler."""
    scheme = {"backward_euler": "", "bdf2": " BDF2", "theta": " CN"}.get(row["scheme"], " " + row["scheme"])
    return f"{int(row['nx'])}x{int(row['ny'])} P{int(row['order'])} {int(row['steps'])}{scheme}"


def plot(rows, png):
    fig, ax = plt.subplots(figsize=(11.5, 6))
    for a in AXES:
        # the joint sweep runs two schemes: backward Euler grey, BDF2 olive
        for scheme, colour in (((None, COLOURS[a]),) if a != "joint" else
                               (("backward_euler", COLOURS[a]), ("bdf2", "tab:olive"))):
            for order, marker in ((1, "o"), (2, "s")):
                sel = [r for r in rows if r["axis"] == a and r["order"] == order and usable(r)
                       and scheme in (None, r["scheme"])]
                if not sel:
                    continue
                label = (f"{a}, P{order}" if a == "order" else
                         f"joint, P{order}, {'BDF2' if scheme == 'bdf2' else 'backward Euler'}" if a == "joint" else
                         "c_nu (error includes the penalty's modelling error)" if a == "c_nu" else a)
                ax.loglog([r["wall_s"] for r in sel], [r["error"] for r in sel], marker, ls="none", ms=7,
                          mfc="none" if a == "joint" else colour, mec=colour, alpha=0.85,
                          label=label if order == 1 or a in ("order", "joint") else None)
    for r in rows:
        if r["baseline"] == 1 and usable(r):
            ax.loglog(r["wall_s"], r["error"], "*", color="k", ms=15, zorder=5, label="baseline (scene as shipped)")
            break
    front = pareto([r for r in unique_runs(rows) if usable(r)])
    ax.loglog([r["wall_s"] for r in front], [r["error"] for r in front], "-", color="k", lw=1.5, alpha=0.6,
              drawstyle="steps-post", zorder=4, label="Pareto front")
    for i, r in enumerate(front):  # above and below in turn: neighbours on the front are close
        ax.annotate(short(r), (r["wall_s"], r["error"]), textcoords="offset points",
                    xytext=(4, 4 if i % 2 == 0 else -10), fontsize=6)
    for target in TARGETS:
        ax.axhline(target, color="0.6", ls=":", lw=0.8)
        ax.text(1.0, target, f"{pct(target)} ", transform=ax.get_yaxis_transform(), ha="right", va="bottom",
                fontsize=7, color="0.4")
    ax.set_xlabel("wall time of the run [s] (fastest of the study's repeats, shared 2-core machine)")
    ax.set_ylabel("error: max of relative L2 errors of u, v, phi at T")
    ax.set_title("Speed against accuracy, paper scene, conductive foundation\n"
                 "(circles P1, squares P2; open: joint sweep of mesh x order x steps x scheme)", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    plt.close(fig)


# ----------------------------------------------------------------------------------------- main
def main(argv):
    if len(argv) not in (3, 4) or argv[1] in ("-h", "--help"):
        print(__doc__, file=sys.stderr)
        return 2
    rows = read_rows(argv[1])
    plot(rows, argv[2])
    stopped = [r for r in unique_runs(rows) if r["completed"] != 1]
    lines = targets_table(rows, ("err_u", "err_v", "err_phi"))
    lines += ["", "Without v (u and phi only, e.g. for the paper's figures):", ""]
    lines += targets_table(rows, ("err_u", "err_phi"))
    lines += ["", f"{len(unique_runs(rows))} runs, {len(stopped)} did not complete"
              + "".join(f"; {settings(r)}: {r['message']}" for r in stopped) + ".", ""]
    lines += sweeps_table(rows)
    text = "\n".join(lines) + "\n"
    print(text, end="")
    if len(argv) == 4:
        with open(argv[3], "w") as f:
            f.write(text)
    print(f"wrote {argv[2]}" + (f" and {argv[3]}" if len(argv) == 4 else ""), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
