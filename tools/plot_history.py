#!/usr/bin/env python3
"""Plots the histories of an fpmshell run.

    python3 tools/plot_history.py RESULTS_DIR

RESULTS_DIR/history.csv -> RESULTS_DIR/history.png (one subplot per column against time) and
RESULTS_DIR/energy.csv -> RESULTS_DIR/energy.png (the energies on one plot, the balance error
on a second); prints the paths of the PNG files written.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fpmv  # noqa: E402


def plot_history(path, out, title):
    data = fpmv.read_csv(path)
    names = [c for c in data if c != "time"]
    if not names:
        return None
    plt = fpmv.pyplot()
    cols = 1 if len(names) <= 3 else 2
    rows = math.ceil(len(names) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(6 * cols, 2.4 * rows + 0.6), squeeze=False,
                             sharex=True)
    t = data.get("time", list(range(len(data[names[0]]))))
    for k, name in enumerate(names):
        ax = axes[k // cols][k % cols]
        ax.plot(t, data[name], lw=1)
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
    for k in range(len(names), rows * cols):
        axes[k // cols][k % cols].set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("time")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return out


def plot_energy(path, out, title):
    data = fpmv.read_csv(path)
    t = data.get("time")
    if not t:
        return None
    plt = fpmv.pyplot()
    has_error = "energy_error" in data
    fig, axes = plt.subplots(2 if has_error else 1, 1, figsize=(7, 6 if has_error else 3.5),
                             squeeze=False, sharex=True)
    ax = axes[0][0]
    for name, values in data.items():
        if name in ("time", "energy_error"):
            continue
        ax.plot(t, values, lw=1, label=name)
    ax.set_ylabel("energy")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    if has_error:
        ax = axes[1][0]
        ax.plot(t, [100 * e for e in data["energy_error"]], lw=1, color="tab:red")
        ax.set_ylabel("energy balance error [%]")
        ax.grid(alpha=0.3)
    axes[-1][0].set_xlabel("time")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", help="fpmshell results folder (history.csv, energy.csv)")
    args = ap.parse_args()
    title = os.path.basename(os.path.normpath(args.results))
    written = []
    for csv_name, png_name, fn in (("history.csv", "history.png", plot_history),
                                   ("energy.csv", "energy.png", plot_energy)):
        path = os.path.join(args.results, csv_name)
        if not os.path.exists(path):
            print("no %s in %s" % (csv_name, args.results), file=sys.stderr)
            continue
        out = fn(path, os.path.join(args.results, png_name), title)
        if out:
            written.append(out)
            print(out)
    return 0 if written else 1


if __name__ == "__main__":
    sys.exit(main())
