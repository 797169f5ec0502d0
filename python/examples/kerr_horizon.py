"""A Kerr horizon 2-metric built in NumPy on a theta-phi grid, remeshed by conformesh.

Prints the area against the closed form 8 pi M r+ and the Gaussian-curvature-measure error e_G, and draws the
relative error per vertex with matplotlib (kerr_horizon.png) when matplotlib is installed.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/kerr_horizon.py [a/M] [eps]
"""

import math
import sys

import numpy as np

import conformesh
from conformesh import metrics


def horizon_metric(a, M=1.0, nu=128, nv=96):
    """g on the horizon r = r+ of Kerr in Boyer-Lindquist coordinates: u = phi, v = theta."""
    rp = M + math.sqrt(M * M - a * a)
    phi, theta = metrics.grid((0, 2 * math.pi, 0, math.pi), (nu, nv), poles="both")
    rho2 = rp * rp + (a * np.cos(theta)) ** 2
    g_phiphi = (rp * rp + a * a) ** 2 * np.sin(theta) ** 2 / rho2
    metric = metrics.sampled(g_phiphi, np.zeros_like(theta), rho2, chart=(0, 2 * math.pi, 0, math.pi),
                             periodic_u=True, poles="both")
    return metric, rp


def main():
    a = float(sys.argv[1]) if len(sys.argv) > 1 else 0.95
    eps = float(sys.argv[2]) if len(sys.argv) > 2 else 0.05
    metric, rp = horizon_metric(a)
    result = conformesh.remesh(metric, eps)
    tri = result.triangulation
    exact = 8 * math.pi * rp
    check = result.report["gaussian_curvature_measure"]
    print(f"Kerr a/M = {a}: {tri.num_vertices} vertices, min angle {result.report['quality']['min_angle_deg']:.2f} deg")
    print(f"area {tri.total_area:.10f}, 8 pi M r+ = {exact:.10f}, relative {tri.total_area / exact - 1:.2e}")
    print(f"Gauss-Bonnet: sum of deficits / 4 pi - 1 = {tri.angle_deficits().sum() / (4 * math.pi) - 1:.1e}")
    print(f"e_G = {check['mean_abs_error']:.4e}, {100 * check['fraction_within']:.1f} % within +-5 %")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    uv = result.chart_coordinates
    fig, ax = plt.subplots(figsize=(8, 4))
    sc = ax.tripcolor(uv[:, 0], uv[:, 1], result.fields["relative_error"], shading="gouraud", cmap="coolwarm",
                      vmin=-0.05, vmax=0.05)
    ax.set_xlabel("phi")
    ax.set_ylabel("theta")
    ax.set_title(f"Kerr horizon a/M = {a}: curvature-measure relative error")
    fig.colorbar(sc)
    fig.savefig("kerr_horizon.png", dpi=120)
    print("wrote kerr_horizon.png")


if __name__ == "__main__":
    main()
