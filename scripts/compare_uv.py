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
# The comparison step of scripts/compare_outputs.sh (Python 3 standard library only): reads
# the list of cases that script ran at REF and at HEAD, compares each pair of runs and writes
# OUT/compare.tsv (one row per mesh and option set), OUT/summary.txt (the table printed at the
# end) and OUT/failures.txt (the details of every change). Exit status: 0 when nothing
# changed, 1 when a difference exceeds the tolerance or a status or message class changed.
#
# What is compared, for a case (a mesh and an option set) run by both programs:
#  - the message class (message_class() below): the exit status (or "timeout", or the
#    signal), for a failure the name of the library's Error_code (the "error_code" of the
#    --json error object; "no-error-code" when it is null), and the kind of each "error:",
#    "warning:" and "note:" line of stderr: its first two ': '-separated fields (for an error
#    the input, written INPUT, and the problem, e.g. "error: INPUT: Input mesh is not
#    triangular"), without parenthesized details, every number written #. A different class
#    is a change. The exact messages (numbers included) are compared too but only reported
#    (message_same): the refactoring may reword the details of a message;
#  - whether each run left an OBJ;
#  - when both ran and wrote an OBJ: the 'v' lines (the same number, the same coordinates in
#    the same order), the faces (the same number, the same vertex indices in the same order),
#    the UVs per face corner (so the numbering of the 'vt' lines does not matter) and which
#    corners share a 'vt' (the seams: the same partition of the corners; and the same number
#    of 'vt' lines), and the UV difference:
#      uv_diff:     each UV set is normalized by its own bounding box (translated to the
#                   origin, divided by its longest side: the layout fits [0,1]^2), then the
#                   largest |du| or |dv| over all face corners;
#      uv_diff_raw: the largest |du| or |dv| of the raw UVs (as written), divided by the
#                   longest side of REF's bounding box: catches a change of position or scale
#                   of the layout that the normalization hides.
#    Both must be <= the tolerance. OBJ files that are byte-identical (or identical but for
#    their comment lines) are recognized first (all differences exactly 0) without parsing.
# The OBJ comment lines ('#') are compared but only reported (comments_same).

import argparse
import itertools
import json
import math
import multiprocessing
import operator
import os
import re
import signal
import sys

# CGAL's Error_code (0..9) and the package's codes (Measured_error_code.h, 10..15)
ERROR_CODE_NAMES = [
    "OK", "ERROR_EMPTY_MESH", "ERROR_NON_TRIANGULAR_MESH", "ERROR_NO_TOPOLOGICAL_DISC",
    "ERROR_NO_TOPOLOGICAL_BALL", "ERROR_BORDER_TOO_SHORT", "ERROR_NON_CONVEX_BORDER",
    "ERROR_CANNOT_SOLVE_LINEAR_SYSTEM", "ERROR_NO_1_TO_1_MAPPING", "ERROR_WRONG_PARAMETER",
    "ERROR_DEGENERATE_FACE", "ERROR_NON_FINITE_COORDINATES", "ERROR_NO_INTERIOR_VERTEX",
    "ERROR_INVALID_BORDER_HALFEDGE", "ERROR_DISTANCE_COMPUTATION_FAILED", "ERROR_DEGENERATE_BORDER_MAP",
]

TIMEOUT_STATUSES = (124, 137)  # timeout(1): the time limit, or the KILL after --kill-after


def read_text(path):
    try:
        with open(path, "rb") as f:
            return f.read().decode("utf-8", "replace")
    except OSError:
        return ""


