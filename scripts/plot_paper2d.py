#!/usr/bin/env python3
"""Figures 2-5 of the seed paper's 2D example, from the piezocontact runner's output.

Usage:  python3 scripts/plot_paper2d.py OUT

OUT is the directory written by
    build/release/examples/piezocontact run scenes/paper2d.json --out OUT
(OUT/insulated/, OUT/conductive/, optionally OUT/sweep_phi_f.csv). The PNGs go to OUT/figures/:
    figure2_deformed_mesh.png           amplified deformed mesh, insulated | conductive
    figure3_contact_velocity.png        vx, vy on Gamma_C at the final time, sliding nodes marked
    figure4_potential_von_mises.png     conductive case: potential [V] and von Mises stress [Pa]
    figure5_displacement_vs_voltage.png max |ux|, max |uy| against the foundation voltage phi_f
A figure whose input is missing is skipped with a message; the exit code is 0 if at least one
figure was written. Needs numpy and matplotlib only (Debian: python3-numpy python3-matplotlib).
"""
import json
import os
import sys

from plot_support import require_plotting

require_plotting("numpy", "matplotlib")
import numpy as np  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

FOUNDATIONS = ("insulated", "conductive")
RUN_HINT = "produce it with: build/release/examples/piezocontact run scenes/paper2d.json --out OUT"
PAPER_PHI_F = ((0.75, "paper, Fig. 5 text: |ux| 0.8e-3 µm, |uy| 1.1e-3 µm"), (-48.0, "paper, Figs. 2-4"))


class MissingInput(Exception):
    pass


# ----------------------------------------------------------------------------------------- input
def read_csv(path, columns):
    """Structured array of a CSV file with a header line; checks that `columns` are present."""
    if not os.path.isfile(path):
        raise MissingInput(f"missing file {path} ({RUN_HINT})")
    try:
        data = np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True, dtype=float))
    except ValueError as e:
        raise MissingInput(f"cannot read {path}: {e}")
    names = data.dtype.names or ()
    lacking = [c for c in columns if c not in names]
    if lacking:
        raise MissingInput(f"{path} lacks column(s) {', '.join(lacking)} (has: {', '.join(names)})")
    if data.size == 0:
        raise MissingInput(f"{path} has no data rows")
    return data


def read_summary(out, foundation):
    path = os.path.join(out, foundation, "summary.json")
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        print(f"note: no usable {path} ({e}); going on without it", file=sys.stderr)
        return {}


def read_mesh(out, foundation):
    """Nodes and cells of one run as a dict of numpy arrays."""
    d = os.path.join(out, foundation)
    nodes = read_csv(os.path.join(d, "final_nodes.csv"), ("node", "x", "y", "ux", "uy", "vx", "vy", "phi"))
    cells = read_csv(os.path.join(d, "final_cells.csv"), ("n0", "n1", "n2", "von_mises"))
    order = np.argsort(nodes["node"])
    nodes = nodes[order]
    if not np.array_equal(nodes["node"], np.arange(nodes.size)):
        raise MissingInput(f"{d}/final_nodes.csv: node indices are not 0..{nodes.size - 1}")
    tri = np.column_stack([cells["n0"], cells["n1"], cells["n2"]]).astype(int)
    if tri.min() < 0 or tri.max() >= nodes.size:
        raise MissingInput(f"{d}/final_cells.csv: node index out of range 0..{nodes.size - 1}")
    return {k: nodes[k] for k in ("x", "y", "ux", "uy", "phi")} | {"tri": tri, "von_mises": cells["von_mises"]}


def final_time(out, foundation):
    try:
        return float(read_csv(os.path.join(out, foundation, "history.csv"), ("t",))["t"][-1])
    except MissingInput:
        return None


# ----------------------------------------------------------------------------------------- helpers
def amplification(m):
    """Factor that shows the largest displacement as 10 % of the strip height."""
    height = np.ptp(m["y"]) or 0.01
    umax = np.hypot(m["ux"], m["uy"]).max()
    return 0.1 * height / umax if umax > 0 else 1.0


