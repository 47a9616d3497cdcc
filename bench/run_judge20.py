#!/usr/bin/python3
"""Fit every target of a bench/make_judge20_targets.py set (or a list of smooth shapes) and
measure the result as issue 38's judge does: `curvefold fit TARGET [--from SURFACE] ARGS`, the
design exported with `export --obj`, its distance to the target by bench/judge_distance.py
(40,000 area-uniform samples). One fit at a time (each fit uses both cores).

Usage: bench/run_judge20.py CURVEFOLD MANIFEST OUT.tsv [--only NAME,...] -- FIT-ARGS...
MANIFEST: tab-separated name, surface ('-' for no --from), parameters, folds, band; the target
is MANIFEST's folder/<name>.obj. OUT.tsv gets one line per target: name, band, target folds,
fitted folds, start Hausdorff% and Chamfer% (the fit's own `start:` line), judged Hausdorff%
and Chamfer%, user CPU seconds, wall seconds, the fit's `stopped:` line, and whether `check`
passes the design whole; OUT.tsv.NAME.txt keeps the fit's command and output.
"""
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    argv = sys.argv[1:]
    fit_args = argv[argv.index("--") + 1:] if "--" in argv else []
    argv = argv[: argv.index("--")] if "--" in argv else argv
    only = None
    if "--only" in argv:
        i = argv.index("--only")
        only = set(argv[i + 1].split(","))
        del argv[i: i + 2]
    cf, manifest, out = argv
    folder = os.path.dirname(os.path.abspath(manifest))
    rows = [line.rstrip("\n").split("\t") for line in open(manifest) if line.strip()]
    with open(out, "a") as log, tempfile.TemporaryDirectory() as work:
        for name, surface, _params, folds, band in rows:
            if only and name not in only:
                continue
            target = os.path.join(folder, name + ".obj")
            design = os.path.join(work, "fit.curvefold.json")
            obj = os.path.join(work, "fit.obj")
            cmd = [cf, "fit", target, "--seed", "1", "-o", design] + fit_args
            if surface != "-":
                cmd += ["--from", surface]
            t0 = time.time()
            before = os.times()
            r = subprocess.run(cmd, capture_output=True, text=True)
            after = os.times()
            wall = time.time() - t0
            user = after.children_user - before.children_user
            text = r.stdout + r.stderr
            with open(out + "." + name + ".txt", "w") as f:  # the fit's own lines, for traces
                f.write(" ".join(cmd) + "\n" + text)
            m = re.search(r"start: Hausdorff [^(]*\(([\d.]+)%\), Chamfer [^(]*\(([\d.]+)%\)", text)
            start = (m.group(1), m.group(2)) if m else ("?", "?")
            stop = re.search(r"stopped: (.*)", text)
            nf = re.search(r"wrote \S+ \((?:\d+ steps?, )?(\d+) folds?", text)
            if r.returncode != 0:
                log.write("\t".join([name, band, folds, "ERR", *start, "?", "?", "%.1f" % user,
                                     "%.1f" % wall, text.strip().splitlines()[-1]]) + "\n")
                log.flush()
                continue
            subprocess.run([cf, "export", design, "--obj", obj], check=True, capture_output=True)
            whole = subprocess.run([cf, "check", design], capture_output=True).returncode == 0
            d = subprocess.run([sys.executable, os.path.join(HERE, "judge_distance.py"), obj,
                                target], capture_output=True, text=True, check=True).stdout.split()
            line = [name, band, folds, nf.group(1) if nf else "?", *start, d[3], d[4],
                    "%.1f" % user, "%.1f" % wall, stop.group(1) if stop else "",
                    "check" if whole else "CHECK FAILED"]
            log.write("\t".join(line) + "\n")
            log.flush()
            print("\t".join(line), flush=True)


if __name__ == "__main__":
    sys.exit(main())