class Run:
    """One run of one program on one case: its folder holds rc, seconds, stdout, stderr, the OBJ."""

    def __init__(self, folder, obj_name, input_path):
        self.folder = folder
        rc = read_text(os.path.join(folder, "rc")).strip()
        self.rc = int(rc) if rc.lstrip("-").isdigit() else None
        s = read_text(os.path.join(folder, "seconds")).strip()
        self.seconds = float(s) if s else float("nan")
        self.stdout = read_text(os.path.join(folder, "stdout"))
        self.stderr = read_text(os.path.join(folder, "stderr"))
        self.obj = None
        if obj_name.startswith("*"):  # the run without INPUT: <default mesh stem>_uv.obj
            names = sorted(n for n in os.listdir(folder) if n.endswith(obj_name[1:])) if os.path.isdir(folder) else []
            if names:
                self.obj = os.path.join(folder, names[0])
        elif os.path.isfile(os.path.join(folder, obj_name)):
            self.obj = os.path.join(folder, obj_name)
        self.input_path = input_path
        self.obj_name = obj_name

    def status(self):
        if self.rc is None:
            return "not run"
        if self.rc in TIMEOUT_STATUSES:
            return "timeout"
        if self.rc > 128:
            try:
                return "signal " + signal.Signals(self.rc - 128).name
            except ValueError:
                return "exit %d" % self.rc
        return "exit %d" % self.rc

    def error_code(self):
        """the Error_code name of the --json error object of a failed run"""
        if self.rc in (None, 0) or self.status() in ("timeout",) or self.status().startswith("signal"):
            return None
        try:
            j = json.loads(self.stdout)
        except ValueError:
            return "no-json-error"
        if not isinstance(j, dict) or "error" not in j:
            return "no-json-error"
        code = j.get("error_code")
        if code is None:
            return "no-error-code"
        if isinstance(code, int) and 0 <= code < len(ERROR_CODE_NAMES):
            return ERROR_CODE_NAMES[code]
        return "error_code %s" % code

    def message_lines(self):
        """the 'error:', 'warning:' and 'note:' lines of stderr, the input path written INPUT and
        the output's name OUTPUT"""
        lines = []
        for line in self.stderr.splitlines():
            if not re.match(r"^(error|warning|note): ", line):
                continue
            if self.input_path:
                line = line.replace(self.input_path, "INPUT")
            if self.obj_name and not self.obj_name.startswith("*"):
                line = re.sub(r"(?<![\w.-])" + re.escape(self.obj_name) + r"(?![\w.-])", "OUTPUT", line)
            lines.append(line)
        return lines

    def message_class(self):
        """status; for a failure the Error_code name; then the kind of each message line: its
        prefix and its first two ': '-separated fields (the input, written INPUT, and the
        problem), without parenthesized details, every number written #"""
        parts = [self.status()]
        code = self.error_code()
        if code is not None:
            parts.append(code)
        kinds = []
        for line in self.message_lines():
            prefix, rest = line.split(": ", 1)
            head = ": ".join(rest.split(": ")[:2])
            head = re.sub(r"\s*\([^()]*\)", "", head)  # parenthesized details
            kind = prefix + ": " + re.sub(r"[-+]?\d+(\.\d+)?([eE][-+]?\d+)?", "#", head)
            if kind not in kinds:
                kinds.append(kind)
        return " | ".join(parts + kinds)


class Obj:
    """the 'v', 'vt' and 'f' lines of an OBJ written by the program (the text after the keyword),
    parsed in bulk"""

    def __init__(self, data):
        self.v_lines = re.findall(rb"^v ([^\n]*)", data, re.M)
        self.vt_lines = re.findall(rb"^vt ([^\n]*)", data, re.M)
        self.f_lines = re.findall(rb"^f ([^\n]*)", data, re.M)
        self.comments = re.findall(rb"^#([^\n]*)", data, re.M)

    @staticmethod
    def numbers(lines, per_line):
        """the first `per_line` numbers of each line, as `per_line` lists of floats"""
        tokens = b" ".join(lines).split()
        if len(tokens) == per_line * len(lines):
            return [list(map(float, tokens[k::per_line])) for k in range(per_line)]
        rows = [l.split()[:per_line] for l in lines]  # other token counts: line by line
        return [[float(r[k]) if k < len(r) else math.nan for r in rows] for k in range(per_line)]

    def vertices(self):
        return list(zip(*self.numbers(self.v_lines, 3)))

    def uvs(self):
        return self.numbers(self.vt_lines, 2)

    def faces(self):
        """(number of corners of each face, vertex of each corner, 0-based vt of each corner)"""
        n = len(self.f_lines)
        tokens = b" ".join(self.f_lines).replace(b"/", b" ").split()
        if len(tokens) == 6 * n and b"".join(self.f_lines).count(b"/") == 3 * n:  # 'f a/t b/t c/t'
            sizes = [3] * n
            corner_v = list(map(int, tokens[0::2]))
            corner_t = list(map(int, tokens[1::2]))
        else:
            sizes, corner_v, corner_t = [], [], []
            for line in self.f_lines:
                corners = line.split()
                sizes.append(len(corners))
                for c in corners:
                    idx = c.split(b"/")
                    corner_v.append(int(idx[0]))
                    corner_t.append(int(idx[1]) if len(idx) > 1 and idx[1] else int(idx[0]))
        m = len(self.vt_lines)
        if corner_t and min(corner_t) <= 0:  # relative indices
            corner_t = [t - 1 if t > 0 else m + t for t in corner_t]
        else:
            corner_t = [t - 1 for t in corner_t]
        return sizes, corner_v, corner_t


