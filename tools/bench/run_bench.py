#!/usr/bin/env python3
"""End-to-end benchmark of the linesurf CLI (docs/user/benchmarks.md).

For every scene of a manifest: generate the input with `linesurf synth` (synthetic scenes, from a
seed) or take it from ../shared (real scenes, skipped with a message when absent), run
`linesurf reconstruct ... --report`, then `linesurf evaluate ... --json` against the ground truth
when there is one. Prints a table per scene (per-stage times, peak memory, LP size, quality at
5 cm, mesh checks) and at the end one Markdown table of all scenes (with the time ratios along a
`series`, e.g. cities of 10, 100 and 1,000 buildings, and the speedup of scenes run with several
thread counts: `"threads": [1, 2]` in the manifest reconstructs once per count, in this one run,
and the record keeps the last), appends one JSON line per scene (with git commit and machine) to --output,
and compares with the committed baseline: a scene is flagged when it is more than 10 % slower
(total, or a stage that takes at least --min-stage-seconds) or loses any quality (precision or
completeness at any threshold lower, or a mesh check that held no longer holds).

Exit status: 0 when nothing regressed, 1 on a regression or a failed scene, 2 on bad usage.
Python 3 standard library only.
"""

import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
DEFAULT_MANIFEST = REPO / "tools" / "bench" / "manifest.json"
DEFAULT_BASELINE = REPO / "tools" / "bench" / "baseline.jsonl"
SLOWER_TOLERANCE = 0.10  # a run is a regression when more than 10 % slower than the baseline
QUALITY_TOLERANCE = 1e-9  # shares are deterministic: any drop beyond rounding counts
MESH_CHECKS = ("closed", "two_manifold", "oriented", "outward")


def log(message):
    print(message, file=sys.stderr, flush=True)


