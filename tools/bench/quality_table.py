#!/usr/bin/env python3
"""Quality table (docs/user/results.md): synthetic scenes with ground truth at two noise
conditions, several seeds, default options (or the options given after --), and the figures
without ground truth of every run.

For every (scene, condition, seed): `linesurf synth`, `linesurf reconstruct --report`,
`linesurf evaluate RESULT GT --visible-from LINES --json`. Prints one Markdown row per (scene,
condition) with the mean and the minimum of precision and completeness at 5 cm, how many runs
were closed / 2-manifold / free of self-intersection, the mean eps, data fit, visibility
consistency and fragments, and the mean wall time; appends one JSON line per run to --output.
With --andalusian PATH, also Andalusian with default options and with its given planes (the
figures without ground truth only).

Usage: tools/bench/quality_table.py [--linesurf build/bin/linesurf] [--workdir /tmp/qt]
         [--scenes house,lshape,room,city-4] [--seeds 1-5] [--conditions a,b]
         [--output runs.jsonl] [--andalusian PATH] [-- extra reconstruct options]
       tools/bench/quality_table.py --compare NAME=RUNS.jsonl ... [--seeds 1-2] [--scenes a,b]
         (sensitivity: one row per file, over the runs of the given seeds)
Exit status: 0, 1 when a run failed, 2 on bad usage. Python 3 standard library only.
"""

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SCENES = {
    "house": ["house"],
    "lshape": ["lshape"],
    "room": ["room"],
    "floor": ["floor"],
    "city-4": ["city", "--size", "4"],
}
CONDITIONS = {
    "a": ["--noise", "0.01", "--outliers", "0.05"],
    "b": ["--noise", "0.02", "--outliers", "0.07", "--residual-split"],
}
CONDITION_NAMES = {"a": "1 cm / 5 %", "b": "2 cm / 7 %, split"}
THRESHOLD = 0.05


def run(command, log_path):
    start = time.monotonic()
    with open(log_path, "w") as log:
        code = subprocess.call(command, stdout=log, stderr=subprocess.STDOUT)
    return code, time.monotonic() - start


def seeds_of(text):
    if "-" in text:
        lo, hi = text.split("-")
        return list(range(int(lo), int(hi) + 1))
    return [int(s) for s in text.split(",")]


def one_run(args, scene, condition, seed, extra):
    directory = Path(args.workdir) / f"{scene}-{condition}-{seed}"
    directory.mkdir(parents=True, exist_ok=True)
    synth = [args.linesurf, "synth", *SCENES[scene], "--seed", str(seed), *CONDITIONS[condition],
             "-o", str(directory)]
    code, _ = run(synth, directory / "synth.log")
    if code != 0:
        return {"scene": scene, "condition": condition, "seed": seed, "error": "synth failed"}
    mesh = directory / "result.ply"
    report = directory / "report.json"
    command = [args.linesurf, "reconstruct", str(directory / "lines.json"), "-o", str(mesh),
               "--report", str(report), *extra]
    code, seconds = run(command, directory / "reconstruct.log")
    if code != 0:
        return {"scene": scene, "condition": condition, "seed": seed, "error": "reconstruct failed",
                "log": str(directory / "reconstruct.log")}
    evaluation = directory / "evaluation.json"
    code, _ = run([args.linesurf, "evaluate", str(mesh), str(directory / "ground_truth.ply"),
                   "--visible-from", str(directory / "lines.json"), "--thresholds",
                   str(THRESHOLD), "--json", str(evaluation)], directory / "evaluate.log")
    if code != 0:
        return {"scene": scene, "condition": condition, "seed": seed, "error": "evaluate failed"}
    r = json.load(open(report))
    e = json.load(open(evaluation))
    q = r.get("quality", {})
    return {"scene": scene, "condition": condition, "seed": seed, "options": extra,
            "seconds": seconds, "planes": r["counts"]["planes"], "epsilon": r["epsilon"]["epsilon"],
            "precision": e["precision"][0], "completeness": e["completeness"][0],
            "closed": e["topology"]["closed"], "two_manifold": e["topology"]["two_manifold"],
            "self_intersecting": e["topology"]["self_intersecting"],
            "data_fit": q.get("data_fit"), "visibility": q.get("visibility_consistency"),
            "components": q.get("num_components"), "fragments": q.get("floating_fragments")}