def pick(values, indices):
    """[values[i] for i in indices], faster"""
    if len(indices) < 2:
        return [values[i] for i in indices]
    return list(operator.itemgetter(*indices)(values))


def finite(values):
    return all(map(math.isfinite, values))


def bounding_box(us, vs):
    """(lower corner, longest side) of the finite UVs"""
    if not (finite(us) and finite(vs)):
        pairs = [(u, v) for u, v in zip(us, vs) if math.isfinite(u) and math.isfinite(v)]
        us, vs = [p[0] for p in pairs], [p[1] for p in pairs]
    if not us:
        return (0., 0.), 1.
    lo = (min(us), min(vs))
    side = max(max(us) - lo[0], max(vs) - lo[1])
    return lo, (side if side > 0. else 1.)


def max_difference(a, b, lo_a=0., scale_a=1., lo_b=0., scale_b=1.):
    """the largest |(x - lo_a) / scale_a - (y - lo_b) / scale_b| over the pairs (x, y) of a and b;
    infinite when a value is not finite at one side only, or they differ"""
    if finite(a) and finite(b):
        if lo_a == lo_b and scale_a == scale_b and a == b:
            return 0.
        na = map(operator.truediv, map(operator.sub, a, itertools.repeat(lo_a)), itertools.repeat(scale_a))
        nb = map(operator.truediv, map(operator.sub, b, itertools.repeat(lo_b)), itertools.repeat(scale_b))
        return max(map(abs, map(operator.sub, na, nb)), default=0.)
    worst = 0.
    for x, y in zip(a, b):
        if x == y or (math.isnan(x) and math.isnan(y)):
            continue
        d = abs((x - lo_a) / scale_a - (y - lo_b) / scale_b)
        worst = max(worst, d) if math.isfinite(d) else math.inf
    return worst


def count_lines(data, prefix):
    return data.count(b"\n" + prefix) + (1 if data.startswith(prefix) else 0)


def without_comments(data):
    return re.sub(rb"(?m)^#[^\n]*\n?", b"", data)


