#!/usr/bin/python3
"""An independent reader of fragsim's VCD (IEEE 1364-2005, clause 18) that
checks it against the run's statistics file (tests/cli_signals.sh).

    vcd_check.py FILE.vcd STATS.json [FIRST LAST]

Reads the header's $var lines and every "#time" and value change by the
standard's grammar (it does not use fragsim's code), then checks:
times strictly increase; one frame_start pulse per frame of frames
FIRST..LAST (default all); query_end pulses = queries; for every unit, the
ones of UNIT_busy and UNIT_stalled summed over the cycles = UNIT_busy and
UNIT_stalled; occlusion_engines_busy and occu_control_busy =
occlusion_test_cycles and occlusion_write_cycles; the last ctr_reloads =
ctr_reloads; UNIT_fifo never above the frame's UNIT_fifo_hwm (the
statistic counts the arriving entry, so it may be one above).  Prints one
line per check; exit status 1 when one fails.
"""
import json
import sys


def read_vcd(path):
    """Returns (vars: id -> (name, width), changes: list of (time, id, bits))."""
    with open(path) as f:
        toks = f.read().split()
    i, ids, changes, t = 0, {}, [], None
    last_t = -1
    in_defs = True
    while i < len(toks):
        tok = toks[i]
        if in_defs:
            if tok == "$var":
                # $var type width id reference $end
                _, width, ident, name = toks[i + 1:i + 5]
                ids[ident] = (name, int(width))
                i = toks.index("$end", i) + 1
                continue
            if tok == "$enddefinitions":
                in_defs = False
                i = toks.index("$end", i) + 1
                continue
            if tok.startswith("$"):
                i = toks.index("$end", i) + 1
                continue
            raise ValueError("unexpected %r in the header" % tok)
        if tok in ("$dumpvars", "$end", "$dumpon", "$dumpoff", "$dumpall"):
            i += 1
            continue
        if tok.startswith("#"):
            t = int(tok[1:])
            if t <= last_t:
                raise ValueError("time %d after %d: not increasing" % (t, last_t))
            last_t = t
            i += 1
            continue
        if tok[0] in "bB":
            bits, ident = tok[1:], toks[i + 1]
            i += 2
        elif tok[0] in "01xXzZ":
            bits, ident = tok[0], tok[1:]
            i += 1
        else:
            raise ValueError("unexpected %r" % tok)
        if ident not in ids:
            raise ValueError("change of undeclared id %r" % ident)
        changes.append((t, ident, bits))
    return ids, changes, last_t


def integrate(ids, changes, end):
    """Per signal: sum over time of the count of ones, rising edges of bit 0,
    the largest value, the last value."""
    cur, since = {}, {}
    ones, rises, peak, last = {}, {}, {}, {}
    for t, ident, bits in changes:
        name = ids[ident][0]
        if name in cur:
            ones[name] += cur[name].count("1") * (t - since[name])
            if cur[name] in ("0",) and bits == "1":
                rises[name] += 1
        else:
            ones[name], rises[name], peak[name] = 0, 0, 0
            if bits == "1" and ids[ident][1] == 1:
                rises[name] += 1
        cur[name], since[name] = bits, t
        v = int(bits.replace("x", "0").replace("z", "0"), 2)
        peak[name] = max(peak[name], v)
        last[name] = v
    for name in cur:
        ones[name] += cur[name].count("1") * (end - since[name])
    return ones, rises, peak, last


def main():
    vcd, stats_path = sys.argv[1], sys.argv[2]
    ids, changes, end = read_vcd(vcd)
    stats = json.load(open(stats_path))["cycle"]
    frames = stats["frames"]
    if len(sys.argv) > 4:
        a, b = int(sys.argv[3]), int(sys.argv[4])
        frames = [f for f in frames if a <= f["frame"] <= b]
    tot = {k: sum(f[k] for f in frames) for k in frames[0] if k != "frame"} if frames else {}
    ones, rises, peak, last = integrate(ids, changes, end)
    names = {n for n, _ in ids.values()}
    bad = 0

    def check(what, got, want, ok=None):
        nonlocal bad
        good = got == want if ok is None else ok
        print("%-40s %s (vcd %s, statistics %s)" % (what, "ok" if good else "DIFFERS", got, want))
        bad += not good

    if "frame_start" in names:
        check("frame_start pulses = frames", rises.get("frame_start", 0), len(frames))
    if "query_end" in names:
        check("query_end pulses = queries", rises.get("query_end", 0), tot.get("queries", 0))
    if "draw_start" in names:
        got = rises.get("draw_start", 0)
        check("draw_start pulses <= draws", got, tot.get("draws", 0), 0 < got <= tot.get("draws", 0))
    for n in sorted(names):
        if n.endswith("_busy") or n.endswith("_stalled"):
            stat = {"occlusion_engines_busy": "occlusion_test_cycles",
                    "occu_control_busy": "occlusion_write_cycles"}.get(n, n)
            if stat in tot:
                check(n + " cycles", ones.get(n, 0), tot[stat])
        if n.endswith("_fifo"):
            hwm = max((f[n + "_hwm"] for f in frames), default=0)
            check(n + " peak <= fifo_hwm", peak.get(n, 0), hwm, peak.get(n, 0) <= hwm)
    if "ctr_reloads" in names:
        check("ctr_reloads last value", last.get("ctr_reloads", 0), tot.get("ctr_reloads", 0))
    print("%d changes, last time %d" % (len(changes), end))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
