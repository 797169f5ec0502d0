#!/usr/bin/env python3
"""plot_horizon_series.py SERIES.json OUT.png — the diagnostics of `conformesh horizons` against time.

Panels: area and irreducible mass, spin from C_polar/C_eq, the equatorial and polar circumferences, and e_G (the
mean curvature-measure error, when the run checked it). Rows whose status is not ok, or without a time, are left out
(the table has them). Needs matplotlib only. docs/horizons.md §5c.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def column(rows, key):
    return [r["time"] for r in rows if r.get(key) is not None], [r[key] for r in rows if r.get(key) is not None]


def main(argv):
    if len(argv) != 3:
        sys.exit("usage: plot_horizon_series.py SERIES.json OUT.png")
    with open(argv[1]) as f:
        rows = [r for r in json.load(f)["rows"] if r["status"] == "ok" and r["time"] is not None]
    fig, ax = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    t, a = column(rows, "area")
    ax[0][0].plot(t, a, "o-", label="area A")
    ax[0][0].set_ylabel("area")
    twin = ax[0][0].twinx()
    t, m = column(rows, "irreducible_mass")
    twin.plot(t, m, "s--", color="C1", label="M_irr = sqrt(A/16 pi)")
    twin.set_ylabel("M_irr")
    ax[0][0].legend(loc="upper left", fontsize=8)
    twin.legend(loc="upper right", fontsize=8)
    t, s = column(rows, "spin")
    ax[0][1].plot(t, s, "o-", color="C2")
    ax[0][1].set_ylabel("spin from C_pol / C_eq")
    for key, style in (("equatorial_circumference", "o-"), ("polar_circumference", "s-")):
        t, c = column(rows, key)
        ax[1][0].plot(t, c, style, label=key.replace("_", " "))
    ax[1][0].set_ylabel("circumference")
    ax[1][0].legend(fontsize=8)
    t, e = column(rows, "e_G")
    if e:
        ax[1][1].semilogy(t, e, "o-", color="C3")
    else:
        ax[1][1].text(0.5, 0.5, "no curvature check (--no-check)", ha="center", transform=ax[1][1].transAxes)
    ax[1][1].set_ylabel("e_G")
    for a_ in (ax[1][0], ax[1][1]):
        a_.set_xlabel("time")
    fig.suptitle("conformesh horizons: %d of the steps ok" % len(rows))
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)


if __name__ == "__main__":
    main(sys.argv)
