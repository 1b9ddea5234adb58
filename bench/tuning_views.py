"""Per view at `high`: each tuned method's RMSE on each tuning view, from a `tune.json` that
`aokit tune` wrote (bench/tuning.sh puts it under docs/tuning.md's table). The lowest of each
view in bold; the last column is the root of the mean squared error the search minimises.

    python3 bench/tuning_views.py TUNE_JSON
"""

import json
import math
import sys


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        tune = json.load(f)
    views = tune["views"]
    rows = []
    for r in tune["results"]:
        if r["preset"] != "high":
            continue
        name = f"`{r['method']}`" + (" + back faces" if r["back_faces"] else "")
        rmse = r["views_rmse"]
        rows.append((name, rmse, math.sqrt(sum(x * x for x in rmse) / len(rmse))))
    best = [min(row[1][i] for row in rows) for i in range(len(views))]
    scenes = [v.split(" / ")[0] for v in views]
    # A view by its scene, or by its camera where the scene has several.
    labels = [v.split(" / ")[scenes.count(v.split(" / ")[0]) > 1] for v in views]
    print("| method, `high` | " + " | ".join(labels) + " | mean |")
    print("|---|" + "--:|" * (len(views) + 1))
    for name, rmse, mean in rows:
        cells = [f"**{x:.4f}**" if x == b else f"{x:.4f}" for x, b in zip(rmse, best)]
        print(f"| {name} | " + " | ".join(cells) + f" | {mean:.4f} |")


if __name__ == "__main__":
    main()
