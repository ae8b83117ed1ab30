"""Writes one measured table as make_tables.py reads it (tools/bench/tables/NAME.json): what was
measured (date and time UTC, machine, commit, command), its columns and rows."""

import datetime
import json
import os
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def write_table(name, doc, title, command, columns, rows, machine=""):
    """Writes tools/bench/tables/NAME.json for `doc` (a path from the repository root) and
    prints its path; `machine` defaults to the host name."""
    commit = subprocess.run(["git", "-C", str(REPO), "rev-parse", "HEAD"], check=True,
                            capture_output=True, text=True).stdout.strip()
    now = datetime.datetime.now(datetime.timezone.utc)
    table = {
        "doc": doc,
        "title": title,
        "measured": {"date": now.strftime("%Y-%m-%d"), "time_utc": now.strftime("%H:%M"),
                     "machine": machine or os.uname().nodename, "commit": commit,
                     "command": command},
        "columns": columns,
        "rows": rows,
    }
    out = REPO / "tools" / "bench" / "tables" / (name + ".json")
    out.write_text(json.dumps(table, indent=2) + "\n", encoding="utf-8")
    print("wrote", out)
