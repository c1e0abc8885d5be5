#!/usr/bin/env python3
"""End to end against a reference (clingo): time AND peak memory, side by side, with ratios.

  scripts/bench_e2e.py --ours target/release/lucent [--ref clingo] --manifest M.tsv
                       [--rows REGEX] [--timeout 60] [--reps 1]

The same method as the shared tools/bench_compare.py (which it replaces for bench_e2e.sh
because that tool has no memory column): each manifest row names an encoding, an instance,
extra arguments and a mode (n1 = first answer set, n0 = all answer sets, opt = proven
optimum); both commands get clingo's command line with --outf=2; times are wall-clock times of
the whole process, the minimum over --reps runs, the two solvers alternating so machine noise
hits both. CPU times (user plus system seconds, GNU time's %U + %S) are printed beside them,
also the minimum over the runs: on a loaded shared machine they are the steadier measure. Peak memory is the process's maximum resident set size as GNU time reports it
(`/usr/bin/time -f %M`, Debian package `time`), the minimum over the runs.

A row agrees when both give the same result, the same model count (n0) and the same optimum
(opt). The last lines are the geometric means of ours/ref time, CPU time and peak memory over
the rows both finished and agree on, with the worst row of each.
Exit status: 0 when every finished row agrees, 1 otherwise.
"""
import argparse
import json
import math
import os
import re
import shlex
import signal
import subprocess
import sys
import tempfile
import threading
import time


def run(cmd, timeout):
    """(seconds, peak RSS in KiB, CPU seconds, stdout, stderr, exit code), or None on timeout.

    The peak RSS comes from GNU time (`/usr/bin/time -f %M`), not from this process's wait4:
    Linux carries the RSS high-water mark of the forking process across exec, so a child of
    Python would never report less than Python's own RSS.
    """
    with tempfile.NamedTemporaryFile(mode="r") as rss, tempfile.TemporaryFile() as out, \
            tempfile.TemporaryFile() as err:
        t0 = time.perf_counter()
        # Own process group, killed whole on timeout: killing GNU time alone left the measured
        # program running, loading the machine for every later row.
        p = subprocess.Popen([TIME, "-f", "%U %S %M", "-o", rss.name] + cmd, stdout=out, stderr=err,
                             start_new_session=True)
        # A blocking wait with a timer for the timeout: `Popen.wait(timeout=...)` polls with
        # sleeps of up to 50 ms, which quantized every wall time to about 50 ms (0.064, 0.115,
        # 0.165 s...) and made tiny rows read up to 2x either way.
        expired = []

        def kill():
            expired.append(True)
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except ProcessLookupError:  # it ended just now
                pass

        timer = threading.Timer(timeout, kill)
        timer.start()
        p.wait()
        secs = time.perf_counter() - t0
        timer.cancel()
        if expired:
            return None
        # The last line (GNU time writes "Command exited with non-zero status N" first when
        # the exit code is not 0): user seconds, system seconds, peak RSS.
        last = rss.read().strip().split("\n")[-1].split()
        kib = int(last[2]) if len(last) == 3 and last[2].isdigit() else None
        try:
            cpu = float(last[0]) + float(last[1])
        except (IndexError, ValueError):
            cpu = None
        out.seek(0)
        err.seek(0)
        return secs, kib, cpu, out.read().decode(errors="replace"), err.read().decode(errors="replace"), \
            p.returncode


def summary(stdout):
    """(result, model count, optimum) from clingo's --outf=2 JSON, or None."""
    try:
        js = json.loads(stdout)
    except ValueError:
        return None
    models = js.get("Models", {})
    cost = models.get("Costs")
    if cost is None:
        witnesses = [w for c in js.get("Call", []) for w in c.get("Witnesses", [])]
        if witnesses and "Costs" in witnesses[-1]:
            cost = witnesses[-1]["Costs"]
    return js.get("Result"), models.get("Number"), cost


TIME = "/usr/bin/time"

MODE_ARGS = {"n1": ["-n1"], "n0": ["-n0", "-q1"], "opt": ["-q1"]}