def compare_objs(ref_path, head_path):
    """the comparison of two OBJs: a dict of the TSV's columns and a list of problems"""
    with open(ref_path, "rb") as f:
        a_bytes = f.read()
    with open(head_path, "rb") as f:
        b_bytes = f.read()
    counts = {"vertices": count_lines(a_bytes, b"v "), "faces": count_lines(a_bytes, b"f "),
              "uvs_ref": count_lines(a_bytes, b"vt "), "uvs_head": count_lines(b_bytes, b"vt ")}
    if a_bytes == b_bytes:
        return dict(counts, mesh_same="yes", seams_same="yes", comments_same="yes", identical="yes",
                    uv_diff=0., uv_diff_raw=0.), []
    if without_comments(a_bytes) == without_comments(b_bytes):  # only a comment changed
        return dict(counts, mesh_same="yes", seams_same="yes", comments_same="no", identical="no",
                    uv_diff=0., uv_diff_raw=0.), []
    a, b = Obj(a_bytes), Obj(b_bytes)
    del a_bytes, b_bytes
    problems = []
    row = dict(counts, identical="no", comments_same="yes" if a.comments == b.comments else "no")
    mesh_same = True
    if len(a.v_lines) != len(b.v_lines):
        problems.append("v lines: %d at REF, %d at HEAD" % (len(a.v_lines), len(b.v_lines)))
        mesh_same = False
    elif a.v_lines != b.v_lines:
        va, vb = a.vertices(), b.vertices()
        if va != vb:
            first = next(i for i, (p, q) in enumerate(zip(va, vb)) if p != q)
            problems.append("v lines differ (first: v line %d)" % (first + 1))
            mesh_same = False
    sizes_a, cv_a, ct_a = a.faces()
    sizes_b, cv_b, ct_b = b.faces()
    if len(sizes_a) != len(sizes_b):
        problems.append("f lines: %d at REF, %d at HEAD" % (len(sizes_a), len(sizes_b)))
        mesh_same = False
    elif sizes_a != sizes_b or cv_a != cv_b:
        first = next(i for i, (p, q) in enumerate(zip(cv_a, cv_b)) if p != q) if len(cv_a) == len(cv_b) else 0
        problems.append("face vertices differ (first near corner %d)" % (first + 1))
        mesh_same = False
    row["mesh_same"] = "yes" if mesh_same else "no"
    if not mesh_same:
        return row, problems  # no UV difference: the corners do not correspond
    # the seams: corners share a vt at REF exactly when they share one at HEAD
    if ct_a == ct_b:
        seams_same = True
    else:
        to_head, to_ref = {}, {}
        seams_same = all(to_head.setdefault(x, y) == y and to_ref.setdefault(y, x) == x for x, y in zip(ct_a, ct_b))
    row["seams_same"] = "yes" if seams_same else "no"
    if not seams_same:
        problems.append("the corners sharing a UV differ (the seams or the UV numbering changed)")
    if len(a.vt_lines) != len(b.vt_lines):
        problems.append("vt lines: %d at REF, %d at HEAD" % (len(a.vt_lines), len(b.vt_lines)))
    (ua, va), (ub, vb) = a.uvs(), b.uvs()
    if ct_a and (min(ct_a) < 0 or max(ct_a) >= len(ua) or min(ct_b) < 0 or max(ct_b) >= len(ub)):
        problems.append("a face refers to a missing vt line")
        return row, problems
    # per face corner
    ua, va, ub, vb = pick(ua, ct_a), pick(va, ct_a), pick(ub, ct_b), pick(vb, ct_b)
    lo_a, side_a = bounding_box(ua, va)
    lo_b, side_b = bounding_box(ub, vb)
    row["uv_diff"] = max(max_difference(ua, ub, lo_a[0], side_a, lo_b[0], side_b),
                         max_difference(va, vb, lo_a[1], side_a, lo_b[1], side_b))
    row["uv_diff_raw"] = max(max_difference(ua, ub), max_difference(va, vb)) / side_a
    return row, problems


def fmt(x):
    if isinstance(x, float):
        if x == 0.:
            return "0"
        return "%.3g" % x if math.isfinite(x) else ("inf" if x > 0 else "nan")
    return str(x)


COLUMNS = ["case", "tier", "mesh", "options", "args", "ref_status", "head_status", "ref_class", "head_class",
           "class_same", "message_same", "ref_obj", "head_obj", "vertices", "faces", "uvs_ref", "uvs_head",
           "identical", "mesh_same", "seams_same", "comments_same", "uv_diff", "uv_diff_raw", "ref_seconds",
           "head_seconds", "verdict", "problems"]