def sci(v):
    """2.1e5 rather than 2.1e+05."""
    mant, exp = f"{v:.1e}".split("e")
    return f"{mant}e{int(exp)}"


def boundary_segments(m):
    """Undeformed boundary of the mesh: edges that belong to one triangle only."""
    edges = np.sort(np.concatenate([m["tri"][:, [0, 1]], m["tri"][:, [1, 2]], m["tri"][:, [2, 0]]]), axis=1)
    uniq, count = np.unique(edges, axis=0, return_counts=True)
    b = uniq[count == 1]
    return np.stack([np.column_stack([m["x"][b[:, k]], m["y"][b[:, k]]]) for k in (0, 1)], axis=1)


def deformed_triangulation(m, s):
    return mtri.Triangulation(m["x"] + s * m["ux"], m["y"] + s * m["uy"], m["tri"])


def finish_mesh_axes(ax):
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")


def time_label(t):
    return f"final time T = {t:g} s" if t is not None else "final time"


# ----------------------------------------------------------------------------------------- figures
def figure2(out, figdir):
    meshes = {f: read_mesh(out, f) for f in FOUNDATIONS}
    fig, axes = plt.subplots(1, 2, figsize=(13, 3.3), sharey=True)
    for ax, (label, f) in zip(axes, zip("ab", FOUNDATIONS)):
        m = meshes[f]
        s = amplification(m)
        ax.add_collection(LineCollection(boundary_segments(m), colors="0.75", linewidths=2.0, zorder=1))
        ax.triplot(deformed_triangulation(m, s), color="tab:blue", linewidth=0.4, zorder=2)
        umax = np.hypot(m["ux"], m["uy"]).max()
        ax.set_title(f"({label}) {f} foundation: displacement × {sci(s)}\n(max |u| = {umax:.2e} m)", fontsize=10)
        finish_mesh_axes(ax)
    axes[1].set_ylabel("")
    fig.suptitle(f"Figure 2. Amplified deformed mesh at {time_label(final_time(out, 'conductive'))}"
                 " (grey: undeformed outline)", fontsize=11)
    fig.tight_layout()
    return save(fig, figdir, "figure2_deformed_mesh.png")


def figure3(out, figdir):
    cols = ("x", "vx", "vy")
    data = {f: read_csv(os.path.join(out, f, "gamma_c.csv"), cols) for f in FOUNDATIONS}
    fig, (ax_x, ax_y) = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    for f, color in zip(FOUNDATIONS, ("tab:blue", "tab:red")):
        g = np.sort(data[f], order="x")
        ax_x.plot(g["x"], g["vx"], "-", color=color, lw=1.2, label=f"{f}: $v_x$")
        ax_y.plot(g["x"], g["vy"], "-", color=color, lw=1.2, label=f"{f}: $v_y$")
        summary = read_summary(out, f)
        thr = summary.get("slip_threshold")
        if thr is None:
            continue
        slip = np.abs(g["vx"]) > thr
        ax_x.plot(g["x"][slip], g["vx"][slip], "o", mfc="none", color=color, ms=6,
                  label=f"{f}: sliding, |$v_x$| > {thr:g} m/s ({slip.sum()} nodes)")
        ax_y.plot(g["x"][slip], g["vy"][slip], "o", mfc="none", color=color, ms=6)
        if "n_slip_nodes" in summary and summary["n_slip_nodes"] != slip.sum():
            print(f"note: {f}: summary.json says n_slip_nodes = {summary['n_slip_nodes']}, "
                  f"gamma_c.csv has {slip.sum()} nodes with |vx| > {thr:g}", file=sys.stderr)
    ax_x.set_ylabel("tangential velocity $v_x$ [m/s]")
    ax_y.set_ylabel("normal velocity $v_y$ [m/s]")
    ax_y.set_xlabel("x on $\\Gamma_C$ (y = 0) [m]")
    for ax in (ax_x, ax_y):
        ax.grid(alpha=0.3)
        ax.axhline(0, color="0.5", lw=0.6)
        ax.legend(fontsize=8, loc="best")
    ax_x.set_title(f"Figure 3. Velocity on $\\Gamma_C$ at {time_label(final_time(out, 'conductive'))}"
                   " (circles: nodes in slip)", fontsize=11)
    fig.tight_layout()
    return save(fig, figdir, "figure3_contact_velocity.png")