def run_timed(command, log_path):
    """Runs command; returns (exit code, wall seconds, peak RSS in MB of that child)."""
    start = time.monotonic()
    with open(log_path, "w") as log_file:
        process = subprocess.Popen(command, stdout=log_file, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(process.pid, 0)
    wall = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    process.returncode = code
    return code, wall, usage.ru_maxrss / 1024.0  # ru_maxrss is in KiB on Linux


def tail(path, lines=8):
    try:
        return "".join(open(path, errors="replace").readlines()[-lines:]).strip()
    except OSError:
        return ""


def git_info():
    def git(*args):
        try:
            return subprocess.run(["git", "-C", str(REPO), *args], capture_output=True, text=True,
                                  check=True).stdout.strip()
        except (OSError, subprocess.CalledProcessError):
            return ""
    return {"commit": git("rev-parse", "HEAD"),
            "dirty": bool(git("status", "--porcelain", "--untracked-files=no"))}


def machine_info():
    info = {"hostname": platform.node(), "system": platform.platform(), "cpus": os.cpu_count(),
            "python": platform.python_version()}
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                info["cpu"] = line.split(":", 1)[1].strip()
                break
        for line in open("/proc/meminfo"):
            if line.startswith("MemTotal"):
                info["memory_gb"] = round(int(line.split()[1]) / 1024 / 1024, 1)
                break
    except OSError:
        pass
    return info


def find_stages(report):
    """Per-stage seconds from a reconstruct report, accepting a dict or a list of pairs/objects."""
    for key in ("stage_seconds", "stages", "timings", "stage_times"):
        value = report.get(key)
        if isinstance(value, dict):
            out = {}
            for name, v in value.items():
                if isinstance(v, (int, float)):
                    out[name] = float(v)
                elif isinstance(v, dict):
                    for sub in ("seconds", "wall_seconds", "time"):
                        if isinstance(v.get(sub), (int, float)):
                            out[name] = float(v[sub])
            if out:
                return out
        if isinstance(value, list):
            out = {}
            for item in value:
                if isinstance(item, (list, tuple)) and len(item) == 2:
                    out[str(item[0])] = float(item[1])
                elif isinstance(item, dict):
                    name = item.get("name", item.get("stage"))
                    seconds = item.get("seconds", item.get("wall_seconds", item.get("time")))
                    if name is not None and isinstance(seconds, (int, float)):
                        out[str(name)] = float(seconds)
            if out:
                return out
    return {}


def find_number(report, *names):
    """First numeric value found under any of the given keys, searching nested objects."""
    stack = [report]
    while stack:
        node = stack.pop(0)
        if isinstance(node, dict):
            for name in names:
                if isinstance(node.get(name), (int, float)) and not isinstance(node.get(name), bool):
                    return node[name]
            stack.extend(v for v in node.values() if isinstance(v, (dict, list)))
        elif isinstance(node, list):
            stack.extend(v for v in node if isinstance(v, (dict, list)))
    return None


def run_scene(scene, args, manifest, workdir, shared):
    name = scene["name"]
    record = {"scene": name, "status": "ok"}
    scene_dir = workdir / name
    scene_dir.mkdir(parents=True, exist_ok=True)
    linesurf = [str(args.linesurf)] + (["-j", str(args.threads)] if args.threads else []) + ["-q"]
    ground_truth = None
    if "synth" in scene:
        spec = scene["synth"]
        command = linesurf + ["synth", spec["family"], "--seed", str(spec.get("seed", 0))]
        for key, flag in (("size", "--size"), ("noise", "--noise"), ("outliers", "--outliers")):
            if key in spec:
                command += [flag, str(spec[key])]
        command += ["-o", str(scene_dir)]
        code, wall, _ = run_timed(command, scene_dir / "synth.log")
        if code != 0:
            return dict(record, status="failed", error="synth exit %d: %s" % (code, tail(scene_dir / "synth.log")))
        record["synth_seconds"] = round(wall, 3)
        input_path = scene_dir / "lines.json"
        ground_truth = scene_dir / "ground_truth.ply"
    else:
        input_path = Path(scene["input"].replace("{shared}", str(shared)))
        if not input_path.exists():
            log("%s: %s is absent, scene skipped" % (name, input_path))
            return dict(record, status="skipped", error="%s absent" % input_path)
        if scene.get("ground_truth"):
            ground_truth = Path(scene["ground_truth"].replace("{shared}", str(shared)))
    record["options"] = scene.get("reconstruct", [])
    mesh_path = scene_dir / "result.ply"
    report_path = scene_dir / "report.json"
    thread_counts = scene.get("threads", [args.threads])
    walls = {}
    for threads in thread_counts:
        runner = [str(args.linesurf)] + (["-j", str(threads)] if threads else []) + ["-q"]
        best = None
        for _ in range(args.repeat):
            command = runner + ["reconstruct", str(input_path), "-o", str(mesh_path),
                                "--report", str(report_path)] + scene.get("reconstruct", [])
            code, wall, rss = run_timed(command, scene_dir / "reconstruct.log")
            if code != 0:
                return dict(record, status="failed",
                            error="reconstruct -j %d exit %d: %s" % (
                                threads, code, tail(scene_dir / "reconstruct.log")))
            if best is None or wall < best[0]:
                best = (wall, rss, json.load(open(report_path)))
        walls[threads] = round(best[0], 3)
    if len(walls) > 1:
        record["wall_seconds_by_threads"] = {str(t): w for t, w in walls.items()}
        first, last = thread_counts[0], thread_counts[-1]
        record["speedup"] = round(walls[first] / walls[last], 3) if walls[last] > 0 else None
    record["series"] = scene.get("series")
    record["series_size"] = scene.get("synth", {}).get("size")
    wall, rss, report = best
    record["wall_seconds"] = round(wall, 3)
    record["peak_rss_mb"] = round(rss, 1)
    reported_peak = find_number(report, "peak_memory_bytes")
    record["reported_peak_mb"] = None if reported_peak is None else round(reported_peak / 2**20, 1)
    record["stages"] = {k: round(v, 3) for k, v in find_stages(report).items()}
    record["lp_variables"] = find_number(report, "lp_variables")
    record["lp_constraints"] = find_number(report, "lp_constraints")
    record["cells"] = find_number(report, "cells", "num_cells")
    record["planes"] = find_number(report, "planes", "num_planes")
    record["segments"] = find_number(report, "segments", "num_segments")

    evaluate = manifest.get("evaluate", {})
    eval_path = scene_dir / "evaluation.json"
    command = linesurf + ["evaluate", str(mesh_path)]
    if ground_truth is not None:
        command += [str(ground_truth), "--samples", str(evaluate.get("samples", 100000)),
                    "--thresholds", ",".join(str(t) for t in evaluate.get("thresholds", [0.02, 0.05, 0.1])),
                    "--json", str(eval_path)]
        if scene.get("visible_from", True):
            command += ["--visible-from", str(input_path)]
    else:
        # No ground truth: evaluate the mesh against itself, for its topology checks only.
        command += [str(mesh_path), "--samples", "1000", "--json", str(eval_path)]
    code, wall, _ = run_timed(command, scene_dir / "evaluate.log")
    if code != 0:
        return dict(record, status="failed", error="evaluate exit %d: %s" % (code, tail(scene_dir / "evaluate.log")))
    evaluation = json.load(open(eval_path))
    record["evaluate_seconds"] = round(wall, 3)
    topology = evaluation["topology"]
    record["mesh"] = {k: topology[k] for k in MESH_CHECKS + ("self_intersecting", "num_faces", "num_components")}
    if ground_truth is not None:
        record["quality"] = {"thresholds": evaluation["thresholds"], "precision": evaluation["precision"],
                             "completeness": evaluation["completeness"],
                             "mean_result_to_gt": evaluation["result_to_gt"]["mean"],
                             "mean_gt_to_result": evaluation["gt_to_result"]["mean"]}

    if args.pictures:
        render = manifest.get("render", {})
        args.pictures.mkdir(parents=True, exist_ok=True)
        command = linesurf + ["render", "--lines", str(input_path), "--mesh", str(mesh_path),
                              "-o", str(args.pictures / (name + ".png")),
                              "--size", render.get("size", "1000x420"),
                              "--view", scene.get("view", render.get("view", "iso"))]
        code, _, _ = run_timed(command, scene_dir / "render.log")
        if code != 0:
            log("%s: render failed: %s" % (name, tail(scene_dir / "render.log")))
    return record


def share_at(quality, which, threshold=0.05):
    if not quality:
        return None
    for t, value in zip(quality["thresholds"], quality[which]):
        if abs(t - threshold) < 1e-12:
            return value
    return None


def fmt(value, spec="%.2f", none="-"):
    return none if value is None else spec % value


def print_table(record, regressions):
    name = record["scene"]
    print("== %s: %s" % (name, record["status"]) + ("" if record["status"] == "ok" else " (%s)" % record.get("error", "")))
    if record["status"] != "ok":
        return
    print("  wall %.2f s   peak RSS %.0f MB   segments %s   planes %s   cells %s   LP %s vars x %s rows" % (
        record["wall_seconds"], record["peak_rss_mb"], fmt(record.get("segments"), "%d"),
        fmt(record.get("planes"), "%d"), fmt(record.get("cells"), "%d"),
        fmt(record.get("lp_variables"), "%d"), fmt(record.get("lp_constraints"), "%d")))
    if record["stages"]:
        print("  stages: " + ", ".join("%s %.2f s" % kv for kv in record["stages"].items()))
    quality = record.get("quality")
    if quality:
        print("  quality at 5 cm: precision %s %%   completeness %s %%" % (
            fmt(100 * share_at(quality, "precision")), fmt(100 * share_at(quality, "completeness"))))
    mesh = record["mesh"]
    print("  mesh: %d faces, %d component(s); closed %s, 2-manifold %s, oriented %s, outward %s, self-intersecting %s" % (
        mesh["num_faces"], mesh["num_components"], *("yes" if mesh[k] else "no" for k in MESH_CHECKS),
        "yes" if mesh["self_intersecting"] else "no"))
    for line in regressions:
        print("  REGRESSION: " + line)


def print_summary(records):
    """One Markdown table of every scene run; along a series, the size and time ratios to the
    previous scene of the series."""
    print("\n| scene | segments | planes | cells | wall s | peak RSS MB | precision 5 cm | completeness 5 cm "
          "| closed / 2-manifold / oriented / self-intersecting | size x | time x | speedup |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    previous = {}
    for r in records:
        if r["status"] != "ok":
            print("| %s | %s |" % (r["scene"], r["status"]) + " |" * 10)
            continue
        size_ratio = time_ratio = None
        series = r.get("series")
        if series and series in previous:
            before = previous[series]
            if before.get("series_size") and r.get("series_size"):
                size_ratio = r["series_size"] / before["series_size"]
            time_ratio = r["wall_seconds"] / before["wall_seconds"]
        if series:
            previous[series] = r
        quality, mesh = r.get("quality"), r["mesh"]
        speedup = r.get("speedup")
        by_threads = r.get("wall_seconds_by_threads")
        print("| %s | %s | %s | %s | %.1f | %.0f | %s | %s | %s | %s | %s | %s |" % (
            r["scene"], fmt(r.get("segments"), "%d"), fmt(r.get("planes"), "%d"),
            fmt(r.get("cells"), "%d"), r["wall_seconds"], r["peak_rss_mb"],
            fmt(None if not quality else 100 * share_at(quality, "precision")),
            fmt(None if not quality else 100 * share_at(quality, "completeness")),
            " / ".join("yes" if mesh[k] else "no" for k in ("closed", "two_manifold", "oriented", "self_intersecting")),
            fmt(size_ratio, "%.0f"), fmt(time_ratio, "%.2f"),
            "-" if speedup is None else "%.2f (%s)" % (
                speedup, ", ".join("-j %s %.1f s" % kv for kv in by_threads.items()))))


def compare(record, base, min_stage_seconds):
    """Regressions of record against the baseline record of the same scene."""
    out = []
    if base is None or base.get("status") != "ok":
        return out
    if record["status"] != "ok":
        return ["scene %s (baseline ran)" % record["status"]]
    if (max(record["wall_seconds"], base["wall_seconds"]) >= min_stage_seconds
            and record["wall_seconds"] > (1 + SLOWER_TOLERANCE) * base["wall_seconds"]):
        out.append("wall %.2f s vs baseline %.2f s (+%.0f %%)" % (
            record["wall_seconds"], base["wall_seconds"], 100 * (record["wall_seconds"] / base["wall_seconds"] - 1)))
    for stage, seconds in record["stages"].items():
        before = base.get("stages", {}).get(stage)
        if before is not None and max(seconds, before) >= min_stage_seconds and seconds > (1 + SLOWER_TOLERANCE) * before:
            out.append("stage %s %.2f s vs baseline %.2f s" % (stage, seconds, before))
    quality, base_quality = record.get("quality"), base.get("quality")
    if base_quality:
        if not quality:
            out.append("no quality numbers (baseline had them)")
        else:
            for which in ("precision", "completeness"):
                for t, now, before in zip(quality["thresholds"], quality[which], base_quality[which]):
                    if now < before - QUALITY_TOLERANCE:
                        out.append("%s at %g: %.4f vs baseline %.4f" % (which, t, now, before))
    for check in MESH_CHECKS:
        if base.get("mesh", {}).get(check) and not record["mesh"].get(check):
            out.append("mesh no longer %s" % check)
    if base.get("mesh", {}).get("self_intersecting") is False and record["mesh"].get("self_intersecting"):
        out.append("mesh now self-intersecting")
    return out


def load_baseline(path):
    baseline = {}
    if path.exists():
        for line in open(path):
            if line.strip():
                record = json.loads(line)
                baseline[record["scene"]] = record  # the last line of a scene wins
    return baseline


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--linesurf", type=Path, default=REPO.parent / "build" / "bin" / "linesurf",
                        help="linesurf executable (default: ../build/bin/linesurf beside the repository)")
    parser.add_argument("--manifest", type=Path, default=DEFAULT_MANIFEST)
    parser.add_argument("--baseline", type=Path, default=DEFAULT_BASELINE)
    parser.add_argument("--output", type=Path, default=Path("bench_results.jsonl"),
                        help="JSON lines file the records are appended to")
    parser.add_argument("--workdir", type=Path, default=Path("bench_work"),
                        help="where generated inputs, meshes and reports go")
    parser.add_argument("--shared", type=Path, default=REPO.parent / "shared")
    parser.add_argument("--scenes", help="comma-separated subset of scene names")
    parser.add_argument("--all", action="store_true", help="also run the scenes marked slow")
    parser.add_argument("--threads", type=int, default=0, help="linesurf -j (0: all cores)")
    parser.add_argument("--repeat", type=int, default=1, help="reconstruct runs per scene; the fastest is kept")
    parser.add_argument("--min-stage-seconds", type=float, default=0.5,
                        help="stages and runs shorter than this are not compared for speed (noise)")
    parser.add_argument("--pictures", type=Path, help="also render input|result PNGs into this directory")
    parser.add_argument("--update-baseline", action="store_true",
                        help="replace the baseline's records of the scenes run with this run's")
    args = parser.parse_args()
    if not args.linesurf.exists():
        parser.error("linesurf executable not found: %s (use --linesurf)" % args.linesurf)
    if args.repeat < 1:
        parser.error("--repeat must be >= 1")
    manifest = json.load(open(args.manifest))
    scenes = manifest["scenes"]
    if args.scenes:
        wanted = args.scenes.split(",")
        unknown = sorted(set(wanted) - {s["name"] for s in scenes})
        if unknown:
            parser.error("unknown scenes: %s" % ", ".join(unknown))
        scenes = [s for s in scenes if s["name"] in wanted]
    elif not args.all:
        for scene in scenes:
            if scene.get("slow"):
                log("%s: marked slow, skipped (use --all or --scenes %s)" % (scene["name"], scene["name"]))
        scenes = [s for s in scenes if not s.get("slow")]
    args.linesurf = args.linesurf.resolve()
    args.workdir.mkdir(parents=True, exist_ok=True)

    common = {"time": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
              "git": git_info(), "machine": machine_info(), "threads": args.threads,
              "manifest": str(args.manifest)}
    baseline = load_baseline(args.baseline)
    records, failed, regressed = [], 0, 0
    start = time.monotonic()
    for scene in scenes:
        log("running %s ..." % scene["name"])
        record = run_scene(scene, args, manifest, args.workdir, args.shared)
        record.update(common)
        regressions = compare(record, baseline.get(record["scene"]), args.min_stage_seconds)
        record["regressions"] = regressions
        print_table(record, regressions)
        sys.stdout.flush()
        failed += record["status"] == "failed"
        regressed += bool(regressions)
        records.append(record)
        with open(args.output, "a") as out:
            out.write(json.dumps(record, sort_keys=True) + "\n")
    print_summary(records)
    print("\n%d scene(s) in %.0f s: %d failed, %d regressed, %d skipped" % (
        len(records), time.monotonic() - start, failed, regressed,
        sum(r["status"] == "skipped" for r in records)))
    if args.update_baseline:
        for record in records:
            if record["status"] == "ok":
                baseline[record["scene"]] = {k: v for k, v in record.items() if k != "regressions"}
        with open(args.baseline, "w") as out:
            for name in sorted(baseline):
                out.write(json.dumps(baseline[name], sort_keys=True) + "\n")
        print("baseline %s updated" % args.baseline)
    return 1 if failed or (regressed and not args.update_baseline) else 0


if __name__ == "__main__":
    sys.exit(main())
