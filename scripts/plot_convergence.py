#!/usr/bin/env python3
"""Plots of a `conformesh convergence` study, after the paper's Figs. 10-12 (Li et al., TVCG 2013).

usage: plot_convergence.py STUDY.json PREFIX
writes PREFIX_fig10.png (a: max circumradius, b: mean circumradius, log-log with the reference slope -1/2, c: min
angle, d: mean min angle, against vertices), PREFIX_fig11.png (a: e_G against vertices, b: e_G against mean
circumradius, log-log with the fitted slope and the reference slope 1 of Theorem 3.4), PREFIX_fig12.png (histogram of relative Gaussian-curvature-measure errors on the finest mesh) and, when the
metric has an embedding (levels carry "extrinsic"), PREFIX_fig13.png (e_H, Hausdorff distance and normal deviation
against mean circumradius, log-log with fitted and reference slopes; histogram of relative mean-curvature-measure errors).
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
    import matplotlib.ticker
except ModuleNotFoundError as missing:
    _missing_module(missing)


def slope(x, y):
    return np.polyfit(np.log(x), np.log(y), 1)[0]


def log_axis(axis):
    """Log scale with few, plain labels (1, 2, 5 per decade over a short range, decades over a long one) and no minor
    labels, so that tick labels never overlap (matplotlib's default labels every minor tick of a short log range)."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter
    axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0), numticks=8))
    axis.set_major_formatter(FuncFormatter(lambda x, _: "%g" % x))
    axis.set_minor_formatter(NullFormatter())


def loglog_with_reference(ax, x, y, order, what):
    """Data, its least-squares slope and a dashed reference line of slope `order` through the data's geometric mean."""
    fitted = slope(x, y)
    ax.plot(x, y, "o-", label="measured (fitted slope %.2f)" % fitted)
    x0, y0 = np.exp(np.log(x).mean()), np.exp(np.log(y).mean())
    xs = np.array([x.min(), x.max()])
    ax.plot(xs, y0 * (xs / x0) ** order, "k--", lw=0.9, label="reference slope %s (%s)" % (_fraction(order), what))
    ax.set_xscale("log")
    ax.set_yscale("log")
    log_axis(ax.xaxis)
    log_axis(ax.yaxis)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    return fitted


def _fraction(order):
    return {-0.5: "-1/2", 0.5: "1/2"}.get(order, "%g" % order)


def label(ax, letter, text):
    ax.set_title("(%s) %s" % (letter, text), fontsize=10)


def figure10(prefix, title, v, rmax, rmean, amin, amean):
    fig, ax = plt.subplots(1, 4, figsize=(16, 4))
    ax[0].plot(v, rmax, "o-", label="max circumradius")
    ax[0].set_ylabel("max circumradius")
    label(ax[0], "a", "max circumradius")
    loglog_with_reference(ax[1], v, rmean, -0.5, "uniform density")
    ax[1].set_ylabel("mean circumradius")
    label(ax[1], "b", "mean circumradius (log-log)")
    ax[2].plot(v, amin, "o-", label="smallest angle")
    ax[2].axhline(20.7, color="r", lw=0.8, ls="--", label="20.7 deg (B = sqrt 2 bound)")
    ax[2].set_ylabel("min angle (deg)")
    label(ax[2], "c", "smallest angle")
    ax[3].plot(v, amean, "o-", label="mean per-triangle smallest angle")
    ax[3].set_ylabel("mean min angle (deg)")
    label(ax[3], "d", "mean smallest angle")
    for a in ax:
        a.set_xlabel("vertices")
        a.grid(alpha=0.3, which="both")
        a.legend(fontsize=8)
    for a in (ax[0], ax[2], ax[3]):
        a.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(5))
    fig.suptitle(title + ": Fig. 10 — sizes and angles in the original metric")
    fig.tight_layout()
    fig.savefig(prefix + "_fig10.png", dpi=120)


def figure11(prefix, title, v, rmean, eg):
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(v, eg, "o-", label="e_G")
    ax[0].set_xlabel("vertices")
    ax[0].set_ylabel("e_G")
    ax[0].xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(5))
    ax[0].grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    label(ax[0], "a", "e_G against vertices")
    loglog_with_reference(ax[1], rmean, eg, 1, "Theorem 3.4: order >= 1")
    ax[1].set_xlabel("mean circumradius")
    ax[1].set_ylabel("e_G")
    label(ax[1], "b", "e_G against mean circumradius (log-log)")
    fig.suptitle(title + ": Fig. 11 — Gaussian curvature measure error e_G (paper eq. 5)")
    fig.tight_layout()
    fig.savefig(prefix + "_fig11.png", dpi=120)


def histogram(ax, rel, fin, what):
    rng, band = fin["histogram_range"], fin["within_band"]
    ax.hist(np.clip(rel, -rng, rng), bins=len(fin["histogram"]), range=(-rng, rng), label="vertices")
    ax.axvspan(-band, band, color="g", alpha=0.1, label="within +-%.2f: %.1f %%" % (band, 100 * fin["fraction_within"]))
    ax.set_xlabel("relative error of the %s measure (end bins: beyond +-%g)" % (what, rng))
    ax.set_ylabel("vertices")
    ax.legend(fontsize=8, loc="best")


def figure12(prefix, title, study, levels):
    fig, ax = plt.subplots(figsize=(6.5, 4))
    histogram(ax, np.array(study.get("finest_relative_errors", [])), levels[-1]["gaussian_curvature_measure"],
              "Gaussian curvature")
    ax.set_title("finest mesh, %d vertices" % levels[-1]["vertices"], fontsize=10)
    fig.suptitle(title + ": Fig. 12 — relative errors per vertex ball")
    fig.tight_layout()
    fig.savefig(prefix + "_fig12.png", dpi=120)


def figure13(prefix, title, study, levels, rmean):
    ext = [L["extrinsic"] for L in levels]
    fig, ax = plt.subplots(1, 4, figsize=(17, 4))
    for a, letter, key, name, order, why in zip(
            ax, "abc", ("e_H", "hausdorff", "normal_deviation"),
            ("e_H", "Hausdorff distance", "max normal deviation (rad)"), (1, 2, 1),
            ("eq. 2: order >= 1", "Lemma 4.8", "Lemma 4.9")):
        loglog_with_reference(a, rmean, np.array([e[key] for e in ext]), order, why)
        a.set_xlabel("mean circumradius")
        a.set_ylabel(name)
        label(a, letter, name + " (log-log)")
    histogram(ax[3], np.array(study.get("finest_mean_curvature_relative_errors", [])), ext[-1], "mean curvature")
    label(ax[3], "d", "finest mesh, %d vertices" % levels[-1]["vertices"])
    fig.suptitle(title + ": Fig. 13 — extrinsic checks in the embedding (eq. 2, Lemmas 4.8-4.9)")
    fig.tight_layout()
    fig.savefig(prefix + "_fig13.png", dpi=120)


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
    figure10(prefix, title, v, rmax, rmean, amin, amean)
    figure11(prefix, title, v, rmean, eg)
    figure12(prefix, title, study, levels)
    if all("extrinsic" in L for L in levels):
        figure13(prefix, title, study, levels, rmean)


if __name__ == "__main__":
    main()
