"""What the bench scripts of docs/design/real_data.md share: their arguments and the command
line their tables record, running linesurf, its scenes (the README example, synthetic city-16 and
Andalusian when ../shared/data holds it) and the figures taken from its reports and its evaluate
command."""

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SHARED = REPO.parent / "shared"


def arguments(description, name):
    """The arguments every such script takes: --linesurf, --workdir, --machine, --name (default
    `name`) and, after `--`, options of every `linesurf reconstruct`. Add its own, then parse."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--linesurf", default=str(REPO / "build" / "bin" / "linesurf"))
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--machine", default="")
    parser.add_argument("--name", default=name)
    parser.add_argument("extra", nargs="*", help="options of linesurf reconstruct (after --)")
    return parser


def command_line(script, args, own=""):
    """The command that reproduces a table of tools/bench/`script` run with `args` (`own`: its
    own arguments, as typed)."""
    return ("python3 tools/bench/%s --linesurf %s --workdir %s --name %s%s%s"
            % (script, os.path.relpath(args.linesurf, REPO), args.workdir, args.name, own,
               " -- " + " ".join(args.extra) if args.extra else ""))


def options_text(args):
    """The reconstruct options of a run, for a table's title."""
    return " ".join(args.extra) or "defaults"


def run(cmd):
    subprocess.run([str(c) for c in cmd], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.PIPE)


def evaluate(linesurf, result, reference, threshold):
    """Precision and completeness (%) of `result` against the mesh `reference` at `threshold`."""
    out = Path(str(result) + ".eval.json")
    run([linesurf, "-q", "evaluate", result, reference, "--thresholds", threshold, "--json", out])
    e = json.load(open(out))
    return 100.0 * e["precision"][0], 100.0 * e["completeness"][0]


def scenes(work, linesurf, include_example=True):
    """(name, lines, ground truth or None) of each scene; city-16 is synthesised into `work`."""
    if include_example:
        example = REPO / "docs" / "examples" / "house"
        yield "README example (house)", example / "lines.json", example / "ground_truth.ply"
    city = work / "city-16"
    if not (city / "lines.json").exists():
        run([linesurf, "synth", "city", "--size", "16", "--seed", "4016", "-o", city])
    yield "synthetic city-16 (seed 4016)", city / "lines.json", city / "ground_truth.ply"
    andalusian = SHARED / "data" / "andalusian" / "input_lines_from_residuals.json"
    if andalusian.exists():
        yield "Andalusian", andalusian, None
    else:
        print("%s: Andalusian absent from %s, skipped" % (Path(sys.argv[0]).name, andalusian),
              file=sys.stderr)


def reconstruct(linesurf, extra, scene, stem):
    """Runs `linesurf reconstruct` to STEM.obj and returns its report, with the wall seconds."""
    start = time.monotonic()
    run([linesurf, "-q", "reconstruct", scene, "-o", str(stem) + ".obj",
         "--report", str(stem) + ".json"] + extra)
    report = json.load(open(str(stem) + ".json"))
    report["seconds"] = time.monotonic() - start
    return report
