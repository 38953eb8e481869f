#!/usr/bin/env python3
"""Issue 24's count check, step 2: `budget`'s counts do not change with the one report.

Runs `ltrender budget` (text) with a binary before the one report (commit 1f98e09: its four
report formats) and one after, on every argument list of CASES_FILE
(scripts/budget_counts_cases.sh writes it), parses both texts into
(file, row, resource) -> (used, limit) and prints every figure only one side has or that
differs, then the totals. Usage: budget_counts_diff.py BEFORE_BIN AFTER_BIN CASES_FILE"""
import re
import subprocess
import sys

LABELS = {  # old text's names -> the new report's keys
    "ALU": "alu", "TEX": "tex", "slots": "instruction_slots", "temps": "temporaries",
    "params": "parameters", "attribs": "attributes", "indir": "indirections",
    "ALU instructions": "alu", "TEX instructions": "tex", "instruction slots": "instruction_slots",
    "temporaries": "temporaries", "parameters": "parameters", "attributes": "attributes",
    "texture indirections": "indirections", "address registers": "address_registers",
    "stages": "stages", "texture units": "texture_units", "constant colours": "constant_colors",
    "lights": "lights", "passes": "passes", "TEV stages": "tev_stages", "texgens": "texgens",
    "texture maps": "texture_maps", "colour channels": "channels",
    "lights per channel": "lights_per_channel", "konst colours": "konst_colors",
    "TEV registers": "tev_registers", "vertex attributes": "vertex_attributes",
}
GX_KEYS = ["tev_stages", "texgens", "texture_maps", "channels", "lights_per_channel",
           "konst_colors", "tev_registers", "vertex_attributes"]


