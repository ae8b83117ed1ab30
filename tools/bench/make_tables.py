#!/usr/bin/env python3
"""Renders the measured tables of tools/bench/tables/*.json into the docs that embed them.

Each data file holds one table: what was measured ("measured": date, time, machine, commit,
command), its columns (key, header, format) and its rows (one object per row, numbers as JSON
numbers). A doc embeds the table between two markers:

    <!-- table:NAME -->
    ...generated: the command, the table, the line naming date, commit, machine and data...
    <!-- /table -->

where NAME is the data file's name without `.json` and the doc is the file's "doc" field.

Usage: tools/bench/make_tables.py          rewrite every embedded table from its data
       tools/bench/make_tables.py --check  exit 1 when a doc's table differs from its data, a
                                           table has no markers or markers name no table
Python 3 standard library only; run from any directory.
"""

import argparse
import difflib
import json
import re
import string
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
TABLES = Path(__file__).resolve().parent / "tables"
MARKER = re.compile(r"<!-- table:([\w.-]+) -->\n(.*?)<!-- /table -->", re.S)


def field_names(fmt):
    return [name for _, name, _, _ in string.Formatter().parse(fmt) if name is not None]


def render_cell(value, fmt):
    """A value is None (empty), a string (as is), a number, a list (positional fields) or an
    object (named fields, or "value" for a one-field format; "suffix" is appended)."""
    if value is None:
        return ""
    if isinstance(value, str):
        return value
    if isinstance(value, list):
        return fmt.format(*value)
    if isinstance(value, dict):
        fields = {k: v for k, v in value.items() if k != "suffix"}
        if "value" in fields and all(not n or n.isdigit() for n in field_names(fmt)):
            text = fmt.format(fields["value"])
        else:
            text = fmt.format(**fields)
        return text + value.get("suffix", "")
    return fmt.format(value)


def render_rows(table):
    columns = table["columns"]
    lines = ["| " + " | ".join(c["header"] for c in columns) + " |",
             "|" + "---|" * len(columns)]
    for row in table["rows"]:
        cells = [render_cell(row.get(c["key"]), c.get("format", "{}")) for c in columns]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def render(name, table, doc):
    m = table["measured"]
    link = Path("../" * (len(Path(table["doc"]).parts) - 1)) / "tools/bench/tables" / (name + ".json")
    lines = []
    if m.get("command"):
        lines += ["```", m["command"].rstrip("\n"), "```", ""]
    lines += render_rows(table)
    when = m["date"] + (" " + m["time_utc"] + " UTC" if m.get("time_utc") else "")
    commit = "at " + m["commit"][:10] if m.get("commit") else "commit not recorded"
    lines += ["", "Measured %s, %s, on %s. Data: [%s](%s)." % (
        when, commit, m["machine"], "tools/bench/tables/" + name + ".json", link.as_posix())]
    return "\n".join(lines) + "\n"


def load_tables():
    tables = {}
    for path in sorted(TABLES.glob("*.json")):
        with open(path, encoding="utf-8") as f:
            tables[path.stem] = json.load(f)
    return tables


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="compare only; exit 1 on any difference")
    args = parser.parse_args()
    tables = load_tables()
    docs = sorted({t["doc"] for t in tables.values()} |
                  {p.relative_to(REPO).as_posix() for p in (REPO / "docs").rglob("*.md")})
    problems = 0
    embedded = set()
    for doc in docs:
        path = REPO / doc
        if not path.exists():
            continue
        text = path.read_text(encoding="utf-8")

        def replace(match):
            nonlocal problems
            name = match.group(1)
            if name not in tables:
                print("%s: marker names no table: %s" % (doc, name), file=sys.stderr)
                problems += 1
                return match.group(0)
            if tables[name]["doc"] != doc:
                print("%s: table %s belongs to %s" % (doc, name, tables[name]["doc"]),
                      file=sys.stderr)
                problems += 1
                return match.group(0)
            embedded.add(name)
            return "<!-- table:%s -->\n%s<!-- /table -->" % (name, render(name, tables[name], doc))

        new = MARKER.sub(replace, text)
        if new != text:
            if args.check:
                problems += 1
                print("%s: embedded tables differ from tools/bench/tables:" % doc, file=sys.stderr)
                sys.stderr.writelines(difflib.unified_diff(
                    text.splitlines(True), new.splitlines(True), doc, doc + " (rendered)"))
            else:
                path.write_text(new, encoding="utf-8")
                print("rewrote", doc)
    for name in sorted(set(tables) - embedded):
        print("%s: table %s has no markers there" % (tables[name]["doc"], name), file=sys.stderr)
        problems += 1
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
