#!/usr/bin/env python3
# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors
#
"""Runs the command-line program on every mesh of some classes of the project's meshes
(../shared/data/meshes, classified in its PROVENANCE.md) and prints a Markdown table: per mesh
the outcome (a valid result: exit 0, no flipped face, the OBJ written; or a clear error:
non-zero exit, a message, no output file left), the exit code, the time and the message or
the result's figures, then the counts per class.

    python3 scripts/mesh_class_report.py PROGRAM [--classes MESSY,CLOSED,OPEN] [--timeout S]

PROGRAM is the built measured_parameterization (e.g. build/cli/measured_parameterization,
or the ASan build's). A class matches when the class column of PROVENANCE.md starts with it.
Exits 1 when a run crashes, hangs, leaves an output file after an error, or succeeds with
flipped faces or a non-finite value.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MESH_DIR = os.path.normpath(os.path.join(HERE, "..", "..", "shared", "data", "meshes"))


def classes_of(provenance):
    meshes = []
    with open(provenance) as f:
        for line in f:
            m = re.match(r"\|\s*`([^`]+)`\s*\|\s*([^|]+?)\s*\|\s*(\d+)\s*\|\s*(\d+)\s*\|", line)
            if m:
                meshes.append((m.group(1), m.group(2), int(m.group(3)), int(m.group(4))))
    return meshes


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("program")
    ap.add_argument("--classes", default="MESSY,CLOSED,OPEN")
    ap.add_argument("--timeout", type=float, default=600.)
    ap.add_argument("--mesh-dir", default=MESH_DIR)
    args = ap.parse_args()
    program = os.path.abspath(args.program)
    wanted = [c.strip() for c in args.classes.split(",") if c.strip()]

    rows, counts, bad = [], {}, 0
    for name, cls, nv, nf in classes_of(os.path.join(args.mesh_dir, "PROVENANCE.md")):
        key = next((c for c in wanted if cls.startswith(c)), None)
        if key is None:
            continue
        work = tempfile.mkdtemp(prefix="mbp_class_")
        t0 = time.monotonic()
        try:
            p = subprocess.run([program, os.path.join(args.mesh_dir, name), "out.obj", "--svg=out.svg", "--json"],
                               cwd=work, capture_output=True, text=True, timeout=args.timeout)
            code, out, err = p.returncode, p.stdout, p.stderr
        except subprocess.TimeoutExpired:
            code, out, err = None, "", "timeout after %g s" % args.timeout
        seconds = time.monotonic() - t0
        left = sorted(os.listdir(work))
        shutil.rmtree(work, ignore_errors=True)

        problem = None
        if code is None:
            problem = "hang"
        elif code < 0:
            problem = "crash (signal %d)" % -code
        elif code == 0:
            try:
                j = json.loads(out)
                flips = j["quality"]["flipped_faces"]
                # The center is null when no member of the automatic border needed it.
                center_uv = j["center"]["uv"] if j.get("center") else []
                finite = all(math.isfinite(float(x)) for x in
                             [j["quality"]["angle_distortion"], j["quality"]["l2_stretch"]] + center_uv)
                seams = j.get("automatic_seams")
                kept = j.get("border_choice", {}).get("chosen")
                detail = "V %d, F %d, %sborder %d, %sflipped faces %d, angle distortion %.4g%s" % (
                    j["vertices"], j["faces"],
                    "automatic seams: %d edges, %d cones; " % (seams["seam_edges"], seams["cones"]) if seams else "",
                    j["border"]["vertices"],
                    "kept %s (blend %.3g); " % (kept["kind"], kept["blend"]) if kept else "",
                    flips, j["quality"]["angle_distortion"],
                    ", repaired (blend %.3g)" % j["repair"]["blend"] if j["repair"]["repaired"] else "")
                if flips != 0 or not finite or "out.obj" not in left:
                    problem = "invalid result"
            except (ValueError, KeyError) as e:
                detail, problem = "bad JSON: %s" % e, "bad JSON"
        else:
            lines = [l for l in err.splitlines() if l.startswith("error:")]
            detail = lines[0].replace(os.path.join(args.mesh_dir, name), name) if lines else err.strip()[:200]
            if left:
                problem = "output left on error: %s" % " ".join(left)
            elif not lines or "Sanitizer" in err or "runtime error" in err:
                problem = "unclear failure"
        outcome = problem or ("valid" if code == 0 else "clear error")
        c = counts.setdefault(key, {"valid": 0, "clear error": 0, "problem": 0, "meshes": 0})
        c["meshes"] += 1
        c[outcome if outcome in ("valid", "clear error") else "problem"] += 1
        bad += problem is not None
        rows.append((key, name, cls, nv, nf, outcome, code, seconds, ", ".join(left) or "none", detail))
        print("%s: %s (exit %s, %.2f s)" % (name, outcome, code, seconds), file=sys.stderr)

    print("| class | mesh | V | F | outcome | exit | seconds | files left | message / result |")
    print("|---|---|---|---|---|---|---|---|---|")
    for key, name, cls, nv, nf, outcome, code, seconds, left, detail in rows:
        print("| %s | `%s` | %d | %d | %s | %s | %.2f | %s | %s |" % (
            cls, name, nv, nf, outcome, code, seconds, left, detail.replace("|", "\\|")))
    print()
    print("| class | meshes | valid | clear error | problem |")
    print("|---|---|---|---|---|")
    for key in wanted:
        if key in counts:
            c = counts[key]
            print("| %s | %d | %d | %d | %d |" % (key, c["meshes"], c["valid"], c["clear error"], c["problem"]))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
