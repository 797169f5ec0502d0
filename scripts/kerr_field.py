#!/usr/bin/env python3
"""kerr_field.py — writes the intrinsic metric of a Kerr horizon (M = 1) sampled on a grid, in conformesh's sampled
metric-field format (docs/metrics.md §4), from the closed form and independently of the C++ code:

    r+ = M + sqrt(M^2 - a^2),  rho^2 = r+^2 + a^2 cos^2(theta),
    g_phiphi = (r+^2 + a^2)^2 sin^2(theta) / rho^2,  g_thetatheta = rho^2,  u = phi, v = theta.

Usage: python3 scripts/kerr_field.py [--a 0.95] [--nu 128] [--nv 64] -o kerr095.txt
Then:  conformesh convergence --field kerr095.txt   (the sampled-field study, docs/studies.md)
"""
import argparse
import math


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--a", type=float, default=0.95, help="spin a/M, 0 <= a < 1 (default 0.95)")
    p.add_argument("--nu", type=int, default=128, help="samples in phi (even; default 128)")
    p.add_argument("--nv", type=int, default=64, help="samples in theta, cell-centred (default 64)")
    p.add_argument("-o", "--output", required=True)
    args = p.parse_args()
    a, M = args.a, 1.0
    if not (0 <= a < 1) or args.nu % 2 or args.nu < 4 or args.nv < 4:
        raise SystemExit("kerr_field.py: need 0 <= a < 1, an even nu >= 4 and nv >= 4")
    rp = M + math.sqrt(M * M - a * a)
    lines = [
        "conformesh-metric-field 1",
        f"# Kerr horizon, M = 1, a = {a!r}: u = phi, v = theta (scripts/kerr_field.py)",
        f"chart 0 {2 * math.pi!r} 0 {math.pi!r}",
        f"grid {args.nu} {args.nv}",
        "periodic_u yes",
        "periodic_v no",
        "poles both",
        "fields g_uu g_uv g_vv",
        "data",
    ]
    for j in range(args.nv):
        theta = (j + 0.5) * math.pi / args.nv  # cell-centred: no sample on a pole
        rho2 = rp * rp + a * a * math.cos(theta) ** 2
        guu = (rp * rp + a * a) ** 2 * math.sin(theta) ** 2 / rho2
        for _ in range(args.nu):  # the metric does not depend on phi
            lines.append(f"{guu!r} 0 {rho2!r}")
    with open(args.output, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