def figure4(out, figdir):
    m = read_mesh(out, "conductive")
    s = amplification(m)
    tri = deformed_triangulation(m, s)
    fig, (ax_p, ax_s) = plt.subplots(2, 1, figsize=(9, 6.8))
    pc = ax_p.tripcolor(tri, m["phi"], shading="gouraud", cmap="viridis")
    fig.colorbar(pc, ax=ax_p, label="electric potential φ [V]")
    ax_p.set_title("(a) electric potential [V]", fontsize=10)
    vm = m["von_mises"]
    positive = vm[vm > 0]
    log = positive.size > 0 and vm.max() > 100 * np.median(positive)  # a stress peak would hide the rest
    norm = LogNorm(vmin=positive.min(), vmax=vm.max()) if log else None
    sc = ax_s.tripcolor(tri, facecolors=np.maximum(vm, positive.min()) if log else vm,
                        cmap="inferno", norm=norm, edgecolors="none")
    fig.colorbar(sc, ax=ax_s, label="von Mises stress [Pa]" + (" (log scale)" if log else ""))
    ax_s.set_title("(b) von Mises stress norm [Pa], one value per cell", fontsize=10)
    for ax in (ax_p, ax_s):
        finish_mesh_axes(ax)
    fig.suptitle(f"Figure 4. Conductive foundation at {time_label(final_time(out, 'conductive'))},\n"
                 f"on the deformed mesh (displacement × {sci(s)})", fontsize=11)
    fig.tight_layout()
    return save(fig, figdir, "figure4_potential_von_mises.png")


def figure5(out, figdir):
    path = os.path.join(out, "sweep_phi_f.csv")
    if not os.path.isfile(path):
        raise MissingInput(f"no {path}: the run did not sweep phi_f (the scene's output.phi_f_sweep); "
                           f"{RUN_HINT}")
    d = np.sort(read_csv(path, ("phi_f", "max_abs_ux", "max_abs_uy")), order="phi_f")
    fig, ax = plt.subplots(figsize=(9, 5.5))
    ax.plot(d["phi_f"], 1e6 * d["max_abs_ux"], "o-", color="tab:blue", label="max |$u_x$|")
    ax.plot(d["phi_f"], 1e6 * d["max_abs_uy"], "s-", color="tab:red", label="max |$u_y$|")
    for (v, note), style in zip(PAPER_PHI_F, ("--", ":")):
        ax.axvline(v, color="0.3", ls=style, lw=1.2, label=f"$\\varphi_f$ = {v:g} V ({note})")
    ax.set_xlabel("foundation potential $\\varphi_f$ [V]")
    ax.set_ylabel("displacement [µm]")
    ax.set_title("Figure 5. Displacement against the foundation voltage (conductive foundation)", fontsize=11)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, frameon=False)
    fig.tight_layout()
    return save(fig, figdir, "figure5_displacement_vs_voltage.png")


def save(fig, figdir, name):
    path = os.path.join(figdir, name)
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path


# ----------------------------------------------------------------------------------------- main
def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__, file=sys.stderr)
        return 2
    out = argv[1]
    if not os.path.isdir(out):
        print(f"error: no directory {out} ({RUN_HINT})", file=sys.stderr)
        return 1
    for f in FOUNDATIONS:
        if not os.path.isdir(os.path.join(out, f)):
            print(f"warning: no directory {os.path.join(out, f)}: figures that need it are skipped",
                  file=sys.stderr)
    figdir = os.path.join(out, "figures")
    os.makedirs(figdir, exist_ok=True)
    written = 0
    for number, make in ((2, figure2), (3, figure3), (4, figure4), (5, figure5)):
        try:
            print("wrote", make(out, figdir))
            written += 1
        except MissingInput as e:
            print(f"skipping figure {number}: {e}", file=sys.stderr)
            plt.close("all")
    if not written:
        print("error: no figure written", file=sys.stderr)
    return 0 if written else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