def compare_case(case, tolerance):
    input_path = "" if case["input"] == "-" else case["input"]
    ref = Run(case["ref_dir"], case["obj"], input_path)
    head = Run(case["head_dir"], case["obj"], input_path)
    row = {k: "-" for k in COLUMNS}
    row.update(case=case["id"], tier=case["tier"], mesh=case["mesh"], options=case["options"], args=case["args"],
               ref_status=ref.status(), head_status=head.status(), ref_class=ref.message_class(),
               head_class=head.message_class(), ref_obj="yes" if ref.obj else "no",
               head_obj="yes" if head.obj else "no", ref_seconds="%.3f" % ref.seconds,
               head_seconds="%.3f" % head.seconds)
    problems = []
    row["class_same"] = "yes" if row["ref_class"] == row["head_class"] else "no"
    if row["class_same"] == "no":
        problems.append("message class: REF '%s', HEAD '%s'" % (row["ref_class"], row["head_class"]))
    row["message_same"] = "yes" if ref.message_lines() == head.message_lines() else "no"
    if (ref.obj is None) != (head.obj is None):
        problems.append("OBJ written: REF %s, HEAD %s" % (row["ref_obj"], row["head_obj"]))
    if ref.rc == 0 and head.rc == 0 and ref.obj and head.obj:
        obj_row, obj_problems = compare_objs(ref.obj, head.obj)
        row.update(obj_row)
        problems += obj_problems
        for key in ("uv_diff", "uv_diff_raw"):
            if isinstance(row[key], float) and not row[key] <= tolerance:
                problems.append("%s %s > tolerance %g" % (key, fmt(row[key]), tolerance))
    elif ref.rc == 0 and head.rc == 0 and ref.obj is None and head.obj is None:
        problems.append("exit 0 without an OBJ at both")
    row["verdict"] = "changed" if problems else "same"
    row["problems"] = "; ".join(problems) if problems else "-"
    return row


