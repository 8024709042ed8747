#!/usr/bin/env python3
"""plot_experiment.py REPORT_DIR - the figures of a duel_evolve experiment, drawn from the CSV files beside them.

Called by `duel_evolve experiment` and `experiment report` after they wrote the data (the C side computes every
number; this only draws). matplotlib (Debian's python3-matplotlib), Agg backend: PNG and SVG of each figure,
each written to a temporary file and renamed, with no date or version in the files so that the same data gives the
same bytes.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

plt.rcParams.update({"svg.hashsalt": "neat-duel", "font.size": 10, "axes.titlesize": 11,
                     "figure.dpi": 100, "savefig.dpi": 100})
METADATA = {"png": {"Software": None}, "svg": {"Date": None, "Creator": None}}
REF_COLOR, METHOD_COLOR = "#1f77b4", "#d62728"


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def save(fig, out_dir, name):
    for ext in ("png", "svg"):
        final = os.path.join(out_dir, "%s.%s" % (name, ext))
        tmp = final + ".tmp"
        fig.savefig(tmp, format=ext, metadata=METADATA[ext], bbox_inches="tight")
        os.replace(tmp, final)
    plt.close(fig)


def fig7(d, table):
    data = rows(os.path.join(d, "fig7-complexity.csv"))
    rand = rows(os.path.join(d, "fig7-random.csv"))
    test = {r["measure"]: r for r in rows(os.path.join(d, "fig7-test.csv"))}
    ref = table["reference"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    for ax, key, label, rmin, rmax in ((axes[0], "mean_connections", "connections", "min_connections",
                                        "max_connections"),
                                       (axes[1], "mean_hidden", "hidden nodes", "min_hidden", "max_hidden")):
        g = [int(r["generation"]) for r in data]
        v = [float(r[key]) for r in data]
        ax.plot(g, v, color=REF_COLOR, lw=1.5, marker="|", markersize=9,
                label="current dominant, mean over the %s runs (|: a new level in one of them)" % ref)
        if rand:
            rg = [int(r["generation"]) for r in rand]
            ax.plot(rg, [float(r[rmin]) for r in rand], color="gray", ls="--", lw=1,
                    label="random fitness: smallest in the population")
            ax.plot(rg, [float(r[rmax]) for r in rand], color="black", ls="--", lw=1,
                    label="random fitness: largest in the population")
        t = test["connections" if key == "mean_connections" else "hidden"]
        # two lines: side by side, one-line titles ran into each other at this width
        ax.set_title("%s of the dominants\nfirst %.1f, final %.1f (first vs final: Wilcoxon p = %.2g)"
                     % (label.capitalize(), float(t["first_mean"]), float(t["final_mean"]), float(t["p"])))
        ax.set_xlabel("generation")
        ax.xaxis.get_major_locator().set_params(integer=True)  # no generation 0.25
        ax.set_ylabel("%s (count)" % label)
        ax.grid(alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=9, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=2)
    fig.suptitle("Figure 7: complexification of the dominant networks", fontsize=12)
    fig.tight_layout()
    save(fig, d, "fig7-complexity")


def fig11(d, table):
    data = rows(os.path.join(d, "fig11-levels.csv"))
    fig, ax = plt.subplots(figsize=(6, 4))
    if data:
        x = [int(r["level_difference"]) for r in data]
        y = [float(r["mean_extra_wins"]) for r in data]
        sd = [float(r["sd_extra_wins"]) for r in data]
        ax.errorbar(x, y, yerr=sd, color=REF_COLOR, marker="o", capsize=3, lw=1.5,
                    label="mean (bars: sd) over every %s run" % table["reference"])
        games = data[0]["games"]
        ax.set_ylabel("extra games won of %s (wins - losses)" % games)
        ax.legend(fontsize=9, loc="upper left")
    ax.xaxis.get_major_locator().set_params(integer=True)
    ax.set_xlabel("difference in dominance level (higher level against lower)")
    ax.set_title("Figure 11: what a difference in dominance level means")
    ax.grid(alpha=0.3)
    save(fig, d, "fig11-levels")


def levels(d, table, method):
    data = rows(os.path.join(d, "levels-%s.csv" % method))
    ref = table["reference"]
    series = {"reference": [], "method": []}
    arrow = {}
    for r in data:
        if r["series"] in series:
            series[r["series"]].append(r)
        else:
            arrow[r["series"]] = r
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax2 = ax.twinx()
    for key, color, name, lw in (("reference", REF_COLOR, ref, 3.0), ("method", METHOD_COLOR, method, 1.2)):
        s = series[key]
        if not s:
            continue
        g = [int(r["generation"]) for r in s]
        lv = [int(r["level"]) for r in s]
        # the reference's lines wide and light, the method's narrow on top: both stay visible where they meet
        ax.vlines(g, 0, lv, color=color, lw=lw, alpha=0.55 if key == "reference" else 1.0,
                  label="%s (%s): dominance level" % (name, s[0]["run"]))
        ax2.plot(g, [int(r["connections"]) for r in s], color=color, ls=":", lw=1, marker=".",
                 label="%s: connections of each level" % name)
    if "arrow_from" in arrow and "arrow_to" in arrow:
        a, b = arrow["arrow_from"], arrow["arrow_to"]
        ax.annotate("", xy=(int(b["generation"]), int(b["level"])), xytext=(int(a["generation"]), int(a["level"])),
                    arrowprops={"arrowstyle": "->", "color": "black", "lw": 1.5})
        ax.text(int(b["generation"]), int(b["level"]) + 0.3,
                "equals level %s (generation %s)" % (b["level"], b["generation"]), fontsize=9)
    ax.set_xlabel("generation")
    ax.xaxis.get_major_locator().set_params(integer=True)
    ax.set_ylabel("dominance level (bars)")
    ax2.set_ylabel("connections of the level's network (dots)")
    ax.set_ylim(bottom=0)
    ax.yaxis.get_major_locator().set_params(integer=True)
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=9, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=2)
    ax.set_title("Typical runs: %s against %s (arrow: %s's best in %s's ranking)" % (method, ref, method, ref))
    ax.grid(alpha=0.3)
    save(fig, d, "levels-%s" % method)


def strength(d, table):
    """The runs' absolute strength over their generations (strength.csv: a plan with strength_every): per method,
    the mean over its runs of the generation champion's (wins - losses) / games against forager-hunter and
    against forager, beside Figure 7."""
    path = os.path.join(d, "strength.csv")
    if not os.path.exists(path):
        return
    data = rows(path)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4), sharey=True)
    for ax, opp in zip(axes, ("forager-hunter", "forager")):
        for m in table["methods"]:
            by_gen = {}
            for r in data:
                if r["method"] != m["name"]:
                    continue
                games = sum(int(r[f"{opp}_{k}"]) for k in ("wins", "losses", "draws", "timeouts"))
                margin = (int(r[f"{opp}_wins"]) - int(r[f"{opp}_losses"])) / games
                by_gen.setdefault(int(r["generation"]), []).append(margin)
            if by_gen:
                gens = sorted(by_gen)
                ax.plot(gens, [sum(by_gen[g]) / len(by_gen[g]) for g in gens], marker=".", label=m["name"])
        ax.axhline(0, color="grey", linewidth=0.8)
        ax.set_title(f"the generation champion against {opp}")
        ax.set_xlabel("generation")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("(wins - losses) / 288, mean over runs")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    save(fig, d, "strength")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_experiment.py REPORT_DIR")
    d = sys.argv[1]
    with open(os.path.join(d, "table1.json")) as f:
        table = json.load(f)
    fig7(d, table)
    strength(d, table)
    fig11(d, table)
    for m in table["methods"]:
        if m["name"] != table["reference"]:
            levels(d, table, m["name"])


if __name__ == "__main__":
    main()
