"""Draw docs/images/contact_cfd_split.png: where kegel's contact model ends and its CFD begins.

    .venv/bin/python docs/images/contact_cfd_split.py

A schematic, not to scale (g is drawn at 0.15 R; kegel's default is 0.08 D_w = 0.16 R): a roller
section on its raceway. The contact model owns the film thinner than g (Biboulet-Houpert's
rolling force with the inlet meniscus where the real film reaches g); the CFD owns the oil
beyond, with the raceway set back by g along its normal so that its narrowest film is g.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

OUT = Path(__file__).with_suffix(".png")


def main() -> None:
    R, g = 1.0, 0.15
    x_g = float(np.sqrt(2 * R * g - g * g))  # real film h(x) = R - sqrt(R^2 - x^2) reaches g
    fig, ax = plt.subplots(figsize=(8.0, 4.0))
    th = np.linspace(0, 2 * np.pi, 400)
    ax.fill(R * np.cos(th), R + R * np.sin(th), color="0.85", ec="k", lw=1.2, zorder=3)
    ax.text(0, R, "roller\n(real diameter)", ha="center", va="center", fontsize=9, zorder=4)
    x = np.linspace(-1.6, 1.6, 2)
    ax.plot(x, [0, 0], "k-", lw=1.5)
    ax.text(1.62, 0.0, "real raceway", va="center", fontsize=8)
    ax.plot(x, [-g, -g], "C0--", lw=1.5)
    ax.text(1.62, -g, "CFD raceway,\nset back by g", va="center", fontsize=8, color="C0")
    # the contact model's zone: real film below g
    xs = np.linspace(-x_g, x_g, 100)
    ax.fill_between(xs, 0, R - np.sqrt(R * R - xs * xs), color="C3", alpha=0.6, zorder=2)
    ax.annotate("contact model: film < g\n(Biboulet-Houpert,\nless Reynolds'\nfar field beyond g)", xy=(0.0, 0.04),
                xytext=(-2.35, 0.6), fontsize=8, color="C3", arrowprops=dict(arrowstyle="->", color="C3"))
    # the CFD's oil: between roller and set-back raceway
    xo = np.linspace(-1.6, 1.6, 300)
    top = np.where(np.abs(xo) < R, R - np.sqrt(np.clip(R * R - xo * xo, 0, None)), 0.9)
    ax.fill_between(xo, -g, np.minimum(top, 0.9), color="C0", alpha=0.15, zorder=1)
    ax.annotate("CFD: oil beyond, narrowest film g\n(n cells across it)", xy=(1.0, 0.3), xytext=(0.65, 1.75),
                fontsize=8, color="C0", arrowprops=dict(arrowstyle="->", color="C0"))
    ax.annotate("", xy=(0.0, -g), xytext=(0.0, 0.0), arrowprops=dict(arrowstyle="<->", color="k"))
    ax.text(0.04, -g / 2, "g", fontsize=10, va="center")
    ax.annotate("", xy=(-x_g, -0.32), xytext=(x_g, -0.32), arrowprops=dict(arrowstyle="<->", color="C3"))
    ax.text(0, -0.4, r"$2\sqrt{2Rg}$", ha="center", va="top", fontsize=9, color="C3")
    ax.set_title("The contact / CFD boundary at a raceway line contact (not to scale)", fontsize=10)
    ax.set_xlim(-2.4, 2.2)
    ax.set_ylim(-0.6, 2.1)
    ax.set_aspect("equal")
    ax.axis("off")
    fig.tight_layout()
    fig.savefig(OUT, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