def row(scene, condition, runs):
    good = [r for r in runs if "error" not in r]
    if not good:
        return f"| {scene} | {CONDITION_NAMES[condition]} | all {len(runs)} runs failed |"
    pct = lambda xs: 100.0 * statistics.mean(xs)
    p = [r["precision"] for r in good]
    c = [r["completeness"] for r in good]
    ok = sum(r["closed"] and r["two_manifold"] and not r["self_intersecting"] for r in good)
    return (f"| {scene} | {CONDITION_NAMES[condition]} | {len(good)}/{len(runs)} | "
            f"{pct(p):.1f} (min {100 * min(p):.1f}) | {pct(c):.1f} (min {100 * min(c):.1f}) | "
            f"{ok}/{len(good)} | {statistics.mean(r['epsilon'] for r in good):.3g} | "
            f"{pct([r['data_fit'] for r in good]):.1f} | {pct([r['visibility'] for r in good]):.1f} | "
            f"{statistics.mean(r['fragments'] for r in good):.1f} | "
            f"{statistics.mean(r['seconds'] for r in good):.1f} |")


def andalusian(args, extra):
    lines = []
    for name, options in (("defaults", []), ("given planes", ["--planes", "given"])):
        directory = Path(args.workdir) / f"andalusian-{name.replace(' ', '-')}"
        directory.mkdir(parents=True, exist_ok=True)
        mesh, report = directory / "result.ply", directory / "report.json"
        code, seconds = run([args.linesurf, "reconstruct", args.andalusian, "-o", str(mesh),
                             "--report", str(report), *options, *extra],
                            directory / "reconstruct.log")
        if code != 0:
            lines.append(f"| {name} | failed (exit {code}, {directory / 'reconstruct.log'}) |")
            continue
        r = json.load(open(report))
        q = r["quality"]
        lines.append(f"| {name} | {r['counts']['planes']} | {r['epsilon']['epsilon']:.4g} "
                     f"({r['epsilon']['source']}) | {q['num_components']} | "
                     f"{100 * q['largest_component_share']:.1f} | {q['floating_fragments']} | "
                     f"{100 * q['data_fit']:.1f} | {100 * q['visibility_consistency']:.1f} | "
                     f"{r['mesh']['closed'] and r['mesh']['manifold']} | {seconds:.0f} |")
    print("\n| Andalusian | planes | eps | components | largest % of volume | floating | "
          "data fit % | visibility % | closed 2-manifold | s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(lines))


def compare(files, seeds, scenes):
    print("| variant | runs | mean precision % | mean completeness % | lowest of both % | "
          "scene/condition means >= 95 % |")
    print("|---|---|---|---|---|---|")
    for item in files:
        name, path = item.split("=", 1)
        runs = [json.loads(line) for line in open(path)]
        runs = [r for r in runs
                if "error" not in r and r["seed"] in seeds and (not scenes or r["scene"] in scenes)]
        groups = {}
        for r in runs:
            groups.setdefault((r["scene"], r["condition"]), []).append(r)
        good = sum(statistics.mean(r["precision"] for r in g) >= 0.95 and
                   statistics.mean(r["completeness"] for r in g) >= 0.95 for g in groups.values())
        print(f"| {name} | {len(runs)} | {100 * statistics.mean(r['precision'] for r in runs):.1f} | "
              f"{100 * statistics.mean(r['completeness'] for r in runs):.1f} | "
              f"{100 * min(min(r['precision'], r['completeness']) for r in runs):.1f} | "
              f"{good}/{len(groups)} |")


def main():
    argv = sys.argv[1:]
    if argv and argv[0] == "--compare":
        seeds = seeds_of(argv[argv.index("--seeds") + 1]) if "--seeds" in argv else range(1, 1000)
        scenes = argv[argv.index("--scenes") + 1].split(",") if "--scenes" in argv else []
        files = [a for a in argv[1:] if "=" in a]
        compare(files, set(seeds), scenes)
        return 0
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--linesurf", default=str(REPO / "build" / "bin" / "linesurf"))
    parser.add_argument("--workdir", default="/tmp/linesurf-quality")
    parser.add_argument("--scenes", default="house,lshape,room,city-4")
    parser.add_argument("--seeds", default="1-5")
    parser.add_argument("--conditions", default="a,b")
    parser.add_argument("--output", default=None)
    parser.add_argument("--andalusian", default=None)
    args = parser.parse_args(argv)
    scenes = args.scenes.split(",")
    conditions = args.conditions.split(",")
    if any(s not in SCENES for s in scenes) or any(c not in CONDITIONS for c in conditions):
        parser.error(f"scenes among {list(SCENES)}, conditions among {list(CONDITIONS)}")
    print(f"options: {' '.join(extra) if extra else '(defaults)'}")
    print("\n| scene | condition | runs | precision % at 5 cm | completeness % at 5 cm | "
          "closed, 2-manifold, no self-intersection | eps | data fit % | visibility % | "
          "fragments | s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    failed = False
    for scene in scenes:
        for condition in conditions:
            runs = [one_run(args, scene, condition, seed, extra) for seed in seeds_of(args.seeds)]
            failed = failed or any("error" in r for r in runs)
            if args.output:
                with open(args.output, "a") as out:
                    for r in runs:
                        out.write(json.dumps(r) + "\n")
            print(row(scene, condition, runs), flush=True)
    if args.andalusian:
        andalusian(args, extra)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