def run(binary, args):
    p = subprocess.run([binary, "budget"] + args, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def used_limit(tok):
    tok = tok.rstrip("!")
    if tok == "-":
        return None
    if "/" in tok:
        u, l = tok.split("/")
        return int(u), int(l)
    return int(tok), None


def parse_old(out):
    """The four old formats -> {(file, row, key): (used, limit)}."""
    rows = {}
    file = None
    mode = None
    gx_limits = None
    comb_limits = {}
    comb_rows = []
    for line in out.splitlines():
        m = re.match(r"budget: (\S+), path arbfp", line)
        if m:
            file, mode = m.group(1), "arbscene"
            continue
        m = re.match(r"budget: (\S+) \(!!ARB", line)
        if m:
            file, mode = m.group(1), "arbfile"
            continue
        if line.startswith("profile ") and "path combiners" in line:
            mode, comb_rows, comb_limits = "comb", [], {}
            file = "?"
            continue
        if line.startswith("profile ") and "Wii" in line:
            mode, gx_limits = "gx", None
            continue
        if mode == "gx" and line.startswith("path gx, "):
            file = line[len("path gx, "):].split(", variant")[0]
            continue
        if mode == "arbscene":
            m = re.match(r"^(material .*?: (?:vertex|fragment) program)\s+(\S+)\s+(\S+)\s+(\S+)\s+"
                         r"(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(fits|OVER)", line)
            if m:
                for col, tok in zip(["alu", "tex", "instruction_slots", "temporaries",
                                     "parameters", "attributes", "indirections"], m.groups()[1:8]):
                    v = used_limit(tok)
                    if v is not None:
                        rows[(file, m.group(1), col)] = v
                continue
            m = re.match(r"  material (.*?): total (-?\d+) ALU \+ (-?\d+) TEX;(.*)", line)
            if m:
                row = "material %s: translucency term" % m.group(1)
                rows[(file, row, "alu")] = (int(m.group(2)), None)
                rows[(file, row, "tex")] = (int(m.group(3)), None)
                for k, (a, t) in enumerate(re.findall(r"(?:first light \(incl\. view vector\)|light \d+) "
                                                      r"(-?\d+) ALU \+ (-?\d+) TEX", m.group(4))):
                    rows[(file, row, "light_%d_alu" % (k + 1))] = (int(a), None)
                    rows[(file, row, "light_%d_tex" % (k + 1))] = (int(t), None)
                continue
            m = re.match(r"  material (.*?): no pass tried|  material (.*?): fewest passes", line)
            if m:
                b = re.search(r"more than (\d+) lights: capacity bound >= (\d+) passes", line)
                row = "material %s: passes" % (m.group(1) or m.group(2))
                rows[(file, row, "most_lights_per_pass")] = (int(b.group(1)), None)
                rows[(file, row, "capacity_bound")] = (int(b.group(2)), None)
                continue
            m = re.match(r"  material (.*?): (lights? .*?): fragment (\d+) ALU \+ (\d+) TEX, (\d+) "
                         r"temps, (\d+) params; vertex (\d+) ALU", line)
            if m:
                row = "material %s: %s" % (m.group(1), m.group(2))
                for key, g in zip(["fragment_alu", "fragment_tex", "fragment_temporaries",
                                   "fragment_parameters", "vertex_alu"], m.groups()[2:]):
                    rows[(file, row, key)] = (int(g), None)
                continue
        if mode == "arbfile":
            for label in sorted([l for l in LABELS if " " in l or l in ("temporaries", "parameters", "attributes")], key=len, reverse=True):
                if line.startswith(label + " "):
                    toks = line[len(label):].split()
                    used = int(toks[0].rstrip("!"))
                    limit = None if toks[1] == "-" else int(toks[1])
                    mesa = None if toks[2] == "-" else int(toks[2])
                    kind = "vertex" if "vertex program" in out.split(file, 1)[1].split("\n", 1)[0] else "fragment"
                    rows[(file, kind + " program", LABELS[label])] = (used, limit)
                    if mesa is not None:
                        rows[(file, kind + " program", LABELS[label] + ".mesa")] = (mesa, None)
                    break
        if mode == "comb":
            m = re.match(r"  material (.*?): combiners/(.*?): (\d+) stages, (\d+) texture units, "
                         r"(\d+) constant colours, (\d+) passes", line)
            if m:
                comb_rows.append(m.groups())
                continue
            m = re.match(r"  stages (\d+)/(\d+), texture units (\d+)/(\d+), constant colours "
                         r"(\d+)/(\d+), lights (\d+)/(\d+), passes (\d+)", line)
            if m:
                g = [int(x) for x in m.groups()]
                summary = {"stages": g[0:2], "texture_units": g[2:4], "constant_colors": g[4:6],
                           "lights": g[6:8]}
                for name, program, s, u, c, p in comb_rows:
                    is_file = program.startswith("/") or program.endswith(".comb") and "/" in program
                    f = program if is_file else "<scene>"
                    row = ("program " + name) if is_file else ("material " + name)
                    for key, val in (("stages", s), ("texture_units", u), ("constant_colors", c)):
                        rows[(f, row, key)] = (int(val), summary[key][1])
                    rows[(f, row, "passes")] = (int(p), None)
                    if not is_file:
                        rows[(f, row, "lights")] = tuple(summary["lights"])
                # the frame's worst, which the new report gives as the most of any row
                for key in ("stages", "texture_units", "constant_colors"):
                    rows[(comb_rows[0][1] if comb_rows and "/" in comb_rows[0][1] and comb_rows[0][1].endswith(".comb") else "<scene>", "(most)", key)] = (summary[key][0], None)
                continue
        if mode == "gx":
            if line.startswith("| limit ("):
                cells = [c.strip() for c in line.strip("|").split("|")]
                gx_limits = [int(c) for c in cells[3:]]
                continue
            m = re.match(r"\| (.+?) \| ([^|]*?) \| (\d+) \| (.*) \|$", line)
            if m and not line.startswith("| program"):
                nums = [int(c.strip()) for c in m.group(4).split("|")]
                rows[(file, m.group(1), "__counts")] = tuple(nums)
                continue
            m = re.match(r"passes per frame: (\d+)", line)
            if m:
                rows[(file, "(most)", "passes")] = (int(m.group(1)), None)
                for k, v in list(rows.items()):
                    if k[0] == file and k[2] == "__counts":
                        del rows[k]
                        for key, u, l in zip(GX_KEYS, v, gx_limits):
                            rows[(file, k[1], key)] = (u, l)
    return rows


RES = re.compile(r"^([A-Za-z][A-Za-z0-9 ]*?) (-?\d+)(?:/(\d+))?!?$")


def parse_new(out):
    rows = {}
    current = None
    for line in out.splitlines():
        m = re.match(r"^(\S+): (program|pass|material) (.*)$", line)
        if not m:
            # a detailed row's resource line: "FILE:   label used/limit, Mesa N: rule"
            d = re.match(r"^(\S+):   (.+?) (\d+)(?:/(\d+))?!?(?:, Mesa (\d+)(?: DIFFERS)?)?(?:: .*)?$", line)
            if d and current and d.group(1) == current[0]:
                key = LABELS[d.group(2)]
                rows[(current[0], current[1], key)] = (int(d.group(3)), int(d.group(4)) if d.group(4) else None)
                if d.group(5):
                    rows[(current[0], current[1], key + ".mesa")] = (int(d.group(5)), None)
            continue
        file, rest = m.group(1), m.group(3)
        # split "NAME: res, res, ...[; verdict]" from the right; a detailed row ends with ":" or
        # ": fits P"/": OVER P".
        body = re.sub(r"; (fits|OVER)( \S+)?$", "", rest)
        parts = body.split(": ")
        res = parts[-1]
        name = ": ".join(parts[:-1])
        toks = res.split(", ")
        if all(RES.match(t) for t in toks) and name:
            name = re.sub(r" \((combiners/|/)[^)]*\)$", "", name)
            for t in toks:
                r = RES.match(t)
                rows[(file, name, LABELS.get(r.group(1), r.group(1).lower().replace(" ", "_")))] = (
                    int(r.group(2)), int(r.group(3)) if r.group(3) else None)
            current = None
        else:
            name = re.sub(r"(: (fits|OVER) \S+)$", "", rest).rstrip(":")
            name = re.sub(r" \(/[^)]*\)$", "", name)
            current = (file, name)
    return rows


def normalise_new(rows, old_rows):
    """The new report's rows under the old report's names: a gx pass row is named by its
    function; the old 'most' figures are the most of any row."""
    out = {}
    for (f, row, key), v in rows.items():
        m = re.match(r"material .* pass \d+ \((.*)\)$", row)
        if m:
            row = m.group(1)
        # the text says a row's scope once when its name starts with it ("material skin: ...")
        for scope in ("material ", "program "):
            if (f, scope + row, key) in old_rows:
                row = scope + row
        out[(f, row, key)] = v
    for (f, row, key), v in list(old_rows.items()):
        if row == "(most)":
            cands = [u for (ff, rr, kk), (u, l) in rows.items() if kk == key and (ff == f or f == "<scene>")]
            out[(f, row, key)] = (max(cands), None) if cands else None
    return out


def main():
    before, after, cases = sys.argv[1:4]
    same = differ = only_before = only_after = 0
    for line in open(cases):
        args = line.split()
        if not args:
            continue
        rb, ob, eb = run(before, args)
        ra, oa, ea = run(after, args)
        old = parse_old(ob)
        new = parse_new(oa)
        # a combiners scene names no file in the old text: key it like the old one
        if "--path" in args and args[args.index("--path") + 1] == "combiners":
            new = {(("<scene>" if f.endswith(".json") else f), r, k): v for (f, r, k), v in new.items()}
        new = normalise_new(new, old)
        print("== budget %s: exit %d -> %d, %d figures before, %d after" % (" ".join(args), rb, ra, len(old), len(new)))
        if rb != ra:
            print("   EXIT DIFFERS")
        if rb == 2 or ra == 2:
            print("   before: %s   after: %s" % (eb.strip(), ea.strip()))
        for k in sorted(set(old) | set(new), key=str):
            if k in old and k in new:
                if old[k] == new[k]:
                    same += 1
                else:
                    differ += 1
                    print("   DIFFERS %s: before %s, after %s" % (k, old[k], new[k]))
            elif k in old:
                only_before += 1
                print("   only before %s: %s" % (k, old[k]))
            else:
                only_after += 1
                print("   only after %s: %s" % (k, new[k]))
    print("TOTAL: %d figures the same, %d differ, %d only before, %d only after" % (same, differ, only_before, only_after))


if __name__ == "__main__":
    main()
