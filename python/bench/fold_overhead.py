"""What a fold costs through Python against the same fold in C++ (issue 30, 4).

A cylinder of about 100k triangles is folded and the fold taken back, again and again: through
`Design.fold` from Python, and through the very same C++ call timed inside the module (no
binding). Prints both medians and the overhead.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/fold_overhead.py [--repeats 30]
"""

import argparse
import statistics
import time

import curvefold
from curvefold import _curvefold

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--repeats", type=int, default=30)
parser.add_argument("--resolution", type=int, default=260)
arguments = parser.parse_args()

design = curvefold.Design.new("cylinder", resolution=arguments.resolution)
grab, to = (0.045, 0.1, 0.0), (0.03, 0.07, 0.02)
triangles = design.triangles.shape[0]
design.fold(grab=grab, to=to)  # warm up both paths
design.undo()

python_seconds = []
for _ in range(arguments.repeats):
    start = time.perf_counter()
    design.fold(grab=grab, to=to)
    python_seconds.append(time.perf_counter() - start)
    design.undo()
cpp_seconds = _curvefold._time_folds_in_cpp(design, grab, to, arguments.repeats)

python_median = statistics.median(python_seconds)
cpp_median = statistics.median(cpp_seconds)
print(f"cylinder, {triangles} triangles, {arguments.repeats} folds each")
print(f"fold through Python: median {python_median * 1e3:.2f} ms")
print(f"fold in C++:         median {cpp_median * 1e3:.2f} ms")
print(f"overhead: {100 * (python_median / cpp_median - 1):+.1f}%")