def cell(row):
    """one cell of the summary table"""
    if row["verdict"] == "changed":
        if row["class_same"] == "no":
            return "STATUS!" if row["ref_status"] != row["head_status"] else "CLASS!"
        if row["mesh_same"] == "no" or row["seams_same"] == "no":
            return "MESH!"
        if isinstance(row["uv_diff"], float):
            return fmt(max(row["uv_diff"], row["uv_diff_raw"])) + "!"
        return "CHANGED!"
    if isinstance(row["uv_diff"], float):
        return fmt(max(row["uv_diff"], row["uv_diff_raw"]))
    if row["ref_status"] == "timeout":
        return "timeout"
    return "err" + row["ref_status"].replace("exit ", "")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--cases", required=True, help="TSV: id tier mesh options args input obj ref_dir head_dir")
    parser.add_argument("--tolerance", type=float, required=True)
    parser.add_argument("--out", required=True, help="folder of compare.tsv, summary.txt, failures.txt")
    parser.add_argument("--header", default="", help="a file whose text starts the summary")
    parser.add_argument("--jobs", type=int, default=1, help="processes comparing in parallel")
    args = parser.parse_args()

    keys = ["id", "tier", "mesh", "options", "args", "input", "obj", "ref_dir", "head_dir"]
    cases = []
    with open(args.cases, encoding="utf-8") as f:
        for line in f:
            if line.strip():
                cases.append(dict(zip(keys, line.rstrip("\n").split("\t"))))
    if args.jobs > 1 and len(cases) > 1:
        with multiprocessing.Pool(args.jobs) as pool:
            rows = pool.starmap(compare_case, [(c, args.tolerance) for c in cases], chunksize=4)
    else:
        rows = [compare_case(c, args.tolerance) for c in cases]

    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "compare.tsv"), "w", encoding="utf-8") as f:
        f.write("\t".join(COLUMNS) + "\n")
        for r in rows:
            f.write("\t".join(fmt(r[k]).replace("\t", " ") for k in COLUMNS) + "\n")

    # the table: one line per (tier, mesh), one column per option set; the special runs (tier
    # "cli") below it
    option_sets, meshes, table, special = [], [], {}, []
    for r in rows:
        if r["tier"] == "cli":
            special.append(r)
            continue
        if r["options"] not in option_sets:
            option_sets.append(r["options"])
        m = (r["tier"], r["mesh"])
        if m not in table:
            meshes.append(m)
            table[m] = {}
        table[m][r["options"]] = cell(r)
    width = max([len("%s/%s" % m) for m in meshes] + [len(r["case"]) for r in special] + [4]) + 1
    widths = [max([len(o)] + [len(table[m].get(o, "")) for m in meshes]) + 2 for o in option_sets]
    out = []
    if args.header and os.path.isfile(args.header):
        out.append(read_text(args.header).rstrip("\n"))
        out.append("")
    out.append("Largest UV difference per mesh and option set: the larger of the normalized and the raw relative")
    out.append("difference (0: exactly equal); errN/timeout: both runs failed alike; '!' marks a change: STATUS! exit")
    out.append("status, CLASS! message class, MESH! v/f lines or seams, X! a UV difference X over the tolerance")
    out.append("")
    out.append("%-*s" % (width, "mesh") + "".join("%*s" % (w, o) for w, o in zip(widths, option_sets)))
    for m in meshes:
        out.append("%-*s" % (width, "%s/%s" % m)
                   + "".join("%*s" % (w, table[m].get(o, "")) for w, o in zip(widths, option_sets)))
    for r in special:
        out.append("%-*s%*s   (%s: %s)" % (width, r["case"], widths[0] if widths else 8, cell(r), r["args"], r["head_class"]))
    out.append("")

    compared = [r for r in rows if isinstance(r["uv_diff"], float)]
    changed = [r for r in rows if r["verdict"] == "changed"]
    both_failed = [r for r in rows if r["ref_status"] != "exit 0" and r["class_same"] == "yes"]
    reworded = [r for r in rows if r["class_same"] == "yes" and r["message_same"] == "no"]
    not_identical = [r for r in compared if r["identical"] == "no"]
    out.append("cases: %d (%d meshes x %d option sets, and %d special runs)"
               % (len(rows), len(meshes), len(option_sets), len(special)))
    out.append("  UVs compared:               %d (byte-identical OBJs: %d)" % (len(compared), len(compared) - len(not_identical)))
    out.append("  failed alike at both:       %d (same exit status and message class)" % len(both_failed))
    out.append("  messages reworded (same class, reported only): %d" % len(reworded))
    out.append("  status or class changed:    %d" % sum(1 for r in rows if r["class_same"] == "no"))
    out.append("  changed in all:             %d" % len(changed))
    if compared:
        worst = max(compared, key=lambda r: max(r["uv_diff"], r["uv_diff_raw"]))
        if max(worst["uv_diff"], worst["uv_diff_raw"]) == 0.:
            out.append("worst UV difference: 0 (every one of the %d compared layouts is exactly equal)" % len(compared))
        else:
            out.append("worst UV difference: %s normalized, %s raw relative (%s)"
                       % (fmt(worst["uv_diff"]), fmt(worst["uv_diff_raw"]), worst["case"]))
    else:
        out.append("worst UV difference: none compared")
    out.append("tolerance: %g" % args.tolerance)
    out.append("table: %s" % os.path.join(args.out, "compare.tsv"))
    if changed:
        out.append("")
        out.append("CHANGED (%d), details in %s:" % (len(changed), os.path.join(args.out, "failures.txt")))
        for r in changed[:40]:
            out.append("  %s: %s" % (r["case"], r["problems"]))
        if len(changed) > 40:
            out.append("  ... and %d more" % (len(changed) - 40))
    out.append("")
    out.append("RESULT: %s" % ("CHANGED" if changed else "SAME (every difference <= tolerance, no status or class change)"))
    text = "\n".join(out) + "\n"
    with open(os.path.join(args.out, "summary.txt"), "w", encoding="utf-8") as f:
        f.write(text)
    with open(os.path.join(args.out, "failures.txt"), "w", encoding="utf-8") as f:
        for r in changed:
            f.write("%s (%s)\n  problems: %s\n  REF:  %s\n  HEAD: %s\n\n" % (
                r["case"], r["args"], r["problems"], r["ref_class"], r["head_class"]))
    sys.stdout.write(text)
    return 1 if changed else 0


if __name__ == "__main__":
    sys.exit(main())