def geomean(xs):
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ours", required=True)
    ap.add_argument("--ref", default="clingo")
    ap.add_argument("--manifest", required=True)
    ap.add_argument("--rows", default="")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--reps", type=int, default=1)
    a = ap.parse_args()
    if not os.access(TIME, os.X_OK):
        sys.exit("bench_e2e.py needs GNU time for peak memory: apt-get install -y time")
    base = os.path.dirname(os.path.abspath(a.manifest))
    with open(a.manifest) as fh:
        header = fh.readline().rstrip("\n").split("\t")
        rows = [dict(zip(header, line.rstrip("\n").split("\t"))) for line in fh if line.strip()]
    pick = re.compile(a.rows) if a.rows else None
    time_ratios, cpu_ratios, mem_ratios, disagree, unfinished = [], [], [], 0, 0
    print("%-22s %-36s %9s %9s %7s %8s %8s %7s %8s %8s %7s  %s"
          % ("family", "instance", "ref_s", "ours_s", "t_ratio", "ref_cpu", "ours_cpu", "c_ratio",
             "ref_MB", "ours_MB", "m_ratio", "verdict"))
    for r in rows:
        name = r["family"] + "/" + os.path.basename(r["instance"])
        if pick and not pick.search(name):
            continue
        files = [os.path.join(base, r["encoding"]), os.path.join(base, r["instance"])]
        tail = shlex.split(r.get("args", "")) + MODE_ARGS[r["mode"]] + ["--outf=2"]
        secs = {"ref": None, "ours": None}
        rss = {"ref": None, "ours": None}
        cpu = {"ref": None, "ours": None}
        out = {}
        for rep in range(a.reps):
            for who in (["ref", "ours"] if rep % 2 == 0 else ["ours", "ref"]):
                cmd = shlex.split(a.ref if who == "ref" else a.ours) + files + tail
                res = run(cmd, a.timeout)
                if res is None:
                    continue
                t, kib, c, stdout, stderr, code = res
                out[who] = (stdout, stderr, code)
                secs[who] = t if secs[who] is None else min(secs[who], t)
                if c is not None:
                    cpu[who] = c if cpu[who] is None else min(cpu[who], c)
                if kib is not None:
                    rss[who] = kib if rss[who] is None else min(rss[who], kib)
        verdict = "ok"
        if secs["ref"] is None or secs["ours"] is None:
            verdict = "ref timeout" if secs["ref"] is None else "ours timeout"
            unfinished += 1
        else:
            s_ref, s_ours = summary(out["ref"][0]), summary(out["ours"][0])
            if s_ours is None:
                verdict = "ours: no JSON (exit %s) %s" % (out["ours"][2], out["ours"][1].strip()[:80])
                disagree += 1
            elif s_ref is not None:
                same = s_ref[0] == s_ours[0]
                if r["mode"] == "n0":
                    same = same and s_ref[1] == s_ours[1]
                if r["mode"] == "opt":
                    same = same and s_ref[2] == s_ours[2]
                if not same:
                    verdict = "DISAGREE ref=%s ours=%s" % (s_ref, s_ours)
                    disagree += 1
            if verdict == "ok":
                time_ratios.append((secs["ours"] / secs["ref"], name))
                if cpu["ref"] is not None and cpu["ours"] is not None:
                    # 10 ms is the resolution of GNU time's CPU seconds.
                    cpu_ratios.append((max(cpu["ours"], 0.01) / max(cpu["ref"], 0.01), name))
                if rss["ref"] and rss["ours"]:
                    mem_ratios.append((rss["ours"] / rss["ref"], name))
        f_s = lambda x: "%9.3f" % x if x is not None else "        -"
        f_mb = lambda x: "%8.1f" % (x / 1024) if x is not None else "       -"
        both = secs["ref"] is not None and secs["ours"] is not None
        t_ratio = "%7.2f" % (secs["ours"] / secs["ref"]) if both else "      -"
        mem = rss["ref"] is not None and rss["ours"] is not None
        m_ratio = "%7.2f" % (rss["ours"] / rss["ref"]) if both and mem else "      -"
        f_c = lambda x: "%8.2f" % x if x is not None else "       -"
        cboth = both and cpu["ref"] is not None and cpu["ours"] is not None
        c_ratio = "%7.2f" % (max(cpu["ours"], 0.01) / max(cpu["ref"], 0.01)) if cboth else "      -"
        print("%-22s %-36s %s %s %s %s %s %s %s %s %s  %s"
              % (r["family"], os.path.basename(r["instance"])[:36], f_s(secs["ref"]), f_s(secs["ours"]),
                 t_ratio, f_c(cpu["ref"]), f_c(cpu["ours"]), c_ratio, f_mb(rss["ref"]),
                 f_mb(rss["ours"]), m_ratio, verdict))
        sys.stdout.flush()
    for what, ratios in (("time", time_ratios), ("CPU time", cpu_ratios), ("peak memory", mem_ratios)):
        worst = max(ratios) if ratios else (float("nan"), "-")
        print("geomean ours/ref %s %.3f over %d rows; worst %.2f (%s)"
              % (what, geomean([x for x, _ in ratios]), len(ratios), worst[0], worst[1]))
    print("%d disagree; %d unfinished" % (disagree, unfinished))
    sys.exit(1 if disagree else 0)


if __name__ == "__main__":
    main()
