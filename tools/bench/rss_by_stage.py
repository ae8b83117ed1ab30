#!/usr/bin/env python3
"""Resident memory of a linesurf run, stage by stage: where the peak is.

Runs the given command (a `linesurf ... reconstruct ...` without -q, so that it prints its
progress on stderr, which is passed through), samples VmRSS of the process every 0.1 s (Linux /proc), and prints for
each stage that reports progress the time span of its reports and the largest RSS seen in it,
then the overall peak and when it happened. Stages without progress reports (the solve, the
extraction) fall between the spans: a peak after the last span is theirs.

Usage: tools/bench/rss_by_stage.py LINESURF [ARGS...]
Exit status: the command's, 2 on bad usage. Python 3 standard library only.
"""

import re
import subprocess
import sys
import threading
import time

SAMPLE_SECONDS = 0.1


def main(argv):
    if len(argv) >= 2 and argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    start = time.time()
    process = subprocess.Popen(argv[1:], stderr=subprocess.PIPE, stdout=subprocess.DEVNULL,
                               text=True)
    spans = {}  # stage -> [first report, last report] in seconds

    def read_progress():
        text = ""
        while True:
            ch = process.stderr.read(1)
            if not ch:
                return
            if ch in "\n%":  # a progress report ends with its percentage
                sys.stderr.write(text + ch)  # the command's own messages stay visible
                match = re.search(r"\[(\w+)\]", text)
                if match:
                    now = time.time() - start
                    spans.setdefault(match.group(1), [now, now])[1] = now
                text = ""
            else:
                text += ch

    reader = threading.Thread(target=read_progress)
    reader.start()
    samples = []  # (seconds, MB)
    while process.poll() is None:
        try:
            with open(f"/proc/{process.pid}/status") as status:
                for line in status:
                    if line.startswith("VmRSS:"):
                        samples.append((time.time() - start, int(line.split()[1]) // 1024))
        except OSError:
            pass  # the process just ended
        time.sleep(SAMPLE_SECONDS)
    reader.join()
    if not samples:
        print("no sample: the command ended at once", file=sys.stderr)
        return process.returncode or 1
    for stage, (first, last) in sorted(spans.items(), key=lambda item: item[1][0]):
        inside = [mb for t, mb in samples if first <= t <= last + SAMPLE_SECONDS]
        print(f"{stage:20s} {first:8.1f} - {last:8.1f} s   max RSS {max(inside, default=0):6d} MB")
    peak_time, peak = max(samples, key=lambda sample: sample[1])
    print(f"peak RSS {peak} MB at {peak_time:.1f} s; the run ended at {samples[-1][0]:.1f} s")
    return process.returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv))
