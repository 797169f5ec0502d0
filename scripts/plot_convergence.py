#!/usr/bin/env python3
"""Plots of a `conformesh convergence` study, after the paper's Figs. 10-12 (Li et al., TVCG 2013).

usage: plot_convergence.py STUDY.json PREFIX
writes PREFIX_fig10.png (a: max circumradius, b: mean circumradius, c: min angle, d: mean min angle, against
vertices), PREFIX_fig11.png (a: e_G against vertices, c: e_G against mean circumradius, log-log with the fitted
slope), PREFIX_fig12.png (histogram of relative Gaussian-curvature-measure errors on the finest mesh) and, when the
metric has an embedding (levels carry "extrinsic"), PREFIX_fig13.png (e_H, Hausdorff distance and normal deviation
against mean circumradius, log-log with fitted slopes; histogram of relative mean-curvature-measure errors).
"""
import json
import sys


def _missing_module(error):
    """Exits naming the missing module and the Debian package that provides it (status 1, message on stderr)."""
    import os
    module = (error.name or "?").split(".")[0]
    package = {"numpy": "python3-numpy", "matplotlib": "python3-matplotlib",
               "mpl_toolkits": "python3-matplotlib"}.get(module, "python3-" + module)
    sys.exit(f"{os.path.basename(sys.argv[0])}: error: no Python module '{module}' for {sys.executable}: install "
             f"Debian's {package} (apt-get install {package}) and run this script with /usr/bin/python3, the "
             f"interpreter CMake configures (CONFORMESH_PYTHON)")


try:
    import numpy as np
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ModuleNotFoundError as missing:
    _missing_module(missing)


def slope(x, y):
    return np.polyfit(np.log(x), np.log(y), 1)[0]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    study = json.load(open(sys.argv[1]))
    prefix = sys.argv[2]
    levels = study["levels"]
    v = np.array([L["vertices"] for L in levels], float)
    rmax = np.array([L["quality"]["max_circumradius"] for L in levels])
    rmean = np.array([L["quality"]["mean_circumradius"] for L in levels])
    amin = np.array([L["quality"]["min_angle_deg"] for L in levels])
    amean = np.array([L["quality"]["mean_min_angle_deg"] for L in levels])
    eg = np.array([L["gaussian_curvature_measure"]["mean_abs_error"] for L in levels])
    title = study["metric"]

    fig, ax = plt.subplots(1, 4, figsize=(16, 3.8))
    for a, y, name in zip(ax, (rmax, rmean, amin, amean),
                          ("max circumradius", "mean circumradius", "min angle (deg)", "mean min angle (deg)")):
        a.plot(v, y, "o-")
        a.set_xlabel("vertices")
        a.set_ylabel(name)
        a.grid(alpha=0.3)
    ax[1].set_xscale("log")
    ax[1].set_yscale("log")
    ax[1].set_title("slope %.3f (expected -1/2)" % slope(v, rmean))
    ax[2].axhline(20.7, color="r", lw=0.8, ls="--", label="20.7 deg (Ruppert)")
    ax[2].legend()
    fig.suptitle(title + ": Fig. 10 (a-d)")
    fig.tight_layout()
    fig.savefig(prefix + "_fig10.png", dpi=120)

    fig, ax = plt.subplots(1, 2, figsize=(9, 3.8))
    ax[0].plot(v, eg, "o-")
    ax[0].set_xlabel("vertices")
    ax[0].set_ylabel("e_G")
    ax[0].set_title("(a) e_G against vertices")
    ax[0].grid(alpha=0.3)
    ax[1].loglog(rmean, eg, "o-")
    s = slope(rmean, eg)
    ax[1].set_xlabel("mean circumradius")
    ax[1].set_ylabel("e_G")
    ax[1].set_title("(c) fitted slope %.3f (Theorem 3.4: >= 1)" % s)
    ax[1].grid(alpha=0.3, which="both")
    fig.suptitle(title + ": Fig. 11")
    fig.tight_layout()
    fig.savefig(prefix + "_fig11.png", dpi=120)

    rel = np.array(study.get("finest_relative_errors", []))
    fin = levels[-1]["gaussian_curvature_measure"]
    band = fin["within_band"]
    rng = fin["histogram_range"]
    fig, ax = plt.subplots(figsize=(6, 3.8))
    ax.hist(np.clip(rel, -rng, rng), bins=fin["histogram"].__len__(), range=(-rng, rng))
    ax.axvspan(-band, band, color="g", alpha=0.1)
    ax.set_xlabel("relative error of the Gaussian curvature measure")
    ax.set_ylabel("vertices")
    ax.set_title("%d vertices: %.1f %% within +-%.2f" % (levels[-1]["vertices"], 100 * fin["fraction_within"], band))
    fig.suptitle(title + ": Fig. 12")
    fig.tight_layout()
    fig.savefig(prefix + "_fig12.png", dpi=120)

    if all("extrinsic" in L for L in levels):
        ext = [L["extrinsic"] for L in levels]
        fig, ax = plt.subplots(1, 4, figsize=(17, 3.8))
        for a, key, name, expected in zip(ax, ("e_H", "hausdorff", "normal_deviation"),
                                          ("e_H", "Hausdorff distance", "max normal deviation (rad)"),
                                          (">= 1", "2", "1")):
            y = np.array([e[key] for e in ext])
            a.loglog(rmean, y, "o-")
            a.set_xlabel("mean circumradius")
            a.set_ylabel(name)
            a.set_title("slope %.3f (expected %s)" % (slope(rmean, y), expected))
            a.grid(alpha=0.3, which="both")
        relh = np.array(study.get("finest_mean_curvature_relative_errors", []))
        fin = ext[-1]
        rng = fin["histogram_range"]
        ax[3].hist(np.clip(relh, -rng, rng), bins=len(fin["histogram"]), range=(-rng, rng))
        ax[3].axvspan(-fin["within_band"], fin["within_band"], color="g", alpha=0.1)
        ax[3].set_xlabel("relative error of the mean curvature measure")
        ax[3].set_title("%.1f %% within +-%.2f" % (100 * fin["fraction_within"], fin["within_band"]))
        fig.suptitle(title + ": extrinsic checks (eq. 2, Lemmas 4.8-4.9)")
        fig.tight_layout()
        fig.savefig(prefix + "_fig13.png", dpi=120)


if __name__ == "__main__":
    main()
