#!/usr/bin/env python3
"""Turns bench/piglit/run.sh's results.tsv and logs into a Markdown report.

Usage: report.py RESULTS.tsv LOGDIR [--piglit COMMIT] [--softgl COMMIT] [--seconds N]
                 [--src PIGLIT_SRC]

The report has the totals per test set and side, the tests that pass on Mesa but not on
softgl (with the first lines of softgl's output), the other disagreements, and one row
per test.
"""

import argparse
import csv
import os
import re

RESULTS = ["pass", "fail", "skip", "warn", "crash", "timeout", "noresult", "notbuilt"]


SRC = None


def read_log(path):
    """A log's lines without line ends, or None when it cannot be read."""
    try:
        with open(path, errors="replace") as f:
            return [l.rstrip() for l in f]
    except OSError:
        return None


def first_lines(path, n=6):
    """The first n non-empty lines of a log, without piglit's JSON lines; the piglit
    source path is shortened to `piglit/`."""
    lines = read_log(path)
    if lines is None:
        return ["(no log)"]
    lines = [l for l in lines if l.strip() and not l.startswith("PIGLIT: {")
             and not l.endswith(" - skipped")]
    more = len(lines) > n
    if SRC:
        lines = [l.replace(SRC.rstrip("/") + "/", "piglit/") for l in lines]
    lines = [l[:160] for l in lines[:n]]
    if more:
        lines.append("...")
    return lines or ["(no output)"]


def subtests(path):
    """(passed, total, failed names) of the subtests a log reports."""
    results = {}
    for line in read_log(path) or []:
        m = re.match(r'PIGLIT: \{"subtest": \{"(.*)" : "([a-z]+)"\}\}', line.strip())
        if m:
            results[m.group(1)] = m.group(2)
    passed = sum(1 for r in results.values() if r == "pass")
    failed = [n for n, r in results.items() if r == "fail"]
    return passed, len(results), failed


def cell(result, path):
    """A result, with its subtests passed/total when the test has subtests."""
    passed, total, _ = subtests(path)
    return "%s (%d/%d)" % (result, passed, total) if total else result


def renderer(logdir, side):
    """GL_RENDERER and GL_VERSION from the glinfo log, if the run had one."""
    path = os.path.join(logdir, side, "glinfo.log")
    found = {}
    for line in read_log(path) or []:
        m = re.match(r"GL_(RENDERER|VERSION) = (.*)", line.strip())
        if m:
            found[m.group(1)] = m.group(2)
    if not found:
        return None
    return "%s, GL %s" % (found.get("RENDERER", "?"), found.get("VERSION", "?"))


def totals_row(rows, side):
    counts = {r: 0 for r in RESULTS}
    for row in rows:
        counts[row[side]] = counts.get(row[side], 0) + 1
    return counts


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tsv")
    ap.add_argument("logdir")
    ap.add_argument("--piglit", default="unknown")
    ap.add_argument("--softgl", default="unknown")
    ap.add_argument("--seconds", default="?")
    ap.add_argument("--src", default=None, help="piglit source path to shorten in logs")
    a = ap.parse_args()
    global SRC
    SRC = a.src
    with open(a.tsv) as f:
        rows = list(csv.DictReader(f, delimiter="\t"))

    out = []
    out.append("# piglit GL 1.x results: softgl and Mesa llvmpipe\n")
    out.append("Written by `bench/piglit/run.sh` (see `bench/piglit/README.md`).\n")
    out.append("- piglit commit: `%s`" % a.piglit)
    out.append("- softgl commit: `%s`" % a.softgl)
    for side in ("softgl", "mesa"):
        r = renderer(a.logdir, side)
        if r:
            out.append("- %s renderer: %s" % (side, r))
    out.append("- %d tests, each run once per side with `-auto`: %s s for both sides\n"
               % (len(rows), a.seconds))

    out.append("## Totals\n")
    out.append("| set | tests | side | " + " | ".join(RESULTS) + " |")
    out.append("|---|---:|---|" + "---:|" * len(RESULTS))
    for name in ("core", "more", "all"):
        sel = [r for r in rows if name == "all" or r["set"] == name]
        if not sel:
            continue
        for side in ("softgl", "mesa"):
            c = totals_row(sel, side)
            out.append("| %s | %d | %s | %s |" % (
                name, len(sel), side, " | ".join(str(c[r]) for r in RESULTS)))
    out.append("")

    worse = [r for r in rows if r["mesa"] == "pass" and r["softgl"] not in ("pass", "skip")]
    skipped = [r for r in rows if r["mesa"] == "pass" and r["softgl"] == "skip"]
    out.append("## Pass on Mesa, fail on softgl (%d)\n" % len(worse))
    if not worse:
        out.append("None.\n")
    for r in worse:
        log = os.path.join(a.logdir, "softgl", r["name"] + ".log")
        out.append("### %s (`%s`): %s\n" % (r["name"], r["command"], cell(r["softgl"], log)))
        _, _, failed = subtests(log)
        if failed:
            out.append("Failing subtests: %s\n" % ", ".join(failed))
        out.append("```")
        out.extend(first_lines(log))
        out.append("```\n")

    out.append("## Pass on Mesa, skipped on softgl (%d)\n" % len(skipped))
    out.append("The test asks for more than softgl exposes (a GL version above 1.5, GLSL or "
               "an extension); the first lines say what.\n")
    if not skipped:
        out.append("None.\n")
    for r in skipped:
        log = os.path.join(a.logdir, "softgl", r["name"] + ".log")
        out.append("- %s (`%s`), %s: %s" % (r["name"], r["command"], cell("skip", log),
                                           " / ".join(first_lines(log, 3))))
    out.append("")

    other = [r for r in rows if r["softgl"] != r["mesa"] and r not in worse
             and r not in skipped]
    out.append("## Other disagreements (%d)\n" % len(other))
    if not other:
        out.append("None.\n")
    for r in other:
        out.append("### %s (`%s`): softgl %s, Mesa %s\n"
                   % (r["name"], r["command"], r["softgl"], r["mesa"]))
        for side in ("softgl", "mesa"):
            out.append("%s:\n" % side)
            out.append("```")
            out.extend(first_lines(os.path.join(a.logdir, side, r["name"] + ".log")))
            out.append("```\n")

    out.append("## Per test\n")
    out.append("Bold: the sides disagree. (p/n): subtests passed of those reported.\n")
    out.append("| set | test | command | softgl | s | Mesa | s |")
    out.append("|---|---|---|---|---:|---|---:|")
    for r in rows:
        s = cell(r["softgl"], os.path.join(a.logdir, "softgl", r["name"] + ".log"))
        m = cell(r["mesa"], os.path.join(a.logdir, "mesa", r["name"] + ".log"))
        if r["softgl"] != r["mesa"]:
            s, m = "**%s**" % s, "**%s**" % m
        out.append("| %s | %s | `%s` | %s | %s | %s | %s |" % (
            r["set"], r["name"], r["command"], s, r["softgl_s"], m, r["mesa_s"]))
    print("\n".join(out))


if __name__ == "__main__":
    main()
